package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.accel.Aabb;

/**
 * A moved torus with an oblique axis (every component non-zero): its box is the analytic one, centre
 * +- (R sqrt(1 - a_i^2) + r) per world axis (the ring's extent plus the tube), within the tiny pad, and
 * contains every point of the surface; the inside test follows the moved centre; fields are validated.
 */
class TorusBoxTest {

    private static Torus oblique() {
        return TorusTest.torus(3, -2, 5, 1, 2, 2, 2, 0.5);   // axis (1, 2, 2) / 3
    }

    @Test
    void boxIsTheAnalyticOneAndHoldsTheSurface() {
        Torus t = oblique();
        Aabb b = t.bounds();
        double[] a = {1 / 3.0, 2 / 3.0, 2 / 3.0}, c = {3, -2, 5};
        double[] min = {b.minX, b.minY, b.minZ}, max = {b.maxX, b.maxY, b.maxZ};
        for (int i = 0; i < 3; i++) {
            double e = 2 * Math.sqrt(1 - a[i] * a[i]) + 0.5;
            assertEquals(c[i] - e, min[i], 1e-9, "min " + i + " of " + b);
            assertEquals(c[i] + e, max[i], 1e-9, "max " + i + " of " + b);
        }
        // points of the surface: (R + r cos p) (cos q u + sin q v) + r sin p a around the centre
        Vector3d ax = new Vector3d(1, 2, 2), u = new Vector3d(2, -1, 0), v = new Vector3d();
        ax.normalize();
        u.normalize();
        v.cross(ax, u);
        for (int i = 0; i < 64; i++) {
            for (int j = 0; j < 16; j++) {
                double q = 2 * Math.PI * i / 64, p = 2 * Math.PI * j / 16, ring = 2 + 0.5 * Math.cos(p);
                double x = 3 + ring * (Math.cos(q) * u.x + Math.sin(q) * v.x) + 0.5 * Math.sin(p) * ax.x;
                double y = -2 + ring * (Math.cos(q) * u.y + Math.sin(q) * v.y) + 0.5 * Math.sin(p) * ax.y;
                double z = 5 + ring * (Math.cos(q) * u.z + Math.sin(q) * v.z) + 0.5 * Math.sin(p) * ax.z;
                assertTrue(x >= b.minX && x <= b.maxX && y >= b.minY && y <= b.maxY && z >= b.minZ && z <= b.maxZ,
                        "surface point (" + x + ", " + y + ", " + z + ") outside " + b);
            }
        }
    }

    @Test
    void insideFollowsTheMovedCentre() {
        Torus t = oblique();
        Vector3d u = new Vector3d(2, -1, 0);
        u.normalize();
        assertTrue(t.isInside(3 + 2 * u.x, -2 + 2 * u.y, 5 + 2 * u.z), "the tube's core");
        assertTrue(t.isInside(3 - 2.4 * u.x, -2 - 2.4 * u.y, 5 - 2.4 * u.z), "0.4 from the core");
        assertFalse(t.isInside(3 + 2.6 * u.x, -2 + 2.6 * u.y, 5 + 2.6 * u.z), "0.6 from the core: outside");
        assertFalse(t.isInside(3, -2, 5), "the hole");
        assertFalse(t.isInside(3 + 2 * u.x + 1, -2 + 2 * u.y, 5 + 2 * u.z + 1), "beside the tube");
    }

    @Test
    void centreAndMinorRadiusAreValidated() {
        for (double bad : new double[] {0, -0.25, Double.NaN}) {
            Torus t = new Torus();
            t.minorRadius = bad;
            assertThrows(IllegalArgumentException.class, t::init, "minorRadius " + bad);
        }
        Torus t = new Torus();
        t.center = new Vector3d(Double.NaN, 0, 0);
        assertThrows(IllegalArgumentException.class, t::init, "a NaN centre");
        t.center = new Vector3d(0, Double.POSITIVE_INFINITY, 0);
        assertThrows(IllegalArgumentException.class, t::init, "an infinite centre");
    }
}
