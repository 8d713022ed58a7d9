package ray.bench;

import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import ray.surface.Sphere;

/**
 * A feasibility measurement for issue 20, not product code: camera rays tested against a small scene's
 * spheres four at a time in the lanes of a vector, each lane doing {@link Sphere#hit}'s operations in its
 * order, against the scalar kernel on the same rays. The rays are classic's camera rays (its eye, 4
 * samples of a pixel side by side), the spheres classic's three; each op is one ray tested against the
 * three spheres, keeping the nearest hit.
 *
 * <p>The lane version here covers what camera rays need (tMin &gt; 0, so the scalar kernel's tMin = 0
 * bounds do not arise) and is checked in {@link #setup} to give every ray the scalar kernel's nearest t
 * bit for bit, on these rays and on random ones from the eye; a lane version that differs makes the
 * benchmark fail rather than report a number. Run: {@code gradle jmh -PjmhArgs='SphereLanesBench'}.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(value = 1, jvmArgsAppend = {"-XX:+UseParallelGC", "--add-modules=jdk.incubator.vector"})
public class SphereLanesBench {

    static final VectorSpecies<Double> D = DoubleVector.SPECIES_256;
    static final int N = 4096;
    static final double T_MIN = 1e-9;
    static final double[][] SPHERES = {{-2.3, 1, 0.3, 1}, {0, 1, -1.2, 1}, {2.3, 1, 0.3, 1}};
    static final double OX = 0, OY = 2.6, OZ = 9;

    double[] dx = new double[N], dy = new double[N], dz = new double[N];
    double[] tScalar = new double[N], tLanes = new double[N];

    @Setup
    public void setup() {
        cameraRays(dx, dy, dz);
        check("camera rays");
        Random r = new Random(465);
        double[] x = dx.clone(), y = dy.clone(), z = dz.clone();
        for (int i = 0; i < N; i++) {   // any direction from the eye, some of them straight at a sphere
            dx[i] = 2 * r.nextDouble() - 1;
            dy[i] = 2 * r.nextDouble() - 1;
            dz[i] = 2 * r.nextDouble() - 1;
            if (i % 8 == 0) {
                double[] s = SPHERES[i % 3];
                dx[i] = s[0] - OX;
                dy[i] = s[1] - OY;
                dz[i] = s[2] - OZ;
            }
        }
        check("random rays");
        System.arraycopy(x, 0, dx, 0, N);
        System.arraycopy(y, 0, dy, 0, N);
        System.arraycopy(z, 0, dz, 0, N);
    }

    /** classic's camera (eye [0 2.6 9] toward [0 0.9 0], 40 degrees), 4 side-by-side samples of each of N / 4 pixels. */
    static void cameraRays(double[] dx, double[] dy, double[] dz) {
        Random r = new Random(3);
        double wy = 0.9 - OY, wz = 0 - OZ, wl = Math.sqrt(wy * wy + wz * wz);
        wy /= wl;
        wz /= wl;
        double h = Math.tan(Math.toRadians(20)), w = h * 640 / 480;
        for (int i = 0; i < N; i += 4) {
            double u = w * (2 * r.nextDouble() - 1), v = h * (2 * r.nextDouble() - 1);
            for (int k = 0; k < 4; k++) {
                double uk = u + k * (2 * w / 1920), vk = v;
                // up' = (0, wz, -wy) (perpendicular to w in the y-z plane), right = (1, 0, 0)
                dx[i + k] = uk;
                dy[i + k] = wy + vk * -wz;
                dz[i + k] = wz + vk * wy;
            }
        }
    }

    private void check(String what) {
        scalar();
        lanes();
        for (int i = 0; i < N; i++) {
            if (Double.doubleToRawLongBits(tScalar[i]) != Double.doubleToRawLongBits(tLanes[i])) {
                throw new AssertionError(what + ": ray " + i + " scalar t " + tScalar[i] + ", lanes t " + tLanes[i]);
            }
        }
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public double[] scalar() {
        double[] t = tScalar;
        Arrays.fill(t, Double.POSITIVE_INFINITY);
        for (int i = 0; i < N; i++) {
            for (double[] s : SPHERES) {
                double h = Sphere.hit(s[0], s[1], s[2], s[3], OX, OY, OZ, dx[i], dy[i], dz[i], T_MIN, t[i]);
                if (h == h) {
                    t[i] = h;
                }
            }
        }
        return t;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public double[] lanes() {
        double[] t = tLanes;
        Arrays.fill(t, Double.POSITIVE_INFINITY);
        for (int i = 0; i < N; i += 4) {
            for (double[] s : SPHERES) {
                hit4(s[0], s[1], s[2], s[3], i, t);
            }
        }
        return t;
    }

    /** {@link Sphere#hit} for rays i..i+3 from the eye with tMin = {@link #T_MIN}: a lane's nearer hit lowers its t[i + lane]. */
    private void hit4(double cx, double cy, double cz, double r, int i, double[] t) {
        double fx = OX - cx, fy = OY - cy, fz = OZ - cz;
        DoubleVector x = DoubleVector.fromArray(D, dx, i), y = DoubleVector.fromArray(D, dy, i), z = DoubleVector.fromArray(D, dz, i);
        DoubleVector a = x.mul(x).add(y.mul(y)).add(z.mul(z));
        DoubleVector b = x.mul(fx).add(y.mul(fy)).add(z.mul(fz));       // fx * dx + fy * dy + fz * dz, in that order
        double ff = fx * fx + fy * fy + fz * fz, c = ff - r * r;
        VectorMask<Double> live = a.compare(VectorOperators.GT, 0).and(a.compare(VectorOperators.LT, Double.POSITIVE_INFINITY));
        if (c > 0) {     // leaving from outside (b > 0, c > 0, tMin > 0): no hit
            live = live.andNot(b.compare(VectorOperators.GT, 0));
        }
        DoubleVector qx = z.mul(fy).sub(y.mul(fz));                      // fy * dz - fz * dy
        DoubleVector qy = x.mul(fz).sub(z.mul(fx));                      // fz * dx - fx * dz
        DoubleVector qz = y.mul(fx).sub(x.mul(fy));                      // fx * dy - fy * dx
        DoubleVector cross = qx.mul(qx).add(qy.mul(qy)).add(qz.mul(qz));
        live = live.and(cross.compare(VectorOperators.LE, a.mul(r * r * (1 + 1e-6) + 1e-6 * ff)));
        if (!live.anyTrue()) {
            return;
        }
        DoubleVector s = b.div(a);
        DoubleVector lx = s.mul(x).neg().add(fx), ly = s.mul(y).neg().add(fy), lz = s.mul(z).neg().add(fz);
        DoubleVector dist = lx.mul(lx).add(ly.mul(ly)).add(lz.mul(lz)).sqrt();
        DoubleVector disc = dist.neg().add(r).mul(dist.add(r));
        live = live.and(disc.compare(VectorOperators.GE, 0));
        if (!live.anyTrue()) {
            return;
        }
        DoubleVector root = a.mul(disc).sqrt();
        DoubleVector q = b.add(root.blend(root.neg(), b.test(VectorOperators.IS_NEGATIVE))).neg();   // -(b + copySign(root, b))
        VectorMask<Double> q0 = q.compare(VectorOperators.EQ, 0);
        DoubleVector t0 = DoubleVector.broadcast(D, c).div(q).blend(0, q0), t1 = q.div(a).blend(0, q0);
        VectorMask<Double> ordered = t0.compare(VectorOperators.LE, t1), reversed = t1.compare(VectorOperators.LT, t0);
        live = live.and(ordered.or(reversed));                           // a NaN root is a miss
        DoubleVector near = t1.blend(t0, ordered), far = t0.blend(t1, ordered);
        DoubleVector hi = DoubleVector.fromArray(D, t, i);
        VectorMask<Double> nearIn = near.compare(VectorOperators.GE, T_MIN).and(near.compare(VectorOperators.LE, hi));
        VectorMask<Double> farIn = far.compare(VectorOperators.GE, T_MIN).and(far.compare(VectorOperators.LE, hi));
        hi.blend(far.blend(near, nearIn), live.and(nearIn.or(farIn))).intoArray(t, i);
    }
}
