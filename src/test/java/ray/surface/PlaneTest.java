package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.surface.PrimitiveFixture.assertHit;
import static ray.surface.PrimitiveFixture.assertMiss;
import static ray.surface.PrimitiveFixture.initMessage;
import static ray.surface.PrimitiveFixture.ray;
import static ray.surface.PrimitiveFixture.v;

import org.junit.jupiter.api.Test;
import ray.Ray;

/** The infinite two-sided plane against numbers worked out by hand. */
class PlaneTest {

    private static Plane plane(double px, double py, double pz, double nx, double ny, double nz) {
        Plane p = new Plane();
        p.point = v(px, py, pz);
        p.normal = v(nx, ny, nz);
        p.init();
        return p;
    }

    @Test
    void defaultPlaneIsTheFloorHitFromAbove() {
        Plane p = new Plane();
        assertHit(p, ray(0.5, 5, -2, 0, -1, 0), 5, v(0.5, 0, -2), v(0, 1, 0), true);
    }

    @Test
    void seenFromBelowTheNormalFacesTheRayAndFrontFaceIsFalse() {
        assertHit(plane(0, 0, 0, 0, 1, 0), ray(3, -2, 1, 0, 2, 0), 1, v(3, 0, 1), v(0, -1, 0), false);
    }

    /** Unnormalised normal (0, 0, 3) through z = 2; a direction of length 0.5: t = 2 / 0.5 = 4. */
    @Test
    void unnormalisedNormalAndDirection() {
        assertHit(plane(7, -1, 2, 0, 0, 3), ray(1, 1, 0, 0, 0, 0.5), 4, v(1, 1, 2), v(0, 0, -1), false);
    }

    /** Oblique: the plane x + y = 2 from the origin along (1, 0, 0) is met at x = 2. */
    @Test
    void obliquePlaneAndRay() {
        double s = Math.sqrt(0.5);
        assertHit(plane(1, 1, 0, 1, 1, 0), ray(0, 0, 0, 1, 0, 0), 2, v(2, 0, 0), v(-s, -s, 0), false);
    }

    @Test
    void parallelRayBehindOriginAndOutOfRangeMiss() {
        Plane p = plane(0, 0, 0, 0, 1, 0);
        assertMiss(p, ray(0, 1, 0, 1, 0, 0));
        assertMiss(p, ray(0, 0, 0, 1, 0, 0));              // in the plane
        assertMiss(p, ray(0, 1, 0, 0, 1, 0));              // behind
        Ray r = ray(0, 1, 0, 0, -1, 0);
        r.tMax = 0.99;
        assertMiss(p, r);
        r.tMax = 1;
        assertHit(p, r, 1, v(0, 0, 0), v(0, 1, 0), true);
        r.tMin = 1.01;
        r.tMax = 5;
        assertMiss(p, r);
    }

    @Test
    void unboundedSoTheBvhTestsItAgainstEveryRay() {
        assertFalse(plane(0, 0, 0, 0, 1, 0).bounds().isFinite());
    }

    @Test
    void zeroNormalIsRefused() {
        Plane p = new Plane();
        p.normal = v(0, 0, 0);
        assertEquals("plane normal must have a non-zero length, got (0.0, 0.0, 0.0)", initMessage(p));
    }

    /** A hit point far along a grazing ray is put back on the plane: its height is exactly 0 here. */
    @Test
    void hitPointIsProjectedOntoThePlane() {
        Plane p = plane(0, 0, 0, 0, 1, 0);
        ray.IntersectionRecord rec = new ray.IntersectionRecord();
        assertTrue(p.intersects(ray(0.1, 1e-3, 0.3, 1, -1e-9, 0.7), rec, null));
        assertEquals(0, rec.location.y);
    }
}
