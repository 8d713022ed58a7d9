package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import ray.accel.Aabb;

/**
 * A CSG's box from its operands' boxes (boxes as operands, so every number is exact): a union holds both,
 * an intersection is the overlap, also when the operands only touch along one axis (a flat box, kept),
 * and a single point when they are apart; a difference is the left operand's. And a triangle refuses a
 * vertex that is not finite, whichever vertex it is.
 */
class CsgBoxTest {

    private static Box box(double x0, double y0, double z0, double x1, double y1, double z1) {
        Box b = new Box();
        b.minPoint = PrimitiveFixture.v(x0, y0, z0);
        b.maxPoint = PrimitiveFixture.v(x1, y1, z1);
        b.init();
        return b;
    }

    private static List<Double> of(Aabb b) {
        return List.of(b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ);
    }

    private static final Box A = box(0, 0, 0, 2, 3, 4);

    @Test
    void unionHoldsBothBoxes() {
        assertEquals(List.of(-1.0, 0.0, -2.0, 2.0, 5.0, 4.0), of(CSGTest.csg("union", A, box(-1, 1, -2, 1, 5, 3)).bounds()));
        assertEquals(List.of(0.0, -1.0, 0.0, 6.0, 3.0, 7.0), of(CSGTest.csg("union", A, box(1, -1, 1, 6, 2, 7)).bounds()));
    }

    @Test
    void intersectionIsTheOverlap() {
        assertEquals(List.of(0.0, 1.0, 0.0, 1.0, 3.0, 3.0), of(CSGTest.csg("intersection", A, box(-1, 1, -2, 1, 5, 3)).bounds()));
        assertEquals(List.of(0.0, 0.0, 0.0, 2.0, 3.0, 4.0), of(CSGTest.csg("difference", A, box(-1, 1, -2, 1, 5, 3)).bounds()));
    }

    @Test
    void operandsTouchingAlongOneAxisKeepTheFlatOverlap() {
        assertEquals(List.of(2.0, 1.0, 1.0, 2.0, 2.0, 3.0), of(CSGTest.csg("intersection", A, box(2, 1, 1, 5, 2, 3)).bounds()));
        assertEquals(List.of(1.0, 3.0, 1.0, 1.5, 3.0, 3.0), of(CSGTest.csg("intersection", A, box(1, 3, 1, 1.5, 6, 3)).bounds()));
        assertEquals(List.of(1.0, 1.0, 4.0, 1.5, 2.0, 4.0), of(CSGTest.csg("intersection", A, box(1, 1, 4, 1.5, 2, 6)).bounds()));
    }

    @Test
    void operandsApartGiveAPoint() {
        // the overlap's min corner, as a point box (an empty box would leave the CSG out of the BVH)
        assertEquals(List.of(3.0, 1.0, 1.0, 3.0, 1.0, 1.0), of(CSGTest.csg("intersection", A, box(3, 1, 1, 5, 2, 3)).bounds()));
        assertEquals(List.of(1.0, 4.0, 1.0, 1.0, 4.0, 1.0), of(CSGTest.csg("intersection", A, box(1, 4, 1, 2, 6, 3)).bounds()));
        assertEquals(List.of(1.0, 1.0, 5.0, 1.0, 1.0, 5.0), of(CSGTest.csg("intersection", A, box(1, 1, 5, 2, 2, 6)).bounds()));
    }

    @Test
    void triangleRefusesAnyNonFiniteVertex() {
        for (int k = 0; k < 3; k++) {
            Triangle t = TriangleTest.tri(0, 0, 0, 1, 0, 0, 0, 1, 0);
            (k == 0 ? t.v0 : k == 1 ? t.v1 : t.v2).y = Double.NaN;
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, t::init, "vertex " + k);
            assertTrue(e.getMessage().contains("finite"), e.getMessage());
        }
    }
}
