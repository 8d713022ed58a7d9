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

/** The closed cylinder against numbers worked out by hand (radius 1, from y = 0 to y = 2). */
class CylinderTest {

    static Cylinder cylinder(double bx, double by, double bz, double ax, double ay, double az, double r) {
        Cylinder c = new Cylinder();
        c.base = v(bx, by, bz);
        c.axis = v(ax, ay, az);
        c.radius = r;
        c.init();
        return c;
    }

    private final Cylinder c = cylinder(0, 0, 0, 0, 2, 0, 1);

    @Test
    void sideAndCapsFromOutside() {
        assertHit(c, ray(5, 1, 0, -1, 0, 0), 4, v(1, 1, 0), v(1, 0, 0), true);
        assertHit(c, ray(0.6, 1.5, 5, 0, 0, -2), 2.1, v(0.6, 1.5, 0.8), v(0.6, 0, 0.8), true);
        assertHit(c, ray(0.3, 5, -0.2, 0, -1, 0), 3, v(0.3, 2, -0.2), v(0, 1, 0), true);
        assertHit(c, ray(0.3, -4, -0.2, 0, 0.5, 0), 8, v(0.3, 0, -0.2), v(0, -1, 0), true);
    }

    @Test
    void fromInsideEveryPartIsHitFromBehind() {
        assertHit(c, ray(0, 1, 0, 0, -1, 0), 1, v(0, 0, 0), v(0, 1, 0), false);
        assertHit(c, ray(0, 1, 0, 0, 1, 0), 1, v(0, 2, 0), v(0, -1, 0), false);
        assertHit(c, ray(0, 1, 0, 0, 0, 1), 1, v(0, 1, 1), v(0, 0, -1), false);
    }

    /** Entering through the top cap, leaving through the side: each crossing once, in order. */
    @Test
    void crossingsInOrderCapThenSide() {
        Ray r = ray(0, 3, 0, 1, -1, 0);                    // top at t = 1 (x = 1 is the rim), side ...
        r = ray(-0.5, 3, 0, 1, -1, 0);                     // top at t = 1 (x = 0.5), side at x = 1: t = 1.5
        IntersectionRecord rec = assertHit(c, r, 1, v(0.5, 2, 0), v(0, 1, 0), true);
        rec = assertHit(c, after(r, rec.t), 1.5, v(1, 1.5, 0), v(-1, 0, 0), false);
        assertMiss(c, after(r, rec.t));
    }

    @Test
    void missesAboveBesideAndAlongTheAxisOutside() {
        assertMiss(c, ray(5, 2.5, 0, -1, 0, 0));
        assertMiss(c, ray(5, 1, 1.01, -1, 0, 0));
        assertMiss(c, ray(1.01, 5, 0, 0, -1, 0));
        assertMiss(c, ray(5, 1, 0, 1, 0, 0));              // behind
    }

    /** Tilted: axis (1, 1, 0), height sqrt(2); a ray along the axis from below meets the bottom cap at the base. */
    @Test
    void tiltedCylinderAlongItsAxis() {
        Cylinder t = cylinder(1, 2, 3, 1, 1, 0, 0.5);
        double s = Math.sqrt(0.5);
        assertHit(t, ray(-1, 0, 3, 1, 1, 0), 2, v(1, 2, 3), v(-s, -s, 0), true);
        assertHit(t, ray(1.5, 2.5, 9, 0, 0, -1), 5.5, v(1.5, 2.5, 3.5), v(0, 0, 1), true);
    }

    @Test
    void insideTestAndBounds() {
        assertTrue(c.isInside(0.5, 1.9, 0.5));
        assertFalse(c.isInside(0.8, 1, 0.8));
        Aabb b = c.bounds();
        assertEquals(-1, b.minX, 1e-9);
        assertEquals(2, b.maxY, 1e-9);
        assertEquals(1, b.maxZ, 1e-9);
    }

    @Test
    void degenerateCylinderIsRefused() {
        Cylinder d = new Cylinder();
        d.axis = v(0, 0, 0);
        assertEquals("cylinder axis must have a non-zero length, got (0.0, 0.0, 0.0)", initMessage(d));
        d = new Cylinder();
        d.radius = -1;
        assertEquals("cylinder radius must be a positive number, got -1.0", initMessage(d));
    }
}
