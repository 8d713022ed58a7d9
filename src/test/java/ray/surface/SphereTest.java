package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/** The ray/sphere test against numbers worked out by hand for a unit sphere at the origin. */
class SphereTest {

    private static final double EPS = 1e-12;
    private final Scene scene = new Scene();

    private static Sphere sphere(double cx, double cy, double cz, double r) {
        Sphere s = new Sphere();
        s.center = new Vector3d(cx, cy, cz);
        s.radius = r;
        s.init();
        return s;
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    }

    static void assertVec(double x, double y, double z, Vector3d v, String what) {
        assertEquals(x, v.x, EPS, what + ".x in " + v);
        assertEquals(y, v.y, EPS, what + ".y in " + v);
        assertEquals(z, v.z, EPS, what + ".z in " + v);
    }

    /** A record full of values no intersection would write, to see that a miss leaves it alone. */
    static IntersectionRecord sentinel() {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(7, 8, 9);
        rec.normal.set(0, 1, 0);
        rec.t = 123.5;
        rec.surface = null;
        rec.frontFace = false;
        rec.error = 0.25;
        return rec;
    }

    static void assertSentinel(IntersectionRecord rec) {
        assertVec(7, 8, 9, rec.location, "location");
        assertVec(0, 1, 0, rec.normal, "normal");
        assertEquals(123.5, rec.t);
        assertEquals(null, rec.surface);
        assertFalse(rec.frontFace);
        assertEquals(0.25, rec.error);
    }

