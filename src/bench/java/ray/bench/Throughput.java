package ray.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Accelerator;

/**
 * In-process ray throughput of the acceleration structure alone, by ray kind, the way
 * {@code embree_rays.py} measures Embree: one camera ray per pixel centre, and every ray the renderer
 * casts while shading them (shadow, mirror, refraction, user rays), recorded from a real render of those
 * camera rays with {@link RayKind} told by the ray-query layer's own counters (so no shading rule is
 * repeated here). Camera, mirror, refraction and user rays take the closest-hit query (with the hit
 * record filled in, as the renderer needs it), shadow rays the any-hit query. One thread, timed after
 * warm-up passes, and more until a pass finishes no compilation, so the JIT has compiled the traversal; no shading.
 */
public final class Throughput {

    /** The query the renderer uses for rays of {@code kind}: closest hit, except any hit for shadow rays. */
    static boolean closest(RayKind kind) {
        return kind != RayKind.SHADOW;
    }

    /**
     * Rays per second of one ray set: median and best pass, and the median per CPU second. (A plain
     * class, not a record: Gradle 4.4.1's class reader calls record classes malformed.)
     */
    public static final class Rate {
        private final RayKind kind;
        private final String query;
        private final int rays, hits;
        private final double medianSeconds, bestSeconds, cpuSeconds;

        Rate(RayKind kind, String query, int rays, double medianSeconds, double bestSeconds, int hits, double cpuSeconds) {
            this.kind = kind;
            this.query = query;
            this.rays = rays;
            this.medianSeconds = medianSeconds;
            this.bestSeconds = bestSeconds;
            this.hits = hits;
            this.cpuSeconds = cpuSeconds;
        }

        public RayKind kind() {
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
    private final double[][] sets = new double[RayKind.values().length][];

    public Throughput(Scene scene) {
        this.scene = scene;
        scene.prepare();
        Accelerator accel = scene.accelerator();
        Recorder recorder = new Recorder(accel);
        TraceContext ctx = new TraceContext(scene.maxDepth);
        TraceContext.bind(ctx);   // a user's class tracing through Scene.trace counts on this context too
        scene.useAccelerator(recorder);
        try {
            int w = scene.width, h = scene.height;
            Ray r = new Ray();
            Vector3d color = new Vector3d();
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    scene.camera.setRayThrough(r, x + 0.5, y + 0.5, w, h);
                    scene.traceCamera(r, ctx, color);
                }
            }
        } finally {
            scene.useAccelerator(accel);
            TraceContext.bind(null);
        }
        for (RayKind k : RayKind.values()) {
            sets[k.ordinal()] = recorder.rays[k.ordinal()].toArray();
        }
    }

    /**
     * Passes every query on to the real accelerator and keeps a copy of its ray under the kind whose
     * count in the thread's {@link ray.RayStats} has just gone up (the ray-query layer counts a ray right
     * before it asks the accelerator).
     */
    private static final class Recorder implements Accelerator {
        final Accelerator inner;
        final Grow[] rays = new Grow[RayKind.values().length];
        final long[] seen = new long[RayKind.values().length];

        Recorder(Accelerator inner) {
            this.inner = inner;
            for (int i = 0; i < rays.length; i++) {
                rays[i] = new Grow();
            }
        }

        private void record(Ray ray, TraceContext ctx) {
            for (RayKind k : RayKind.values()) {
                long n = ctx.stats.get(k);
                if (n != seen[k.ordinal()]) {
                    seen[k.ordinal()] = n;
                    rays[k.ordinal()].add(ray);
                    return;
                }
            }
        }

        @Override
        public boolean closestHit(Ray ray, IntersectionRecord rec, TraceContext ctx) {
            record(ray, ctx);
            return inner.closestHit(ray, rec, ctx);
        }

        @Override
        public boolean anyHit(Ray ray, TraceContext ctx) {
            record(ray, ctx);
            return inner.anyHit(ray, ctx);
        }
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
    public int rayCount(RayKind kind) {
        return sets[kind.ordinal()].length / STRIDE;
    }

