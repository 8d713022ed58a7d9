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
import ray.accel.Aabb;

/**
 * The closed cone against numbers worked out by hand: base radius 1 at y = 0, apex at y = 2, so the
 * side's radius at height y is 1 - y / 2 and its outward normal is (x, k rho, z) / (rho sqrt(1 + k^2)), k = 1/2.
 */
class ConeTest {

    static Cone cone(double bx, double by, double bz, double ax, double ay, double az, double r) {
        Cone c = new Cone();
        c.base = v(bx, by, bz);
        c.axis = v(ax, ay, az);
        c.radius = r;
        c.init();
        return c;
    }

    private final Cone c = cone(0, 0, 0, 0, 2, 0, 1);
    private static final double N = 1 / Math.sqrt(1.25);

    @Test
    void sideBaseAndApexFromOutside() {
        assertHit(c, ray(5, 1, 0, -1, 0, 0), 4.5, v(0.5, 1, 0), v(N, 0.5 * N, 0), true);
        assertHit(c, ray(0.4, 1, 5, 0, 0, -1), 4.7, v(0.4, 1, 0.3), v(0.8 * N, 0.5 * N, 0.6 * N), true);
        assertHit(c, ray(0.2, -3, 0.1, 0, 1, 0), 3, v(0.2, 0, 0.1), v(0, -1, 0), true);
        assertHit(c, ray(0, 5, 0, 0, -1, 0), 3, v(0, 2, 0), v(0, 1, 0), true);
    }

    @Test
    void fromInsideTheSideAndTheBaseAreHitFromBehind() {
        assertHit(c, ray(0, 0.5, 0, 1, 0, 0), 0.75, v(0.75, 0.5, 0), v(-N, -0.5 * N, 0), false);
        assertHit(c, ray(0, 0.5, 0, 0, -1, 0), 0.5, v(0, 0, 0), v(0, 1, 0), false);
    }

    /** A ray down a line parallel to a generator: enters the side once, leaves through the base. */
    @Test
    void rayParallelToAGeneratorEntersOnceAndLeavesThroughTheBase() {
        Ray r = ray(-0.5, 2, 0, 1, -2, 0);                 // x = -0.5 + t, y = 2 - 2t; side at rho = 1 - y/2 = t
        IntersectionRecord rec = assertHit(c, r, 0.25, v(-0.25, 1.5, 0), v(-N, 0.5 * N, 0), true);
        rec = assertHit(c, after(r, rec.t), 1, v(0.5, 0, 0), v(0, 1, 0), false);
        assertMiss(c, after(r, rec.t));
    }

    @Test
    void missesBesideAboveAndBehind() {
        assertMiss(c, ray(0.6, 1, 5, 0, 0, -1));           // radius at y = 1 is 0.5
        assertMiss(c, ray(5, 2.01, 0, -1, 0, 0));
        assertMiss(c, ray(5, 1, 0, 1, 0, 0));
        assertMiss(c, ray(0, -3, 1.01, 0, 1, 0));          // beside the base, parallel to the axis
    }

    @Test
    void insideTestAndBounds() {
        assertTrue(c.isInside(0.4, 1, 0));
        assertFalse(c.isInside(0.6, 1, 0));
        Aabb b = c.bounds();
        assertEquals(-1, b.minZ, 1e-9);
        assertEquals(2, b.maxY, 1e-9);
        assertEquals(0, b.minY, 1e-9);
    }

    @Test
    void degenerateConeIsRefused() {
        Cone d = new Cone();
        d.axis = v(0, 0, 0);
        assertEquals("cone axis must have a non-zero length, got (0.0, 0.0, 0.0)", initMessage(d));
        d = new Cone();
        d.radius = 0;
        assertEquals("cone radius must be a positive number, got 0.0", initMessage(d));
    }
}