    @Test
    void headOnRayHitsNearPoleWithOutwardNormal() {
        Sphere s = sphere(0, 0, 0, 1);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray(0, 0, 5, 0, 0, -1), rec, scene));
        assertEquals(4, rec.t, EPS);
        assertVec(0, 0, 1, rec.location, "location");
        assertVec(0, 0, 1, rec.normal, "normal");
        assertTrue(rec.frontFace);
        assertSame(s, rec.surface);
    }

    /** Off-centre: x = 0.6 meets the unit sphere at z = sqrt(1 - 0.36) = 0.8. */
    @Test
    void offCentreHitHasUnitOutwardNormal() {
        Sphere s = sphere(0, 0, 0, 1);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray(0.6, 0, 5, 0, 0, -1), rec, scene));
        assertEquals(4.2, rec.t, EPS);
        assertVec(0.6, 0, 0.8, rec.location, "location");
        assertVec(0.6, 0, 0.8, rec.normal, "normal");
        assertEquals(1, rec.normal.length(), EPS);
    }

    @Test
    void translatedSphereHitsAtItsOwnSurface() {
        Sphere s = sphere(1, 2, 3, 2);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray(1, 10, 3, 0, -1, 0), rec, scene));
        assertEquals(6, rec.t, EPS);
        assertVec(1, 4, 3, rec.location, "location");
        assertVec(0, 1, 0, rec.normal, "normal");
    }

    @Test
    void rayPassingBesideSphereMisses() {
        IntersectionRecord rec = sentinel();
        assertFalse(sphere(0, 0, 0, 1).intersects(ray(3, 0, 5, 0, 0, -1), rec, scene));
        assertSentinel(rec);
    }

    /** Tangent at x = 1 and just either side: a clean hit or a clean miss, never a NaN. */
    @Test
    void tangentRayGivesCleanHitOrCleanMiss() {
        Sphere s = sphere(0, 0, 0, 1);
        for (double x : new double[] {Math.nextDown(1.0), 1.0, Math.nextUp(1.0), 1 - 1e-9, 1 + 1e-9}) {
            IntersectionRecord rec = sentinel();
            if (s.intersects(ray(x, 0, 5, 0, 0, -1), rec, scene)) {
                assertTrue(Double.isFinite(rec.t), "t at x=" + x);
                assertEquals(5, rec.t, 1e-4, "t at x=" + x);
                assertEquals(1, rec.location.length(), 1e-12, "location on the sphere at x=" + x);
                assertEquals(1, rec.normal.length(), 1e-12, "unit normal at x=" + x);
                assertEquals(1, rec.normal.x, 1e-4, "normal at x=" + x);
            } else {
                assertTrue(x > 1, "a ray at x=" + x + " <= 1 must hit");
                assertSentinel(rec);
            }
        }
        // exactly tangent: the double root t = 5 at (1, 0, 0)
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray(1, 0, 5, 0, 0, -1), rec, scene));
        assertEquals(5, rec.t, EPS);
        assertVec(1, 0, 0, rec.location, "location");
        assertVec(1, 0, 0, rec.normal, "normal");
    }

    /** From inside, the far root is taken and the normal is turned to face the ray. */
    @Test
    void rayStartingInsideHitsFarSideWithNormalFacingRay() {
        Sphere s = sphere(0, 0, 0, 1);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray(0, 0, 0, 0, 0, -1), rec, scene));
        assertEquals(1, rec.t, EPS);
        assertVec(0, 0, -1, rec.location, "location");
        assertVec(0, 0, 1, rec.normal, "normal (outward is -z; turned toward the ray)");
        assertFalse(rec.frontFace);
        assertSame(s, rec.surface);
    }

    @Test
    void sphereBehindOriginIsMissed() {
        IntersectionRecord rec = sentinel();
        assertFalse(sphere(0, 0, 0, 1).intersects(ray(0, 0, 5, 0, 0, 1), rec, scene));
        assertSentinel(rec);
    }

    @Test
    void hitBeyondTMaxIsExcludedAndTMaxItselfIsIncluded() {
        Sphere s = sphere(0, 0, 0, 1);
        Ray r = ray(0, 0, 5, 0, 0, -1);
        r.tMax = 3.9;
        IntersectionRecord rec = sentinel();
        assertFalse(s.intersects(r, rec, scene));
        assertSentinel(rec);
        r.tMax = 4;   // [tMin, tMax] is closed
        assertTrue(s.intersects(r, rec, scene));
        assertEquals(4, rec.t, EPS);
    }

    /** The near root below tMin: the far root t = 6 is the hit, seen from inside the sphere. */
    @Test
    void nearRootBelowTMinGivesFarRoot() {
        Sphere s = sphere(0, 0, 0, 1);
        Ray r = ray(0, 0, 5, 0, 0, -1);
        r.tMin = 4.5;
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(r, rec, scene));
        assertEquals(6, rec.t, EPS);
        assertVec(0, 0, -1, rec.location, "location");
        assertVec(0, 0, 1, rec.normal, "normal");
        assertFalse(rec.frontFace);
    }

    @Test
    void bothRootsOutsideSpanMiss() {
        Sphere s = sphere(0, 0, 0, 1);
        Ray r = ray(0, 0, 5, 0, 0, -1);
        r.tMin = 6.5;
        IntersectionRecord rec = sentinel();
        assertFalse(s.intersects(r, rec, scene));
        r.tMin = 4.1;
        r.tMax = 5.9;   // the span lies between the roots
        assertFalse(s.intersects(r, rec, scene));
        assertSentinel(rec);
    }

    /** A direction of length 4: same point, t divided by 4. */
    @Test
    void unnormalisedDirectionScalesTOnly() {
        Sphere s = sphere(0, 0, 0, 1);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersects(ray(0.6, 0, 5, 0, 0, -4), rec, scene));
        assertEquals(4.2 / 4, rec.t, EPS);
        assertVec(0.6, 0, 0.8, rec.location, "location");
        assertVec(0.6, 0, 0.8, rec.normal, "normal");
    }

    @Test
    void zeroDirectionNeverHits() {
        IntersectionRecord rec = sentinel();
        assertFalse(sphere(0, 0, 0, 1).intersects(ray(0, 0, 0, 0, 0, 0), rec, scene));
        assertSentinel(rec);
    }

    @Test
    void boundsAreCentrePlusMinusRadius() {
        Aabb b = sphere(1, 2, 3, 0.5).bounds();
        assertEquals(0.5, b.minX);
        assertEquals(1.5, b.minY);
        assertEquals(2.5, b.minZ);
        assertEquals(1.5, b.maxX);
        assertEquals(2.5, b.maxY);
        assertEquals(3.5, b.maxZ);
    }

    @Test
    void nonPositiveOrNonFiniteRadiusIsRejected() {
        for (double r : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            Sphere s = new Sphere();
            s.radius = r;
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, s::init, "radius " + r);
            assertTrue(e.getMessage().contains("radius"), e.getMessage());
        }
    }
}
