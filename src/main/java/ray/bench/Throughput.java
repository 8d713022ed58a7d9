package ray.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Accelerator;
import ray.light.Light;
import ray.light.LightSample;
import ray.material.GlazedMaterial;

/**
 * In-process ray throughput of the acceleration structure alone, by ray kind, the way
 * {@code embree_rays.py} measures Embree: one camera ray per pixel centre; the shadow rays those
 * camera rays' hits send to each light (only where the light is in front of the surface, as the
 * renderer does); the mirror rays they send off glazed surfaces. Camera and mirror rays take the
 * closest-hit query (with the hit record filled in, as the renderer needs it), shadow rays the any-hit
 * query. One thread, timed after warm-up passes so the JIT has compiled the traversal; no shading.
 */
public final class Throughput {

    /** The three kinds of ray a Whitted renderer casts. */
    public enum Kind {
        CAMERA("camera", true), SHADOW("shadow", false), MIRROR("mirror", true);

        final String label;
        final boolean closest;

        Kind(String label, boolean closest) {
            this.label = label;
            this.closest = closest;
        }

        public String label() {
            return label;
        }
    }

    /**
     * Rays per second of one ray set: median and best pass, and the median per CPU second. (A plain
     * class, not a record: Gradle 4.4.1's class reader calls record classes malformed.)
     */
    public static final class Rate {
        private final Kind kind;
        private final String query;
        private final int rays, hits;
        private final double medianSeconds, bestSeconds, cpuSeconds;

        Rate(Kind kind, String query, int rays, double medianSeconds, double bestSeconds, int hits, double cpuSeconds) {
            this.kind = kind;
            this.query = query;
            this.rays = rays;
            this.medianSeconds = medianSeconds;
            this.bestSeconds = bestSeconds;
            this.hits = hits;
            this.cpuSeconds = cpuSeconds;
        }

        public Kind kind() {
            return kind;
        }

        public String query() {
            return query;
        }

        public int rays() {
            return rays;
        }

        public int hits() {
            return hits;
        }

        public double cpuSeconds() {
            return cpuSeconds;
        }

        public double mraysPerSecond() {
            return rays / medianSeconds / 1e6;
        }

        public double bestMraysPerSecond() {
            return rays / bestSeconds / 1e6;
        }

        public double mraysPerCpuSecond() {
            return rays / cpuSeconds / 1e6;
        }
    }

    private static final int STRIDE = 8;   // ox oy oz dx dy dz tMin tMax

    private final Scene scene;
    private final double[][] sets = new double[Kind.values().length][];

    public Throughput(Scene scene) {
        this.scene = scene;
        scene.prepare();
        int w = scene.width, h = scene.height;
        double[] camera = new double[STRIDE * w * h];
        Ray r = new Ray();
        for (int y = 0, i = 0; y < h; y++) {
            for (int x = 0; x < w; x++, i += STRIDE) {
                scene.camera.setRayThrough(r, x + 0.5, y + 0.5, w, h);
                put(camera, i, r);
            }
        }
        sets[Kind.CAMERA.ordinal()] = camera;
        // secondary rays from the camera rays' hits, spawned exactly as the renderer spawns them
        Accelerator accel = scene.accelerator();
        TraceContext ctx = new TraceContext(scene.maxDepth);
        IntersectionRecord rec = new IntersectionRecord();
        LightSample s = new LightSample();
        Ray shadow = new Ray(), mirror = new Ray();
        Grow shadows = new Grow(), mirrors = new Grow();
        for (int i = 0; i < camera.length; i += STRIDE) {
            get(camera, i, r);
            if (!accel.closestHit(r, rec, ctx)) {
                continue;
            }
            Vector3d n = rec.normal;
            for (Light light : scene.lights) {
                for (int k = 0, c = light.sampleCount(); k < c; k++) {
                    if (!light.sample(rec, scene, k, s) || s.shadowTested) {
                        continue;
                    }
                    Vector3d l = s.direction;
                    if (n.x * l.x + n.y * l.y + n.z * l.z > 0) {
                        rec.spawnRayTo(s.position.x, s.position.y, s.position.z, shadow);
                        shadows.add(shadow);
                    }
                }
            }
            if (rec.surface.material instanceof GlazedMaterial g && g.mirrorCoefficient != 0 && scene.maxDepth > 0) {
                Vector3d d = r.direction;
                double dn = 2 * (d.x * n.x + d.y * n.y + d.z * n.z);
                rec.spawnRay(d.x - dn * n.x, d.y - dn * n.y, d.z - dn * n.z, mirror);
                mirrors.add(mirror);
            }
        }
        sets[Kind.SHADOW.ordinal()] = shadows.toArray();
        sets[Kind.MIRROR.ordinal()] = mirrors.toArray();
    }

