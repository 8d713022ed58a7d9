package ray.bench;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Accelerator;
import ray.parse.Parser;

/**
 * The BVH queries on a benchmark scene's camera rays (one per pixel centre, as embree_rays.py casts
 * them): closest hit with the record filled in, and any hit. One op is one pass over all the rays;
 * divide the rays (480,000 for mesh100k) by the score for rays per second. The scene is found as
 * {@code raytracer --bench} finds it (RAYTRACER_BENCH_DIR or ../shared/bench; mesh100k is generated
 * when missing).
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.AverageTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(value = 1, jvmArgsAppend = {"-XX:+UseParallelGC"})
public class BvhBench {

    @Param({"mesh100k"})
    String scene;

    Accelerator accel;
    double[] rays;
    TraceContext ctx;
    Ray ray = new Ray();
    IntersectionRecord rec = new IntersectionRecord();

    @Setup(Level.Trial)
    public void setup() throws Exception {
        Path dir = Bench.sceneDirectory(Bench.findBenchDir(null), Bench.defaultWork(), List.of(scene), System.out);
        Scene s = Parser.parse(dir.resolve(scene + ".txt"));
        s.prepare();
        accel = s.accelerator();
        ctx = new TraceContext(s.maxDepth);
        int w = s.width, h = s.height;
        rays = new double[6 * w * h];
        Ray r = new Ray();
        for (int y = 0, i = 0; y < h; y++) {
            for (int x = 0; x < w; x++, i += 6) {
                s.camera.setRayThrough(r, x + 0.5, y + 0.5, w, h);
                rays[i] = r.origin.x; rays[i + 1] = r.origin.y; rays[i + 2] = r.origin.z;
                rays[i + 3] = r.direction.x; rays[i + 4] = r.direction.y; rays[i + 5] = r.direction.z;
            }
        }
    }

    @Benchmark
    public int closestHitAllCameraRays() {
        int hits = 0;
        double[] a = rays;
        for (int i = 0; i < a.length; i += 6) {
            ray.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], 0, Double.POSITIVE_INFINITY, 0);
            if (accel.closestHit(ray, rec, ctx)) {
                hits++;
            }
        }
        return hits;
    }

    @Benchmark
    public int anyHitAllCameraRays() {
        int hits = 0;
        double[] a = rays;
        for (int i = 0; i < a.length; i += 6) {
            ray.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], 0, Double.POSITIVE_INFINITY, 0);
            if (accel.anyHit(ray, ctx)) {
                hits++;
            }
        }
        return hits;
    }
}