    /** Closest-hit rate on the camera rays (the Embree comparison). */
    public Rate closestHit(int warmups, int passes) {
        return run(RayKind.CAMERA, true, warmups, passes);
    }

    /** Any-hit rate on the camera rays with t up to infinity (as embree_rays.py's rtcOccluded1). */
    public Rate anyHit(int warmups, int passes) {
        return run(RayKind.CAMERA, false, warmups, passes);
    }

    /** The rate of one kind with the query the renderer uses for it; null when the scene casts none. */
    public Rate measure(RayKind kind, int warmups, int passes) {
        return rayCount(kind) == 0 ? null : run(kind, closest(kind), warmups, passes);
    }

    /**
     * Inner-node visits and primitive tests per ray of one pass over the rays of {@code kind}: counted
     * only in a JVM started with {@code -Dray.bvh.count=true} (zeros otherwise).
     */
    public double[] workPerRay(RayKind kind) {
        double[] rays = sets[kind.ordinal()];
        TraceContext ctx = new TraceContext(scene.maxDepth);
        pass(scene.accelerator(), ctx, new Ray(), new IntersectionRecord(), rays, closest(kind));
        double n = Math.max(1, rays.length / STRIDE);
        ray.accel.Bvh bvh = (ray.accel.Bvh) scene.accelerator();
        return new double[] {bvh.nodeVisits(ctx) / n, bvh.primitiveTests(ctx) / n};
    }

    /** Most warm-up passes beyond those asked for, while the JIT is still compiling ({@link #run}). */
    static final int SETTLE_PASSES = 40;

    private Rate run(RayKind kind, boolean closest, int warmups, int passes) {
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
        // warm-up: the passes asked for, then more until one pass goes by with no compilation finished in
        // it (at most SETTLE_PASSES more): C2 compiles the traversal several times over its first second
        // (a trap when a ray takes a branch the profile had never seen, then a recompilation), and a pass
        // timed on code about to be thrown away measured that code, not the traversal's steady state
        // (docs/performance.md, issue 20, session 41)
        for (int p = 0; p < warmups; p++) {
            hits = pass(accel, ctx, r, rec, rays, closest);
        }
        java.lang.management.CompilationMXBean jit = ManagementFactory.getCompilationMXBean();
        boolean timed = jit != null && jit.isCompilationTimeMonitoringSupported();
        long compiled = timed ? jit.getTotalCompilationTime() : 0;
        for (int extra = 0; timed && extra < SETTLE_PASSES; extra++) {
            for (int k = 0; k < repeat; k++) {
                hits = pass(accel, ctx, r, rec, rays, closest);
            }
            long now = jit.getTotalCompilationTime();
            if (now == compiled) {
                break;
            }
            compiled = now;
        }
        for (int p = 0; p < passes; p++) {
            long c0 = mx.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            for (int k = 0; k < repeat; k++) {
                hits = pass(accel, ctx, r, rec, rays, closest);
            }
            long t1 = System.nanoTime();
            long c1 = mx.getCurrentThreadCpuTime();
            times[p] = (t1 - t0) / 1e9;
            cpu[p] = (c1 - c0) / 1e9;
        }
        Arrays.sort(times);
        Arrays.sort(cpu);
        return new Rate(kind, closest ? "closest hit" : "any hit", count * repeat, times[passes / 2], times[0], hits * repeat,
                cpu[passes / 2]);
    }

    /** Rays a call of {@link #closestRays} or {@link #anyRays} traces. */
    private static final int CHUNK = 256;

