package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;

/** Shared checks of the primitives' unit tests: a hit with hand-derived t, point, normal and side. */
final class PrimitiveFixture {

    static final double EPS = 1e-12;

    private PrimitiveFixture() {
    }

    static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    }

    static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    /**
     * The surface is hit at t with the given point, the given normal (already turned to face the ray) and
     * front-face flag; the record names the surface and carries a positive error bound.
     */
    static IntersectionRecord assertHit(Surface s, Ray ray, double t, Vector3d p, Vector3d n, boolean front) {
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray, rec, null), "expected a hit: " + s + ", " + ray);
        String what = s + ", " + ray + ": " + rec;
        assertEquals(t, rec.t, EPS * Math.max(1, Math.abs(t)), "t of " + what);
        SphereTest.assertVec(p.x, p.y, p.z, rec.location, "location of " + what);
        SphereTest.assertVec(n.x, n.y, n.z, rec.normal, "normal of " + what);
        assertEquals(front, rec.frontFace, "frontFace of " + what);
        assertSame(s, rec.surface);
        assertTrue(rec.error > 0 && rec.error < 1e-10, "error bound " + rec.error + " of " + what);
        assertTrue(rec.normal.dot(ray.direction) <= 0, "normal does not face the ray: " + what);
        return rec;
    }

    /** A miss leaves the record exactly as it was. */
    static void assertMiss(Surface s, Ray ray) {
        IntersectionRecord rec = SphereTest.sentinel();
        assertFalse(s.intersects(ray, rec, null), "expected a miss: " + s + ", " + ray + ": " + rec);
        SphereTest.assertSentinel(rec);
    }

    /** The next crossing after the one in {@code rec} along the same ray (t strictly greater). */
    static Ray after(Ray ray, double t) {
        Ray r = ray(ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z);
        r.tMin = Math.nextUp(t);
        return r;
    }

    static String initMessage(Surface s) {
        try {
            s.init();
        } catch (IllegalArgumentException e) {
            return e.getMessage();
        }
        throw new AssertionError("init() accepted " + s);
    }
}
