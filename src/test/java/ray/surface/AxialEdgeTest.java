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
import ray.accel.Aabb;

/**
 * Cylinders and cones on their edge cases, each with exact numbers (axis along y, so the local frame is
 * exact): rays along a generator (a cylinder's side line, a cone's slope line) or parallel to one, rays
 * lying in a cap's plane, a tangent ray, the ray's span starting or ending exactly at a crossing, the rim
 * where side and cap meet; and the shared solid-of-revolution parts: the box of an oblique one, the
 * strict inside test at the caps and the side, validation of the base.
 */
class AxialEdgeTest {

    private static final double S = Math.sqrt(0.5);

    private static Ray span(Ray r, double tMin, double tMax) {
        r.tMin = tMin;
        r.tMax = tMax;
        return r;
    }

    // ---- cylinder: radius 1 around the y axis, 0 <= y <= 1 ----

    private final Cylinder cyl = CylinderTest.cylinder(0, 0, 0, 0, 1, 0, 1);

    @Test
    void cylinderRayAlongItsSideLineEntersThroughTheCapRim() {
        // x = 1, z = 0 is a line of the side itself: the closed solid holds it, the ray enters at the bottom rim
        assertHit(cyl, ray(1, -1, 0, 0, 1, 0), 1, v(1, 0, 0), v(0, -1, 0), true);
        // parallel to the axis, 1.5 from it in z (the frame's second local axis): outside, a miss
        assertMiss(cyl, ray(0, -1, 1.5, 0, 1, 0));
        assertMiss(cyl, ray(1.5, -1, 0, 0, 1, 0));
        assertHit(cyl, ray(0, -1, 0.9, 0, 1, 0), 1, v(0, 0, 0.9), v(0, -1, 0), true);
    }

    @Test
    void cylinderRayInACapPlaneMeetsTheSideAtTheRim() {
        assertHit(cyl, ray(-2, 0, 0, 1, 0, 0), 1, v(-1, 0, 0), v(-1, 0, 0), true);
        assertHit(cyl, ray(-2, 1, 0, 1, 0, 0), 1, v(-1, 1, 0), v(-1, 0, 0), true);
        assertMiss(cyl, ray(-2, 1.5, 0, 1, 0, 0));
        assertMiss(cyl, ray(-2, -0.5, 0, 1, 0, 0));
    }

    @Test
    void cylinderTangentRayTouchesTheSide() {
        assertHit(cyl, ray(-2, 0.5, 1, 1, 0, 0), 2, v(0, 0.5, 1), v(0, 0, 1), true);
        assertMiss(cyl, ray(-2, 0.5, Math.nextUp(1.0), 1, 0, 0));
    }

    @Test
    void cylinderRimCrossingCountsAsTheSide() {
        // through the top rim point (-1, 1, 0), side and top cap at the same t = 1: the side's normal
        assertHit(cyl, ray(-2, 2, 0, 1, -1, 0), 1, v(-1, 1, 0), v(-1, 0, 0), true);
        // leaving through the bottom rim (1, 0, 0) from inside: the side's normal, turned to the ray
        assertHit(cyl, ray(0, 1, 0, 1, -1, 0), 1, v(1, 0, 0), v(-1, 0, 0), false);
    }