    /**
     * One pass over the rays in {@code a}, {@link #CHUNK} rays a call. Not one loop over all of them: a
     * method called once a pass, its loop running a million times, is compiled on the stack, thrown
     * away when the other query's pass comes, and compiled whole only after a dozen calls, so the passes
     * timed on it measured C1's loop in some runs and C2's in others (mesh100k's camera rays at 4.1-4.6
     * or 6.6-7.2 Mrays/s from run to run, docs/performance.md, issue 20, session 41). A method a query,
     * called a few thousand times a pass, is compiled whole in the first pass and never sees the other
     * query.
     */
    private static int pass(Accelerator accel, TraceContext ctx, Ray r, IntersectionRecord rec, double[] a, boolean closest) {
        int hits = 0;
        for (int i = 0; i < a.length; i += CHUNK * STRIDE) {
            int end = Math.min(a.length, i + CHUNK * STRIDE);
            hits += closest ? closestRays(accel, ctx, r, rec, a, i, end) : anyRays(accel, ctx, r, a, i, end);
        }
        return hits;
    }

    private static int closestRays(Accelerator accel, TraceContext ctx, Ray r, IntersectionRecord rec, double[] a, int from, int to) {
        int hits = 0;
        for (int i = from; i < to; i += STRIDE) {
            r.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], a[i + 6], a[i + 7], 0);
            if (accel.closestHit(r, rec, ctx)) {
                hits++;
            }
        }
        return hits;
    }

    private static int anyRays(Accelerator accel, TraceContext ctx, Ray r, double[] a, int from, int to) {
        int hits = 0;
        for (int i = from; i < to; i += STRIDE) {
            r.set(a[i], a[i + 1], a[i + 2], a[i + 3], a[i + 4], a[i + 5], a[i + 6], a[i + 7], 0);
            if (accel.anyHit(r, ctx)) {
                hits++;
            }
        }
        return hits;
    }

    /**
     * {@code java ray.bench.Throughput scene.txt [passes]}: prints the rates. With {@code --row NAME
     * scene.txt}: one Markdown table row (each RayKind, then camera any-hit; median Mrays/s), and
     * with {@code --camera scene.txt}: "closest MEDIAN BEST" and "any MEDIAN BEST" lines for the
     * camera rays (what {@code raytracer --bench} reads from the JVMs it starts).
     */
    public static void main(String[] args) throws Exception {
        if (args[0].equals("--row")) {
            Throughput t = new Throughput(ray.parse.Parser.parse(java.nio.file.Path.of(args[2])));
            StringBuilder row = new StringBuilder("| " + args[1] + " |");
            for (RayKind k : RayKind.values()) {
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
        for (RayKind k : RayKind.values()) {
            Rate r = k == RayKind.CAMERA ? null : t.measure(k, 3, passes);
            if (r != null) {
                print(r, k.key() + " rays");
            }
        }
    }

    /**
     * Heap bytes allocated per ray by a whole single-threaded render, after one warm-up render: what the hot
     * path allocates, measured, not hoped for from escape analysis. Counts every thread's allocation, the
     * render thread's (which the renderer starts) included: it needs a JVM with the Epsilon collector and
     * no thread-local allocation buffers (InProcessTables starts one), where the heap's used bytes only
     * grow, by exactly what is allocated; any other collector is refused rather than measured wrongly.
     * "alloc BYTES_PER_RAY RAYS TOTAL_BYTES IMAGE_BYTES", bytes per ray not counting the image.
     */
    static String allocationLine(Scene s) {
        boolean epsilon = false;
        for (java.lang.management.GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            epsilon |= gc.getName().startsWith("Epsilon");
        }
        if (!epsilon || ManagementFactory.getRuntimeMXBean().getInputArguments().indexOf("-XX:-UseTLAB") < 0) {
            throw new IllegalStateException("--alloc needs -XX:+UseEpsilonGC -XX:-UseTLAB (every thread's bytes, exactly)");
        }
        java.lang.management.MemoryMXBean heap = ManagementFactory.getMemoryMXBean();
        new ray.render.Renderer(s).threads(1).render();
        ray.render.Renderer r = new ray.render.Renderer(s).threads(1);
        s.prepare();   // build outside the measured span
        long a0 = heap.getHeapMemoryUsage().getUsed();
        // the renderer calls prepare() itself: subtract what a build allocates, measured alone
        r.render();
        long a1 = heap.getHeapMemoryUsage().getUsed();
        s.prepare();
        long a2 = heap.getHeapMemoryUsage().getUsed();
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
