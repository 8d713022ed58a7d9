package ray.bench;

import java.util.Arrays;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Accelerator;

/**
 * In-process ray throughput of the acceleration structure alone, the way {@code embree_rays.py}
 * measures Embree: one ray per pixel centre of the scene's camera, closest-hit (the renderer's
 * camera-ray query) and any-hit (its shadow query) over all of them, on one thread, timed after
 * warm-up passes so the JIT has compiled the traversal. No shading, no image.
 */
public final class Throughput {

    /** Rays per second of one query kind: median and best over the timed passes. */
    public record Rate(String query, int rays, double medianSeconds, double bestSeconds, int hits, double cpuSeconds) {
        public double mraysPerSecond() {
            return rays / medianSeconds / 1e6;
        }

        public double bestMraysPerSecond() {
            return rays / bestSeconds / 1e6;
        }
    }

    private final Scene scene;
    private final double[] rays;   // ox oy oz dx dy dz per ray
    private final int count;

    public Throughput(Scene scene) {
        this.scene = scene;
        scene.prepare();
        int w = scene.width, h = scene.height;
        count = w * h;
        rays = new double[6 * count];
        Ray r = new Ray();
        for (int y = 0, i = 0; y < h; y++) {
            for (int x = 0; x < w; x++, i += 6) {
                scene.camera.setRayThrough(r, x + 0.5, y + 0.5, w, h);
                rays[i] = r.origin.x; rays[i + 1] = r.origin.y; rays[i + 2] = r.origin.z;
                rays[i + 3] = r.direction.x; rays[i + 4] = r.direction.y; rays[i + 5] = r.direction.z;
            }
        }
    }

    public int rayCount() {
        return count;
    }

    /** Runs {@code warmups} untimed passes, then {@code passes} timed ones, of the closest-hit query. */
    public Rate closestHit(int warmups, int passes) {
        return run(true, warmups, passes);
    }

    /** As {@link #closestHit}, for the any-hit (shadow) query over the same rays with t up to infinity. */
    public Rate anyHit(int warmups, int passes) {
        return run(false, warmups, passes);
    }

    private Rate run(boolean closest, int warmups, int passes) {
        Accelerator accel = scene.accelerator();
        TraceContext ctx = new TraceContext(scene.maxDepth);
        Ray r = new Ray();
        IntersectionRecord rec = new IntersectionRecord();
        double[] times = new double[passes], cpu = new double[passes];
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        int hits = 0;
        for (int p = -warmups; p < passes; p++) {
            long c0 = mx.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            hits = pass(accel, ctx, r, rec, closest);
            long t1 = System.nanoTime();
            long c1 = mx.getCurrentThreadCpuTime();
            if (p >= 0) {
                times[p] = (t1 - t0) / 1e9;
                cpu[p] = (c1 - c0) / 1e9;
            }
        }
        Arrays.sort(times);
        Arrays.sort(cpu);
        return new Rate(closest ? "closest hit" : "any hit", count, times[passes / 2], times[0], hits, cpu[passes / 2]);
    }

    private int pass(Accelerator accel, TraceContext ctx, Ray r, IntersectionRecord rec, boolean closest) {
        int hits = 0;
        double[] a = rays;
        for (int i = 0, n = 6 * count; i < n; i += 6) {
            r.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], 0, Double.POSITIVE_INFINITY, 0);
            if (closest ? accel.closestHit(r, rec, ctx) : accel.anyHit(r, ctx)) {
                hits++;
            }
        }
        return hits;
    }

    /** {@code java ray.bench.Throughput scene.txt [passes]}: prints both rates. */
    public static void main(String[] args) throws Exception {
        Scene s = ray.parse.Parser.parse(java.nio.file.Path.of(args[0]));
        int passes = args.length > 1 ? Integer.parseInt(args[1]) : 7;
        Throughput t = new Throughput(s);
        for (Rate r : new Rate[] {t.closestHit(3, passes), t.anyHit(3, passes)}) {
            System.out.printf("%-11s %,d rays, %.1f%% hit: median %.2f Mrays/s, best %.2f Mrays/s (per CPU second: %.2f)%n",
                    r.query(), r.rays(), 100.0 * r.hits() / r.rays(), r.mraysPerSecond(), r.bestMraysPerSecond(),
                    r.rays() / r.cpuSeconds() / 1e6);
        }
    }
}