    private static final class Grow {
        double[] a = new double[STRIDE * 1024];
        int n;

        void add(Ray r) {
            if (n + STRIDE > a.length) {
                a = Arrays.copyOf(a, 2 * a.length);
            }
            put(a, n, r);
            n += STRIDE;
        }

        double[] toArray() {
            return Arrays.copyOf(a, n);
        }
    }

    private static void put(double[] a, int i, Ray r) {
        a[i] = r.origin.x; a[i + 1] = r.origin.y; a[i + 2] = r.origin.z;
        a[i + 3] = r.direction.x; a[i + 4] = r.direction.y; a[i + 5] = r.direction.z;
        a[i + 6] = r.tMin; a[i + 7] = r.tMax;
    }

    private static void get(double[] a, int i, Ray r) {
        r.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], a[i + 6], a[i + 7], 0);
    }

    /** Number of rays of {@code kind} in this scene's sets (pixel centres and the rays they spawn). */
    public int rayCount(Kind kind) {
        return sets[kind.ordinal()].length / STRIDE;
    }

    /** Closest-hit rate on the camera rays (the Embree comparison). */
    public Rate closestHit(int warmups, int passes) {
        return run(Kind.CAMERA, true, warmups, passes);
    }

    /** Any-hit rate on the camera rays with t up to infinity (as embree_rays.py's rtcOccluded1). */
    public Rate anyHit(int warmups, int passes) {
        return run(Kind.CAMERA, false, warmups, passes);
    }

    /** The rate of one kind with the query the renderer uses for it; null when the scene casts none. */
    public Rate measure(Kind kind, int warmups, int passes) {
        return rayCount(kind) == 0 ? null : run(kind, kind.closest, warmups, passes);
    }

    /**
     * Inner-node visits and primitive tests per ray of one pass over the rays of {@code kind}: counted
     * only in a JVM started with {@code -Dray.bvh.count=true} (zeros otherwise).
     */
    public double[] workPerRay(Kind kind) {
        double[] rays = sets[kind.ordinal()];
        TraceContext ctx = new TraceContext(scene.maxDepth);
        pass(scene.accelerator(), ctx, new Ray(), new IntersectionRecord(), rays, kind.closest);
        double n = Math.max(1, rays.length / STRIDE);
        ray.accel.Bvh bvh = (ray.accel.Bvh) scene.accelerator();
        return new double[] {bvh.nodeVisits(ctx) / n, bvh.primitiveTests(ctx) / n};
    }

    private Rate run(Kind kind, boolean closest, int warmups, int passes) {
        double[] rays = sets[kind.ordinal()];
        Accelerator accel = scene.accelerator();
        TraceContext ctx = new TraceContext(scene.maxDepth);
        Ray r = new Ray();
        IntersectionRecord rec = new IntersectionRecord();
        double[] times = new double[passes], cpu = new double[passes];
        ThreadMXBean mx = ManagementFactory.getThreadMXBean();
        int hits = 0;
        // a small set (a few thousand mirror rays) is traced several times per pass, so that a pass
        // lasts long enough to time (and to let the JIT settle) however few rays the scene casts
        int count = rays.length / STRIDE, repeat = Math.max(1, 200_000 / Math.max(1, count));
        for (int p = -warmups; p < passes; p++) {
            long c0 = mx.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            for (int k = 0; k < repeat; k++) {
                hits = pass(accel, ctx, r, rec, rays, closest);
            }
            long t1 = System.nanoTime();
            long c1 = mx.getCurrentThreadCpuTime();
            if (p >= 0) {
                times[p] = (t1 - t0) / 1e9;
                cpu[p] = (c1 - c0) / 1e9;
            }
        }
        Arrays.sort(times);
        Arrays.sort(cpu);
        return new Rate(kind, closest ? "closest hit" : "any hit", count * repeat, times[passes / 2], times[0], hits * repeat,
                cpu[passes / 2]);
    }

    private static int pass(Accelerator accel, TraceContext ctx, Ray r, IntersectionRecord rec, double[] a, boolean closest) {
        int hits = 0;
        for (int i = 0; i < a.length; i += STRIDE) {
            r.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], a[i + 6], a[i + 7], 0);
            if (closest ? accel.closestHit(r, rec, ctx) : accel.anyHit(r, ctx)) {
                hits++;
            }
        }
        return hits;
    }

    /**
     * {@code java ray.bench.Throughput scene.txt [passes]}: prints the rates. With {@code --row NAME
     * scene.txt}: one Markdown table row (camera, shadow, mirror, camera any-hit; median Mrays/s), and
     * with {@code --camera scene.txt}: "closest MEDIAN BEST" and "any MEDIAN BEST" lines for the
     * camera rays (what {@code raytracer --bench} reads from the JVMs it starts).
     */
    public static void main(String[] args) throws Exception {
        if (args[0].equals("--row")) {
            Throughput t = new Throughput(ray.parse.Parser.parse(java.nio.file.Path.of(args[2])));
            StringBuilder row = new StringBuilder("| " + args[1] + " |");
            for (Kind k : Kind.values()) {
                Rate r = t.measure(k, 3, 7);
                row.append(r == null ? " - |" : String.format(java.util.Locale.ROOT, " %.2f |", r.mraysPerSecond()));
            }
            row.append(String.format(java.util.Locale.ROOT, " %.2f |", t.anyHit(3, 7).mraysPerSecond()));
            System.out.println(row);
            return;
        }
        if (args[0].equals("--alloc")) {
            System.out.println(allocationLine(ray.parse.Parser.parse(java.nio.file.Path.of(args[1]))));
            return;
        }
        if (args[0].equals("--camera")) {
            Throughput t = new Throughput(ray.parse.Parser.parse(java.nio.file.Path.of(args[1])));
            Rate c = t.closestHit(5, 9), a = t.anyHit(5, 9);
            System.out.println(String.format(java.util.Locale.ROOT, "closest %.3f %.3f", c.mraysPerSecond(), c.bestMraysPerSecond()));
            System.out.println(String.format(java.util.Locale.ROOT, "any %.3f %.3f", a.mraysPerSecond(), a.bestMraysPerSecond()));
            return;
        }
        Scene s = ray.parse.Parser.parse(java.nio.file.Path.of(args[0]));
        int passes = args.length > 1 ? Integer.parseInt(args[1]) : 7;
        Throughput t = new Throughput(s);
        print(t.closestHit(3, passes), "camera rays");
        print(t.anyHit(3, passes), "camera rays");
        for (Kind k : new Kind[] {Kind.SHADOW, Kind.MIRROR}) {
            Rate r = t.measure(k, 3, passes);
            if (r != null) {
                print(r, k.label + " rays");
            }
        }
    }

    /**
     * Heap bytes allocated per ray by a whole render on this thread (one render thread, after one
     * warm-up render): what the hot path allocates, measured, not hoped for from escape analysis.
     * "alloc BYTES_PER_RAY RAYS TOTAL_BYTES IMAGE_BYTES", bytes per ray not counting the image.
     */
    static String allocationLine(Scene s) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long self = Thread.currentThread().getId();
        new ray.render.Renderer(s).threads(1).render();
        ray.render.Renderer r = new ray.render.Renderer(s).threads(1);
        s.prepare();   // build outside the measured span
        long a0 = mx.getThreadAllocatedBytes(self);
        // the renderer calls prepare() itself: subtract what a build allocates, measured alone
        r.render();
        long a1 = mx.getThreadAllocatedBytes(self);
        s.prepare();
        long a2 = mx.getThreadAllocatedBytes(self);
        long rays = r.stats().total();
        long render = (a1 - a0) - (a2 - a1);
        long image = 24L * s.width * s.height;   // the result: 3 doubles per pixel, allocated once
        return String.format(java.util.Locale.ROOT, "alloc %.4f %d %d %d", (double) (render - image) / rays, rays, render, image);
    }

    private static void print(Rate r, String what) {
        System.out.println(String.format("%-11s %-12s %,9d rays, %5.1f%% hit: median %6.2f Mrays/s, best %6.2f, per CPU second %6.2f",
                r.query(), what, r.rays(), 100.0 * r.hits() / r.rays(), r.mraysPerSecond(), r.bestMraysPerSecond(),
                r.mraysPerCpuSecond()));
    }
}