    @Test
    void cylinderSpanEndsExactlyAtACrossing() {
        // enters the side at t = 2, leaves at t = 4
        assertHit(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), 2, 10), 2, v(-1, 0.5, 0), v(-1, 0, 0), true);
        assertHit(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), 0, 2), 2, v(-1, 0.5, 0), v(-1, 0, 0), true);
        assertHit(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), 4, 10), 4, v(1, 0.5, 0), v(-1, 0, 0), false);
        assertHit(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), 3, 4), 4, v(1, 0.5, 0), v(-1, 0, 0), false);
        assertMiss(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), 3, Math.nextDown(4.0)));
        assertMiss(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), Math.nextUp(4.0), 10));
        assertMiss(cyl, span(ray(-3, 0.5, 0, 1, 0, 0), 0, Math.nextDown(2.0)));
    }

    // ---- cone: base radius 1 at y = 0, apex (0, 1, 0), so k = 1 and the side is |(x, z)| = 1 - y ----

    private final Cone cone = ConeTest.cone(0, 0, 0, 0, 1, 0, 1);

    @Test
    void coneRayParallelToASlopeLineCrossesOnlyTheOtherSide() {
        // direction (1, -1, 0) is parallel to the slope line from the apex to (1, 0, 0): the quadratic is linear
        assertHit(cone, ray(-1, 1.5, 0, 1, -1, 0), 0.75, v(-0.25, 0.75, 0), v(-S, S, 0), true);
        assertHit(cone, span(ray(-1, 1.5, 0, 1, -1, 0), 1, 10), 1.5, v(0.5, 0, 0), v(0, 1, 0), false);
        // the reverse: in through the base, out through the side
        assertHit(cone, ray(1, -0.5, 0, -1, 1, 0), 0.5, v(0.5, 0, 0), v(0, -1, 0), true);
        assertHit(cone, span(ray(1, -0.5, 0, -1, 1, 0), 1, 10), 1.25, v(-0.25, 0.75, 0), v(S, -S, 0), false);
        // the same rays with a direction twice as long: the linear root divides by the direction's scale
        assertHit(cone, ray(-1, 1.5, 0, 2, -2, 0), 0.375, v(-0.25, 0.75, 0), v(-S, S, 0), true);
        assertHit(cone, span(ray(1, -0.5, 0, -2, 2, 0), 0.5, 10), 0.625, v(-0.25, 0.75, 0), v(S, -S, 0), false);
        // parallel to the slope line, above the apex: only the upper nappe, which is not part of the solid
        assertMiss(cone, ray(0, 1.5, 0, 1, -1, 0));
        assertMiss(cone, ray(0, 1.5, 0, -1, 1, 0));
    }

    @Test
    void coneRayInTheTangentPlaneAlongASlopeLineMisses() {
        // the plane x + y = 1 touches the cone along the slope line z = 0; 0.5 off that line in z: never inside
        assertMiss(cone, ray(0.5, 0.5, 0.5, 1, -1, 0));
        assertMiss(cone, ray(0.5, 0.5, -0.5, -1, 1, 0));
    }

    @Test
    void coneRayAlongItsOwnSlopeLineEntersAtTheRim() {
        // the line x + y = 1, z = 0 lies on the side: the closed solid holds it from the base rim to the apex
        assertHit(cone, ray(1.5, -0.5, 0, -1, 1, 0), 0.5, v(1, 0, 0), v(0, -1, 0), true);
    }

    @Test
    void coneRimCrossingCountsAsTheSide() {
        // entering from below at the base rim (1, 0, 0), side and base at t = 1: the side's normal
        assertHit(cone, ray(2, -0.5, 0, -1, 0.5, 0), 1, v(1, 0, 0), v(S, S, 0), true);
        // leaving through the base rim (1, 0, 0) from inside: the side's normal, turned to the ray
        assertHit(cone, ray(0, 0.5, 0, 1, -0.5, 0), 1, v(1, 0, 0), v(-S, -S, 0), false);
    }

    @Test
    void coneRayInTheBaseOrApexPlane() {
        assertHit(cone, ray(-2, 0, 0, 1, 0, 0), 1, v(-1, 0, 0), v(-S, S, 0), true);
        assertMiss(cone, ray(-2, -0.25, 0, 1, 0, 0));
        // through the apex, across the axis: touches the apex, whose normal is the axis
        assertHit(cone, ray(-2, 1, 0, 1, 0, 0), 2, v(0, 1, 0), v(0, 1, 0), true);
        assertMiss(cone, ray(-2, 1.25, 0, 1, 0, 0));
    }

    @Test
    void coneSpanEndsExactlyAtACrossing() {
        // at y = 0.5 the radius is 0.5: enters at t = 2.5, leaves at t = 3.5 (the expansion point is t = 3)
        double n = S;
        assertHit(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 0, 3), 2.5, v(-0.5, 0.5, 0), v(-n, n, 0), true);
        assertHit(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 2.5, 3), 2.5, v(-0.5, 0.5, 0), v(-n, n, 0), true);
        assertHit(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 0, 2.5), 2.5, v(-0.5, 0.5, 0), v(-n, n, 0), true);
        assertHit(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 3.5, 10), 3.5, v(0.5, 0.5, 0), v(-n, -n, 0), false);
        assertHit(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 3, 3.5), 3.5, v(0.5, 0.5, 0), v(-n, -n, 0), false);
        assertMiss(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 3, 3.4));
        assertMiss(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 0, 2.4));
        assertMiss(cone, span(ray(-3, 0.5, 0, 1, 0, 0), 3.6, 10));
        // the origin behind the expansion point: from (3, 0.5, 0) going -x, enters at t = 2.5 (x = 0.5)
        assertHit(cone, span(ray(3, 0.5, 0, -1, 0, 0), 0, 3), 2.5, v(0.5, 0.5, 0), v(n, n, 0), true);
    }

    @Test
    void coneAndCylinderRefuseAZeroOrInfiniteDirection() {
        for (AxialSurface s : new AxialSurface[] {cone, cyl}) {
            assertMiss(s, ray(0, 0.5, 0, 0, 0, 0));
            assertMiss(s, ray(-3, 0.5, 0, Double.POSITIVE_INFINITY, 0, 0));
        }
    }

    // ---- shared: box, inside test, validation ----

    @Test
    void boxOfAnObliqueSolidIsTheAnalyticOne() {
        // axis (2, 4, 4) (unit (1, 2, 2) / 3, length 6) from base (1, -2, 3), radius 0.5
        double[] a = {1 / 3.0, 2 / 3.0, 2 / 3.0}, base = {1, -2, 3}, top = {3, 2, 7};
        for (AxialSurface s : new AxialSurface[] {
                CylinderTest.cylinder(1, -2, 3, 2, 4, 4, 0.5), ConeTest.cone(1, -2, 3, 2, 4, 4, 0.5)}) {
            Aabb b = s.bounds();
            double[] min = {b.minX, b.minY, b.minZ}, max = {b.maxX, b.maxY, b.maxZ};
            double topRadius = s instanceof Cone ? 0 : 0.5;
            for (int i = 0; i < 3; i++) {
                double e = Math.sqrt(1 - a[i] * a[i]);
                double lo = Math.min(base[i] - 0.5 * e, top[i] - topRadius * e);
                double hi = Math.max(base[i] + 0.5 * e, top[i] + topRadius * e);
                assertEquals(lo, min[i], 1e-9, "min " + i + " of " + s + ": " + b);
                assertEquals(hi, max[i], 1e-9, "max " + i + " of " + s + ": " + b);
                assertTrue(min[i] < lo && max[i] > hi, "the box is padded outward: " + b);
            }
        }
        // padded by more than rounding (relative 1e-13 of the solid's size and place), also for a solid wider
        // than it is tall or far away
        for (AxialSurface s : new AxialSurface[] {CylinderTest.cylinder(0, 0, 0, 0, 1, 0, 10),
                CylinderTest.cylinder(1e6, 0, 0, 0, 1, 0, 2), ConeTest.cone(0, 0, 0, 0, 1, 0, 10)}) {
            Aabb b = s.bounds();
            double scale = Math.abs(s.base.x) + s.radius + 1;
            assertTrue(b.minY < -1e-13 * scale && b.maxY > 1 + 1e-13 * scale, "padded in y: " + b + " of " + s);
            assertTrue(b.minZ < -s.radius - 1e-13 * scale && b.maxZ > s.radius + 1e-13 * scale, "padded in z: " + b);
        }
    }

    @Test
    void insideIsStrictAtTheCapsAndTheSideOfAMovedSolid() {
        // base (1, 2, 3), axis (0, 2, 0), radius 1
        for (AxialSurface s : new AxialSurface[] {
                CylinderTest.cylinder(1, 2, 3, 0, 2, 0, 1), ConeTest.cone(1, 2, 3, 0, 2, 0, 1)}) {
            assertTrue(s.isInside(1, 2.5, 3), "on the axis: " + s);
            assertTrue(s.isInside(1.25, 2.5, 3.25), "near the axis: " + s);
            assertFalse(s.isInside(1, 2, 3), "the base centre is on the surface: " + s);
            assertFalse(s.isInside(1, 4, 3), "the top centre (apex) is on the surface: " + s);
            assertFalse(s.isInside(1, 1.5, 3), "below: " + s);
            assertFalse(s.isInside(1, 4.5, 3), "above: " + s);
        }
        Cylinder c = CylinderTest.cylinder(1, 2, 3, 0, 2, 0, 1);
        assertFalse(c.isInside(2, 3, 3), "on the side");
        assertFalse(c.isInside(1, 3, 4), "on the side");
        assertTrue(c.isInside(1.75, 3, 3), "within the side");
        Cone k = ConeTest.cone(1, 2, 3, 0, 2, 0, 1);
        assertFalse(k.isInside(1.5, 3, 3), "on the side at half height (radius 0.5)");
        assertTrue(k.isInside(1.25, 3, 3), "within the side at half height");
    }

    @Test
    void aBaseThatIsNotFiniteIsRefused() {
        Cylinder c = new Cylinder();
        c.base = v(Double.NaN, 0, 0);
        assertTrue(initMessage(c).contains("cylinder base"), initMessage(c));
        Cone k = new Cone();
        k.base = v(0, Double.POSITIVE_INFINITY, 0);
        assertTrue(initMessage(k).contains("cone base"), initMessage(k));
    }
}
