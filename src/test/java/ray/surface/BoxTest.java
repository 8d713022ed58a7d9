package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.surface.PrimitiveFixture.after;
import static ray.surface.PrimitiveFixture.assertHit;
import static ray.surface.PrimitiveFixture.assertMiss;
import static ray.surface.PrimitiveFixture.initMessage;
import static ray.surface.PrimitiveFixture.ray;
import static ray.surface.PrimitiveFixture.v;

import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;

/** The axis-aligned box against numbers worked out by hand. */
class BoxTest {

    private static Box box(double x0, double y0, double z0, double x1, double y1, double z1) {
        Box b = new Box();
        b.minPoint = v(x0, y0, z0);
        b.maxPoint = v(x1, y1, z1);
        b.init();
        return b;
    }

    @Test
    void axisAlignedRaysHitEachFaceFromOutside() {
        Box b = box(-1, -2, -3, 1, 2, 3);
        assertHit(b, ray(0.5, 0.5, 10, 0, 0, -1), 7, v(0.5, 0.5, 3), v(0, 0, 1), true);
        assertHit(b, ray(0.5, 0.5, -10, 0, 0, 2), 3.5, v(0.5, 0.5, -3), v(0, 0, -1), true);
        assertHit(b, ray(5, 1, 1, -1, 0, 0), 4, v(1, 1, 1), v(1, 0, 0), true);
        assertHit(b, ray(-5, 1, 1, 0.5, 0, 0), 8, v(-1, 1, 1), v(-1, 0, 0), true);
        assertHit(b, ray(0, 7, 0, 0, -1, 0), 5, v(0, 2, 0), v(0, 1, 0), true);
        assertHit(b, ray(0, -7, 0, 0, 1, 0), 5, v(0, -2, 0), v(0, -1, 0), true);
    }

    /** From inside, the exit: normal turned to face the ray, frontFace false. */
    @Test
    void rayFromInsideHitsTheFarFaceFromBehind() {
        Box b = new Box();
        b.init();
        assertHit(b, ray(0, 0, 0, 1, 0, 0), 1, v(1, 0, 0), v(-1, 0, 0), false);
        assertHit(b, ray(0.5, 0, 0, -3, 0, 0), 0.5, v(-1, 0, 0), v(1, 0, 0), false);
    }

    /** The diagonal from the corner region: enters through x = -1 at t = 1 (y, z slabs entered earlier). */
    @Test
    void obliqueRayEntersThroughTheLastSlabAndLeavesThroughTheFirst() {
        Box b = new Box();
        Ray r = ray(-2, -1.5, 0, 1, 1, 0);                 // x in box for t in [1, 3], y for t in [0.5, 2.5]
        IntersectionRecord rec = assertHit(b, r, 1, v(-1, -0.5, 0), v(-1, 0, 0), true);
        assertHit(b, after(r, rec.t), 2.5, v(0.5, 1, 0), v(0, -1, 0), false);
        assertMiss(b, after(r, 2.5));
    }

    @Test
    void missesBesideBehindAndOutOfRange() {
        Box b = new Box();
        assertMiss(b, ray(0, 1.5, 5, 0, 0, -1));           // parallel to the y slab, outside it
        assertMiss(b, ray(0, 0, 5, 0, 0, 1));              // behind
        assertMiss(b, ray(-3, 0, 0, 1, 1.01, 0));          // passes the corner (-1, 1.02)
        Ray r = ray(0, 0, 5, 0, 0, -1);
        r.tMax = 3.9;
        assertMiss(b, r);
        assertMiss(b, ray(0, 0, 5, 0, 0, 0));              // zero direction
    }

    @Test
    void hitPointLiesExactlyOnTheFace() {
        Box b = box(0.1, 0.2, 0.3, 0.7, 1.1, 1.3);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(b.intersects(ray(-3.3, 0.3, 0.4, 1.7, 0.13, 0.31), rec, null));
        assertEquals(0.1, rec.location.x);
    }

    @Test
    void insideTestAndBounds() {
        Box b = box(-1, -2, -3, 1, 2, 3);
        assertTrue(b.isInside(0.9, -1.9, 2.9));
        assertFalse(b.isInside(1, 0, 0));
        assertEquals(-3, b.bounds().minZ);
        assertEquals(2, b.bounds().maxY);
    }

    @Test
    void emptyOrInvertedBoxIsRefused() {
        Box b = new Box();
        b.maxPoint = v(1, -1, 1);
        assertEquals("box minPoint must be below maxPoint in every coordinate, got (-1.0, -1.0, -1.0) and (1.0, -1.0, 1.0)",
                initMessage(b));
    }
}
