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

/** The torus (R = 1, r = 1/4 unless said) against numbers worked out by hand. */
class TorusTest {

    static Torus torus(double cx, double cy, double cz, double ax, double ay, double az, double big, double r) {
        Torus t = new Torus();
        t.center = v(cx, cy, cz);
        t.axis = v(ax, ay, az);
        t.majorRadius = big;
        t.minorRadius = r;
        t.init();
        return t;
    }

    /** Along a diameter in the torus's plane: four crossings at |x| = 1.25 and 0.75, alternating sides. */
    @Test
    void diameterCrossesFourTimesInOrderAlternatingSides() {
        Torus t = new Torus();
        Ray r = ray(5, 0, 0, -1, 0, 0);
        IntersectionRecord rec = assertHit(t, r, 3.75, v(1.25, 0, 0), v(1, 0, 0), true);
        rec = assertHit(t, after(r, rec.t), 4.25, v(0.75, 0, 0), v(1, 0, 0), false);
        rec = assertHit(t, after(r, rec.t), 5.75, v(-0.75, 0, 0), v(1, 0, 0), true);
        rec = assertHit(t, after(r, rec.t), 6.25, v(-1.25, 0, 0), v(1, 0, 0), false);
        assertMiss(t, after(r, rec.t));
    }

    @Test
    void topOfTheTubeAndTheHole() {
        Torus t = new Torus();
        assertHit(t, ray(0, 5, -1, 0, -2, 0), 2.375, v(0, 0.25, -1), v(0, 1, 0), true);
        assertMiss(t, ray(0, 5, 0, 0, -1, 0));             // down the hole
        assertMiss(t, ray(0, 0.26, -5, 0, 0, 1));          // just above the tube's top
        assertHit(t, ray(0, 0, 0, 0, 0, 1), 0.75, v(0, 0, 0.75), v(0, 0, -1), true);   // from the hole
    }

    @Test
    void fromInsideTheTubeTheWallIsHitFromBehind() {
        Torus t = new Torus();
        assertHit(t, ray(1, 0, 0, 0, 1, 0), 0.25, v(1, 0.25, 0), v(0, -1, 0), false);
        assertHit(t, ray(0, -0.1, 1, 0, 0, 1), 0.25 * Math.sqrt(1 - 0.16), v(0, -0.1, 1 + 0.25 * Math.sqrt(0.84)),
                v(0, 0.4, -Math.sqrt(0.84)), false);
    }

    /** Axis along z, far from the origin and unnormalised: the same crossings, moved. */
    @Test
    void tiltedAndMovedTorus() {
        Torus t = torus(100, -200, 300, 0, 0, 7, 2, 0.5);
        Ray r = ray(100, -200 + 10, 300, 0, -2, 0);
        IntersectionRecord rec = assertHit(t, r, 3.75, v(100, -200 + 2.5, 300), v(0, 1, 0), true);
        assertHit(t, after(r, rec.t), 4.25, v(100, -200 + 1.5, 300), v(0, 1, 0), false);
        assertHit(t, ray(100 + 2, -200, 310, 0, 0, -1), 9.5, v(102, -200, 300.5), v(0, 0, 1), true);
    }

    @Test
    void insideTestAndBounds() {
        Torus t = new Torus();
        assertTrue(t.isInside(0, 0.2, 1));
        assertFalse(t.isInside(0, 0, 0));
        Aabb b = t.bounds();
        assertEquals(-1.25, b.minX, 1e-9);
        assertEquals(0.25, b.maxY, 1e-9);
        assertEquals(1.25, b.maxZ, 1e-9);
    }

    @Test
    void degenerateTorusIsRefused() {
        Torus d = new Torus();
        d.minorRadius = 1;
        assertEquals("torus minorRadius must be below majorRadius (a ring torus; a horn or spindle torus intersects"
                + " itself), got minorRadius 1.0 and majorRadius 1.0", initMessage(d));
        d = new Torus();
        d.axis = v(0, 0, 0);
        assertEquals("torus axis must have a non-zero length, got (0.0, 0.0, 0.0)", initMessage(d));
        d = new Torus();
        d.majorRadius = -2;
        assertEquals("torus majorRadius must be a positive number, got -2.0", initMessage(d));
    }
}
