package ray.surface;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import ray.accel.Aabb;

/**
 * A torus's box is padded outward by more than rounding (a relative 1e-13 of its size and place), for a
 * fat tube, at the origin and far from it; and its inside test is strict on the tube's surface.
 */
class TorusEdgeTest {

    @Test
    void boxIsPaddedBeyondRounding() {
        for (Torus t : new Torus[] {TorusTest.torus(0, 0, 0, 0, 1, 0, 1, 0.9), TorusTest.torus(0, 0, 0, 0, 1, 0, 2, 0.5),
                TorusTest.torus(1e6, 0, 0, 0, 1, 0, 2, 0.5)}) {
            Aabb b = t.bounds();
            double cx = t.center.x, big = t.majorRadius, r = t.minorRadius;
            double pad = 1e-13 * (Math.abs(cx) + big + r);
            assertTrue(b.minX < cx - big - r - pad && b.maxX > cx + big + r + pad, "x of " + b + " for " + t);
            assertTrue(b.minY < -r - pad && b.maxY > r + pad, "y (the axis) of " + b + " for " + t);
            assertTrue(b.minZ < -big - r - pad && b.maxZ > big + r + pad, "z of " + b + " for " + t);
        }
    }

    @Test
    void insideIsStrictOnTheTube() {
        Torus t = TorusTest.torus(0, 0, 0, 0, 1, 0, 2, 0.5);
        assertTrue(t.isInside(2.25, 0, 0));
        assertFalse(t.isInside(2.5, 0, 0), "outer equator");
        assertFalse(t.isInside(1.5, 0, 0), "inner equator");
        assertFalse(t.isInside(0, 0.5, 2), "top of the tube");
        assertFalse(t.isInside(0, -0.5, -2), "bottom of the tube");
    }
}
