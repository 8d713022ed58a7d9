package ray.bench;

import java.util.Random;
import java.util.concurrent.TimeUnit;
import javax.vecmath.Vector3d;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.Sphere;
import ray.surface.Triangle;

/**
 * The ray/primitive kernels, per call: the static kernels the BVH uses ({@code Sphere.hit},
 * {@code Triangle.setupRay} + {@code Triangle.hit}) and the framework's {@code intersects} on the same
 * rays. 1,024 random rays against one sphere and one triangle, about half of them hitting; each
 * benchmark op is one ray (OperationsPerInvocation), so the score is nanoseconds per test.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.NANOSECONDS)
@Fork(value = 1, jvmArgsAppend = {"-XX:+UseParallelGC"})
public class KernelBench {

    static final int N = 1024;

    double[] rays = new double[6 * N];
    Ray[] rayObjects = new Ray[N];
    Sphere sphere = new Sphere();
    Triangle triangle = new Triangle();
    double[] triData;
    double[] kernel = new double[Triangle.KERNEL_SIZE];
    IntersectionRecord rec = new IntersectionRecord();

    @Setup
    public void setup() {
        Random r = new Random(465);
        sphere.center = new Vector3d(0, 0, 0);
        sphere.radius = 1;
        triangle.v0 = new Vector3d(-1, -1, 0);
        triangle.v1 = new Vector3d(1, -1, 0);
        triangle.v2 = new Vector3d(0, 1.5, 0);
        triData = new double[] {-1, -1, 0, 1, -1, 0, 0, 1.5, 0};
        for (int i = 0; i < N; i++) {
            // from a point on a sphere of radius 5 towards a point in [-1.5, 1.5]^2 x {0}
            double th = Math.PI * r.nextDouble(), ph = 2 * Math.PI * r.nextDouble();
            double ox = 5 * Math.sin(th) * Math.cos(ph), oy = 5 * Math.sin(th) * Math.sin(ph), oz = 5 * Math.cos(th);
            if (oz < 0) {
                oz = -oz;   // in front of the one-sided triangle
            }
            double tx = 3 * r.nextDouble() - 1.5, ty = 3 * r.nextDouble() - 1.5;
            double dx = tx - ox, dy = ty - oy, dz = -oz, l = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double[] v = {ox, oy, oz, dx / l, dy / l, dz / l};
            System.arraycopy(v, 0, rays, 6 * i, 6);
            rayObjects[i] = new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx / l, dy / l, dz / l));
            rayObjects[i].tMin = 0;
        }
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public double sphereHitKernel() {
        double s = 0;
        double[] a = rays;
        for (int i = 0; i < 6 * N; i += 6) {
            double t = Sphere.hit(0, 0, 0, 1, a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], 0, Double.POSITIVE_INFINITY);
            if (t == t) {
                s += t;
            }
        }
        return s;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public double sphereIntersects() {
        double s = 0;
        for (Ray r : rayObjects) {
            if (sphere.intersects(r, rec, null)) {
                s += rec.t;
            }
        }
        return s;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public double triangleHitKernel() {
        double s = 0;
        for (Ray r : rayObjects) {
            Triangle.setupRay(r, kernel, 0);
            double[] k = kernel;
            double t = Triangle.hit(triData, 0, (int) k[0], (int) k[1], (int) k[2], k[3], k[4], k[5], k[6], k[7], k[8],
                    0, Double.POSITIVE_INFINITY, k, 9);
            if (t == t) {
                s += t;
            }
        }
        return s;
    }

    @Benchmark
    @OperationsPerInvocation(N)
    public double triangleIntersects() {
        double s = 0;
        for (Ray r : rayObjects) {
            if (triangle.intersects(r, rec, null)) {
                s += rec.t;
            }
        }
        return s;
    }
}
