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
import ray.IntersectionRecord;
import ray.Ray;
import ray.accel.Aabb;

/**
 * Boxes, discs and planes on their edge cases, with exact numbers: rays lying in a face's plane, through
 * an edge or the rim, spans that start or end exactly at a crossing, a ray parallel to a plane whose span
 * starts at 0, the strict inside test on every face, the box of an oblique disc, the error bound by
 * formula, and validation of each point field.
 */
class FlatEdgeTest {

    private static Ray span(Ray r, double tMin, double tMax) {
        r.tMin = tMin;
        r.tMax = tMax;
        return r;
    }

    private static Box box() {
        Box b = new Box();
        b.minPoint = v(-1, -2, -3);
        b.maxPoint = v(1, 2, 3);
        b.init();
        return b;
    }

    @Test
    void boxRayInAFacePlaneHitsThatFacesEdge() {
        Box b = box();
        assertHit(b, ray(-1, -5, 0, 0, 1, 0), 3, v(-1, -2, 0), v(0, -1, 0), true);
        assertHit(b, ray(1, -5, 0, 0, 1, 0), 3, v(1, -2, 0), v(0, -1, 0), true);
        assertHit(b, ray(0, -5, 3, 0, 1, 0), 3, v(0, -2, 3), v(0, -1, 0), true);
        assertMiss(b, ray(Math.nextUp(1.0), -5, 0, 0, 1, 0));
        assertMiss(b, ray(0, -5, Math.nextDown(-3.0), 0, 1, 0));
    }

    @Test
    void boxEdgeCrossingCountsAsTheLowerAxissFace() {
        // entering through the edge x = -1, y = -2 at t = 1: the x face (the first axis decides a tie)
        assertHit(box(), ray(-2, -3, 0, 1, 1, 0), 1, v(-1, -2, 0), v(-1, 0, 0), true);
        // leaving through the edge x = 1, y = 2 at t = 1: the x face, turned to the ray
        assertHit(box(), ray(0, 0, 0, 1, 2, 0), 1, v(1, 2, 0), v(-1, 0, 0), false);
    }

    @Test
    void boxRayTouchingOnlyAnEdgeHitsIt() {
        // (-2, -1, 0) + t (1, -1, 0) touches the edge x = -1, y = -2 at t = 1 and nothing else: the box is closed
        assertHit(box(), ray(-2, -1, 0, 1, -1, 0), 1, v(-1, -2, 0), v(-1, 0, 0), true);
        assertMiss(box(), ray(-2, Math.nextDown(-1.0), 0, 1, -1, 0));
    }

    @Test
    void boxSpanEndsExactlyAtACrossing() {
        Box b = box();
        // along x through the middle: enters the x = -1 face at t = 4, leaves the x = 1 face at t = 6
        assertHit(b, ray(-5, 0, 0, 1, 0, 0), 4, v(-1, 0, 0), v(-1, 0, 0), true);
        assertHit(b, span(ray(-5, 0, 0, 1, 0, 0), 4, 10), 4, v(-1, 0, 0), v(-1, 0, 0), true);
        assertHit(b, span(ray(-5, 0, 0, 1, 0, 0), 0, 4), 4, v(-1, 0, 0), v(-1, 0, 0), true);
        assertHit(b, span(ray(-5, 0, 0, 1, 0, 0), 6, 10), 6, v(1, 0, 0), v(-1, 0, 0), false);
        assertHit(b, span(ray(-5, 0, 0, 1, 0, 0), 5, 6), 6, v(1, 0, 0), v(-1, 0, 0), false);
        assertMiss(b, span(ray(-5, 0, 0, 1, 0, 0), 5, Math.nextDown(6.0)));
        assertMiss(b, span(ray(-5, 0, 0, 1, 0, 0), 0, Math.nextDown(4.0)));
        assertMiss(b, span(ray(-5, 0, 0, 1, 0, 0), Math.nextUp(6.0), 10));
    }

    @Test
    void boxInsideIsStrictOnEveryFace() {
        Box b = box();
        assertTrue(b.isInside(0.9, 1.9, 2.9));
        assertTrue(b.isInside(-0.9, -1.9, -2.9));
        double[][] onFaces = {{-1, 0, 0}, {1, 0, 0}, {0, -2, 0}, {0, 2, 0}, {0, 0, -3}, {0, 0, 3}};
        for (double[] p : onFaces) {
            assertFalse(b.isInside(p[0], p[1], p[2]), "on a face: " + java.util.Arrays.toString(p));
        }
    }

