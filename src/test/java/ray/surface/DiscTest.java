package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static ray.surface.PrimitiveFixture.assertHit;
import static ray.surface.PrimitiveFixture.assertMiss;
import static ray.surface.PrimitiveFixture.initMessage;
import static ray.surface.PrimitiveFixture.ray;
import static ray.surface.PrimitiveFixture.v;

import org.junit.jupiter.api.Test;
import ray.accel.Aabb;

/** The two-sided disc against numbers worked out by hand. */
class DiscTest {

    static Disc disc(double cx, double cy, double cz, double nx, double ny, double nz, double r) {
        Disc d = new Disc();
        d.center = v(cx, cy, cz);
        d.normal = v(nx, ny, nz);
        d.radius = r;
        d.init();
        return d;
    }

    @Test
    void hitInsideTheRadiusFromEitherSide() {
        Disc d = disc(0, 0, 0, 0, 0, 1, 2);
        assertHit(d, ray(1.5, 0, 5, 0, 0, -1), 5, v(1.5, 0, 0), v(0, 0, 1), true);
        assertHit(d, ray(0, -1.9, -1, 0, 0, 4), 0.25, v(0, -1.9, 0), v(0, 0, -1), false);
    }

    @Test
    void missOutsideTheRadius() {
        Disc d = disc(0, 0, 0, 0, 0, 1, 2);
        assertMiss(d, ray(2.01, 0, 5, 0, 0, -1));
        assertMiss(d, ray(1.5, 1.5, 5, 0, 0, -1));         // |(1.5, 1.5)| = 2.12
        assertMiss(d, ray(0, 0, 5, 1, 0, 0));              // parallel
    }

    /** Tilted disc: along the in-plane direction (0, 1, -1)/sqrt(2), 0.99 r hits and 1.01 r misses. */
    @Test
    void tiltedDiscHitsInsideAndMissesOutsideItsRadius() {
        Disc d = disc(1, 2, 3, 0, 1, 1, 1);
        double s = Math.sqrt(0.5);
        assertHit(d, ray(1, 2 + 10, 3 + 10, 0, -1, -1), 10, v(1, 2, 3), v(0, s, s), true);
        assertHit(d, ray(1, 2 + 0.99 * s, 3 - 0.99 * s - 4, 0, 0, 1), 4, v(1, 2 + 0.99 * s, 3 - 0.99 * s),
                v(0, -s, -s), false);
        assertMiss(d, ray(1, 2 + 1.01 * s, 3 - 1.01 * s - 4, 0, 0, 1));
    }

    @Test
    void boundsAreTheDiscsExtent() {
        Aabb b = disc(1, 2, 3, 0, 0, 5, 2).bounds();
        assertEquals(-1, b.minX, 1e-9);
        assertEquals(3, b.maxX, 1e-9);
        assertEquals(0, b.minY, 1e-9);
        assertEquals(4, b.maxY, 1e-9);
        assertEquals(3, b.minZ, 1e-9);
        assertEquals(3, b.maxZ, 1e-9);
    }

    @Test
    void badRadiusOrNormalIsRefused() {
        Disc d = new Disc();
        d.radius = 0;
        assertEquals("disc radius must be a positive number, got 0.0", initMessage(d));
        d = new Disc();
        d.normal = v(0, 0, 0);
        assertEquals("disc normal must have a non-zero length, got (0.0, 0.0, 0.0)", initMessage(d));
    }
}
