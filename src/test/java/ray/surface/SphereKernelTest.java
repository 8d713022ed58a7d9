package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Sphere.hit's division-free early miss must never change an answer: on random rays, including rays
 * grazing the silhouette to within a few ulps, tiny far spheres and huge near ones, it must return
 * bit for bit what the exact quadratic alone returns.
 */
class SphereKernelTest {

    /** The exact test without the early miss (the kernel as it was before the shortcut). */
    static double reference(double cx, double cy, double cz, double r, double ox, double oy, double oz,
                            double dx, double dy, double dz, double tMin, double tMax) {
        double fx = ox - cx, fy = oy - cy, fz = oz - cz;
        double a = dx * dx + dy * dy + dz * dz;
        if (!(a > 0) || a == Double.POSITIVE_INFINITY) {
            return Double.NaN;
        }
        double b = fx * dx + fy * dy + fz * dz;
        double s = b / a;
        double lx = fx - s * dx, ly = fy - s * dy, lz = fz - s * dz;
        double dist = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double disc = (r - dist) * (r + dist);
        if (disc < 0) {
            return Double.NaN;
        }
        double c = (fx * fx + fy * fy + fz * fz) - r * r;
        double q = -(b + Math.copySign(Math.sqrt(a * disc), b));
        double t0, t1;
        if (q == 0) {
            t0 = t1 = 0;
        } else {
            t0 = c / q;
            t1 = q / a;
        }
        double tNear = Math.min(t0, t1), tFar = Math.max(t0, t1);
        if (tNear >= tMin && tNear <= tMax) {
            return tNear;
        }
        if (tFar >= tMin && tFar <= tMax) {
            return tFar;
        }
        return Double.NaN;
    }

    /**
     * The kernel before the exit for leaving rays: {@link #reference} behind the division-free clear miss
     * (which, with subnormal squares, can miss where the quadratic alone finds a root at -0.0).
     */
    static double beforeLeavingExit(double cx, double cy, double cz, double r, double ox, double oy, double oz,
                                    double dx, double dy, double dz, double tMin, double tMax) {
        double fx = ox - cx, fy = oy - cy, fz = oz - cz;
        double a = dx * dx + dy * dy + dz * dz;
        double qx = fy * dz - fz * dy, qy = fz * dx - fx * dz, qz = fx * dy - fy * dx;
        double ff = fx * fx + fy * fy + fz * fz;
        if (a > 0 && a != Double.POSITIVE_INFINITY && qx * qx + qy * qy + qz * qz > a * (r * r * (1 + 1e-6) + 1e-6 * ff)) {
            return Double.NaN;
        }
        return reference(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin, tMax);
    }