    @Test
    void boxRefusesNonFiniteOrFlatCorners() {
        Box b = new Box();
        b.minPoint = v(Double.NEGATIVE_INFINITY, 0, 0);   // below maxPoint, so only the finiteness check refuses it
        assertTrue(initMessage(b).contains("box minPoint") && !initMessage(b).contains("below"), initMessage(b));
        b = new Box();
        b.maxPoint = v(1, Double.POSITIVE_INFINITY, 1);
        assertTrue(initMessage(b).contains("box maxPoint"), initMessage(b));
        for (int axis = 0; axis < 3; axis++) {
            b = new Box();
            b.minPoint = v(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
            b.maxPoint = v(1, 1, 1);
            assertTrue(initMessage(b).contains("below maxPoint"), "flat in axis " + axis + ": " + initMessage(b));
        }
    }

    // ---- disc: radius 1 around the origin in the plane y = 0 unless said ----

    @Test
    void discRimBelongsToTheDisc() {
        Disc d = DiscTest.disc(0, 0, 0, 0, 1, 0, 1);
        assertHit(d, ray(1, 1, 0, 0, -1, 0), 1, v(1, 0, 0), v(0, 1, 0), true);
        assertHit(d, ray(0, 1, -1, 0, -1, 0), 1, v(0, 0, -1), v(0, 1, 0), true);
        assertMiss(d, ray(Math.nextUp(1.0), 1, 0, 0, -1, 0));
    }

    @Test
    void discSpanEndsExactlyAtTheCrossing() {
        Disc d = DiscTest.disc(0, 0, 0, 0, 1, 0, 1);
        assertHit(d, span(ray(0.5, 2, 0, 0, -1, 0), 2, 10), 2, v(0.5, 0, 0), v(0, 1, 0), true);
        assertHit(d, span(ray(0.5, 2, 0, 0, -1, 0), 0, 2), 2, v(0.5, 0, 0), v(0, 1, 0), true);
        assertMiss(d, span(ray(0.5, 2, 0, 0, -1, 0), Math.nextUp(2.0), 10));
        assertMiss(d, span(ray(0.5, 2, 0, 0, -1, 0), 0, Math.nextDown(2.0)));
    }

    @Test
    void boxOfAnObliqueDiscIsTheAnalyticOne() {
        // normal (1, 2, 2) / 3 at (1, -2, 3), radius 2: the rim's extent along axis i is 2 sqrt(1 - n_i^2)
        Aabb b = DiscTest.disc(1, -2, 3, 1, 2, 2, 2).bounds();
        double[] n = {1 / 3.0, 2 / 3.0, 2 / 3.0}, c = {1, -2, 3};
        double[] min = {b.minX, b.minY, b.minZ}, max = {b.maxX, b.maxY, b.maxZ};
        for (int i = 0; i < 3; i++) {
            double e = 2 * Math.sqrt(1 - n[i] * n[i]);
            assertEquals(c[i] - e, min[i], 1e-9, "min " + i + " of " + b);
            assertEquals(c[i] + e, max[i], 1e-9, "max " + i + " of " + b);
            assertTrue(min[i] < c[i] - e && max[i] > c[i] + e, "padded outward: " + b);
        }
        // padded by more than rounding (relative 1e-13 of the disc's size and place), also when the radius
        // is larger than the distance from the origin, and far from the origin
        for (Disc d : new Disc[] {DiscTest.disc(0, 0, 0, 0, 1, 0, 5), DiscTest.disc(1e6, 0, 0, 0, 1, 0, 2)}) {
            Aabb a = d.bounds();
            double scale = Math.abs(d.center.x) + d.radius;
            assertTrue(a.minY < -1e-13 * scale && a.maxY > 1e-13 * scale, "padded in y: " + a + " of " + d);
            assertTrue(a.minZ < -d.radius - 1e-13 * scale && a.maxZ > d.radius + 1e-13 * scale, "padded in z: " + a);
        }
    }

    @Test
    void discAndPlaneRefuseANonFinitePoint() {
        Disc d = new Disc();
        d.center = v(0, Double.NaN, 0);
        assertTrue(initMessage(d).contains("disc center"), initMessage(d));
        Plane p = new Plane();
        p.point = v(0, 0, Double.NEGATIVE_INFINITY);
        assertTrue(initMessage(p).contains("plane point"), initMessage(p));
    }

    // ---- plane: y = 5, normal given at length 2 ----

    private static Plane plane() {
        Plane p = new Plane();
        p.point = v(0, 5, 0);
        p.normal = v(0, 2, 0);
        p.init();
        return p;
    }

    @Test
    void planeSpanEndsExactlyAtTheCrossing() {
        assertHit(plane(), span(ray(3, 7, 4, 0, -1, 0), 2, 10), 2, v(3, 5, 4), v(0, 1, 0), true);
        assertHit(plane(), span(ray(3, 7, 4, 0, -1, 0), 0, 2), 2, v(3, 5, 4), v(0, 1, 0), true);
        assertMiss(plane(), span(ray(3, 7, 4, 0, -1, 0), Math.nextUp(2.0), 10));
    }

    @Test
    void aRayParallelToThePlaneMissesEvenFromZero() {
        // NaN for "parallel", not a t: a span from 0 must not take a parallel ray as a hit at its origin
        assertMiss(plane(), span(ray(0, 7, 0, 1, 0, 0), 0, 10));
        assertMiss(plane(), span(ray(0, 5, 0, 1, 0, 0), 0, 10));
        assertMiss(DiscTest.disc(0, 0, 0, 0, 1, 0, 1), span(ray(0, 1, 0, 1, 0, 0), 0, 10));
    }

    @Test
    void planeErrorBoundIsItsFormula() {
        // ERROR * (largest coordinate of the hit point + largest coordinate of the plane's point)
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(plane().intersects(ray(3, 7, 4, 0, -1, 0), rec, null));
        assertEquals(Plane.ERROR * (5 + 5), rec.error, 1e-30, "error of " + rec);
        Plane far = new Plane();
        far.point = v(-40, 0, 0);
        far.normal = v(1, 0, 0);
        far.init();
        assertTrue(far.intersects(ray(0, 7, -9, -1, 0, 0), rec, null));
        assertEquals(Plane.ERROR * (40 + 40), rec.error, 1e-30, "error of " + rec);
    }
}
