package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A box is finite only when all six bounds are numbers and min <= max on every axis; include grows it per axis. */
class AabbTest {

    @Test
    void finiteOnlyWhenEveryBoundIsANumberAndOrdered() {
        assertTrue(new Aabb(0, 0, 0, 1, 1, 1).isFinite());
        assertTrue(new Aabb(1, 2, 3, 1, 2, 3).isFinite(), "a point is a box");
        assertFalse(new Aabb().isFinite(), "empty");
        assertFalse(Aabb.infinite().isFinite());
        double[] ok = {0, 0, 0, 1, 1, 1};
        for (int k = 0; k < 6; k++) {
            for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
                double[] b = ok.clone();
                b[k] = bad;
                assertFalse(new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]).isFinite(), "bound " + k + " = " + bad);
            }
        }
        for (int a = 0; a < 3; a++) {
            double[] b = ok.clone();
            b[a] = 2;   // min above max on axis a only
            assertFalse(new Aabb(b[0], b[1], b[2], b[3], b[4], b[5]).isFinite(), "min > max on axis " + a);
        }
    }

    @Test
    void includeGrowsEachAxisOnItsOwn() {
        Aabb b = new Aabb();
        b.include(1, 2, 3);
        assertBox(b, 1, 2, 3, 1, 2, 3);
        b.include(-1, 5, 3);
        assertBox(b, -1, 2, 3, 1, 5, 3);
        b.include(0, 0, -7);
        assertBox(b, -1, 0, -7, 1, 5, 3);
        b.include(4, 3, 9);
        assertBox(b, -1, 0, -7, 4, 5, 9);
        assertTrue(b.isFinite());
        assertEquals("Aabb[-1.0 0.0 -7.0 .. 4.0 5.0 9.0]", b.toString());
    }

    private static void assertBox(Aabb b, double x0, double y0, double z0, double x1, double y1, double z1) {
        assertEquals(x0, b.minX, 0);
        assertEquals(y0, b.minY, 0);
        assertEquals(z0, b.minZ, 0);
        assertEquals(x1, b.maxX, 0);
        assertEquals(y1, b.maxY, 0);
        assertEquals(z1, b.maxZ, 0);
    }
}