    @Test
    void earlyMissChangesNoAnswer() {
        Random rnd = new Random(3);
        int hits = 0, grazing = 0;
        for (int k = 0; k < 2_000_000; k++) {
            double scale = Math.pow(10, rnd.nextInt(13) - 6);          // 1e-6 .. 1e6
            double r = scale * (0.01 + rnd.nextDouble());
            double cx = scale * 100 * (rnd.nextDouble() - 0.5), cy = scale * 100 * (rnd.nextDouble() - 0.5), cz = scale * 100 * (rnd.nextDouble() - 0.5);
            double far = Math.pow(10, rnd.nextInt(7));
            double ox = cx + far * scale * 50 * (rnd.nextDouble() - 0.5), oy = cy + far * scale * 50 * (rnd.nextDouble() - 0.5),
                    oz = cz + far * scale * 50 * (rnd.nextDouble() - 0.5);
            // aim at a point at distance ~r from the centre: on, just inside or just outside the silhouette
            double px = rnd.nextGaussian(), py = rnd.nextGaussian(), pz = rnd.nextGaussian();
            double pl = Math.sqrt(px * px + py * py + pz * pz);
            double rr = r * (1 + (rnd.nextInt(3) == 0 ? rnd.nextGaussian() * 1e-12 : rnd.nextGaussian() * 0.3));
            double dx = cx + rr * px / pl - ox, dy = cy + rr * py / pl - oy, dz = cz + rr * pz / pl - oz;
            if (rnd.nextBoolean()) {
                double dl = Math.sqrt(dx * dx + dy * dy + dz * dz);
                dx /= dl;
                dy /= dl;
                dz /= dl;
            }
            double tMin = rnd.nextInt(4) == 0 ? 0 : 1e-9, tMax = rnd.nextInt(4) == 0 ? 1 : Double.POSITIVE_INFINITY;
            double expected = reference(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin, tMax);
            double got = Sphere.hit(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin, tMax);
            final int kk = k;
            assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(got), () -> "case " + kk);
            if (expected == expected) {
                hits++;
            }
            if (Math.abs(rr / r - 1) < 1e-9) {
                grazing++;
            }
        }
        assertTrue(hits > 100_000, "enough hits: " + hits);
        assertTrue(grazing > 100_000, "enough grazing rays: " + grazing);
    }

    /**
     * The exit for a ray leaving from outside and heading away (every shadow ray leaving a sphere toward
     * its light) must give the quadratic's answer bit for bit: rays from points on, just outside and just
     * inside the surface, in every direction, at scales from 1e-160 to 1e150 (where a root can round to
     * -0.0, which a spawned ray's tMin = 0 accepts), tangent rays, and tMin below 0 (where the negative
     * roots are hits).
     */
    @Test
    void leavingRaysGetTheQuadraticsAnswer() {
        Random rnd = new Random(11);
        int leaving = 0, leavingHits = 0, negativeZero = 0;
        for (int k = 0; k < 2_000_000; k++) {
            double scale = Math.pow(10, rnd.nextInt(311) - 160);         // 1e-160 .. 1e150
            double r = scale * (0.01 + rnd.nextDouble());
            double cx = scale * 10 * (rnd.nextDouble() - 0.5), cy = scale * 10 * (rnd.nextDouble() - 0.5), cz = scale * 10 * (rnd.nextDouble() - 0.5);
            double ux = rnd.nextGaussian(), uy = rnd.nextGaussian(), uz = rnd.nextGaussian();
            double ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
            ux /= ul;
            uy /= ul;
            uz /= ul;
            // the origin on the surface, a few ulps off it, or a little further out
            int kind = rnd.nextInt(4);
            double rr = kind == 0 ? r : kind == 1 ? r * (1 + (rnd.nextInt(9) - 4) * 0x1p-52)
                    : kind == 2 ? r * (1 + 1e-9 * rnd.nextDouble()) : r * (1 + rnd.nextDouble());
            double ox = cx + rr * ux, oy = cy + rr * uy, oz = cz + rr * uz;
            double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
            if (rnd.nextInt(4) == 0) {             // tangent: the normal's component removed, a hair of it put back
                double un = dx * ux + dy * uy + dz * uz, eps = rnd.nextInt(3) == 0 ? 0 : Math.pow(10, -rnd.nextInt(300));
                dx += (eps - un) * ux;
                dy += (eps - un) * uy;
                dz += (eps - un) * uz;
            }
            double mag = Math.pow(10, rnd.nextInt(301) - 150);           // |d| from 1e-150 to 1e150
            dx *= mag;
            dy *= mag;
            dz *= mag;
            int t = rnd.nextInt(5);
            double tMin = t == 0 ? -r / mag : t == 1 ? -0.0 : t == 2 ? 1e-9 : 0, tMax = Double.POSITIVE_INFINITY;
            double expected = beforeLeavingExit(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin, tMax);
            double got = Sphere.hit(cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin, tMax);
            if (Double.doubleToLongBits(expected) != Double.doubleToLongBits(got)) {   // bit for bit, -0.0 too
                fail("case " + k + ": expected " + expected + ", got " + got + " for "
                        + java.util.Arrays.toString(new double[] {cx, cy, cz, r, ox, oy, oz, dx, dy, dz, tMin}));
            }
            double fx = ox - cx, fy = oy - cy, fz = oz - cz;
            if (fx * dx + fy * dy + fz * dz > 0 && (fx * fx + fy * fy + fz * fz) - r * r > 0) {
                leaving++;
                if (expected == expected) {
                    leavingHits++;
                    if (Double.doubleToRawLongBits(expected) == Double.doubleToRawLongBits(-0.0)) {
                        negativeZero++;
                    }
                }
            }
        }
        assertTrue(leaving > 500_000, "enough leaving rays: " + leaving);
        // hits of leaving rays: behind the origin, taken where tMin < 0
        assertTrue(leavingHits > 10_000, "enough leaving rays that hit: " + leavingHits);
        assertTrue(negativeZero > 0, "a leaving ray hit at -0.0: " + negativeZero);
    }
}
