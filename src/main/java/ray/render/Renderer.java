package ray.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import javax.vecmath.Vector3d;
import ray.Camera;
import ray.PixelSample;
import ray.Ray;
import ray.RayPacket;
import ray.RayStats;
import ray.Scene;
import ray.TraceContext;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * Renders a scene on all cores. The image is cut into {@value #TILE} x {@value #TILE} tiles handed out,
 * spread over the image ({@link #spreadStride}), to a fixed set of threads; each thread owns its
 * {@link TraceContext} (scratch objects and ray counters) and writes only its tiles' pixels. Every pixel
 * depends only on the scene, so the image is bit-identical for any thread count and tile order.
 */
public final class Renderer {

    public static final int TILE = 16;
    /**
     * Whether renders start with {@link #warmUpPixels} pixels spread over the image: asked for by
     * {@code -Dray.render.warmUp=true}, which the launcher passes to a long render (full tiered
     * compilation). C2 compiles the render's hottest methods from the branch and type profiles of their
     * first few thousand calls. Taken from the first tiles alone, those calls see one corner of the image
     * (its sky, one material, rays of one direction sign), and each branch or type the rest of the image
     * brings later throws C2's code away for a recompilation of the whole inlined traversal (80-250 ms
     * each; classichd recompiled Bvh.closestHit four or five times). Pixels spread over the image first
     * make the profile the image's: classichd's C2 compilations took 1.0-1.5 s (their wall time), now
     * 0.8-0.95 s, and its CPU time 0.94x (docs/performance.md, "C2's profiles from the whole image").
     */
    static final boolean WARM_UP = Boolean.getBoolean("ray.render.warmUp");
    /** The most warm-up pixels a render takes: 128, and no more than one pixel in 1024 of the image. */
    static final int WARM_UP_PIXELS = 128;
    /**
     * Stack per render thread: room for the scene's MaxDepth whatever -Xss says, and no more. Measured
     * (interpreted, the largest frames): MaxDepth 1000 of mirrors or glass needs under 1 MiB, so
     * 2 MiB plus 4 KiB a level is generous for built-ins and for students' own materials, while an
     * endless recursion in a student's shade() stops at once with its StackOverflowError instead of
     * filling hundreds of MiB per thread first (it took about 1.8 GB per thread with 256 MiB stacks).
     */
    static long stackBytes(int maxDepth) {
        return (2L << 20) + 4096L * Math.max(0, maxDepth);
    }

    private final Scene scene;
    private int threads = Runtime.getRuntime().availableProcessors();
    private ProgressListener listener = ProgressListener.NONE;
    private volatile boolean cancelled;
    private RayStats stats = new RayStats();
    /** The contexts of the render threads running now (empty between passes and once the render is over). */
    private volatile List<TraceContext> running = List.of();
    private RenderSettings settings = new RenderSettings();
    /** A plan derived before the render (the command line's cost check), used when it fits the render. */
    private RenderPlan givenPlan;
    /** The plan of the last render, and the settings it resolved. */
    private RenderPlan plan;
    private RenderSummary summary;
    /** n_s and MaxDepth of the render in progress (its resolved settings). */
    private int ns = 1, maxDepth;
    /** The pixels {@link #render()} renders: the whole image unless {@link #window} set a rectangle. */
    private Area window;
    /** The scene was prepared with the given plan already ({@link SplitRender}): render() leaves it as it is. */
    private boolean prepared;
    /** Read the threads' CPU clocks ({@link #measureCpu}); the render threads' CPU nanoseconds of the render in progress. */
    private boolean measureCpu;
    private boolean warmUp = WARM_UP;
    private final java.util.concurrent.atomic.AtomicLong threadCpuNanos = new java.util.concurrent.atomic.AtomicLong();

    public Renderer(Scene scene) {
        this.scene = scene;
    }

    public Renderer threads(int n) {
        if (n < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + n);
        }
        this.threads = n;
        return this;
    }

    /**
     * Also measure the render's CPU time ({@link RenderSummary#cpuSeconds}) on the threads' own clocks:
     * what the accuracy study judges settings by, since several renders sharing a machine or a JVM
     * (Spark tasks) stretch each other's wall time but not their CPU time. Off by default (reading a
     * thread's clock loads java.lang.management, which a plain render does not need).
     */
    public Renderer measureCpu(boolean on) {
        this.measureCpu = on;
        return this;
    }

    /**
     * Whether a render first renders {@link #warmUpPixels} pixels spread over the image (default:
     * {@link #WARM_UP}, the launcher's choice for a long render). Their rays are not counted, the
     * listener does not hear of them, and nothing of them is kept (the grid render's writes, rendered
     * again to the same value with their tiles; a film's samples traced and dropped), so the image is the
     * same either way.
     */
    Renderer warmUp(boolean on) {
        this.warmUp = on;
        return this;
    }

    public Renderer listener(ProgressListener l) {
        this.listener = l;
        return this;
    }

    /** Asks a running {@link #render()} to stop after the tiles in progress; it then throws. */
    public void cancel() {
        cancelled = true;
    }

    /** Rays cast by the last {@link #render()}, by kind. */
    public RayStats stats() {
        return stats;
    }

    /**
     * Rays cast so far by the render in progress: the finished passes plus the running threads' own
     * counters, read without synchronisation (each thread keeps counting while this reads), so a live
     * figure for a progress display; once {@link #render()} has returned it is {@code stats().total()}.
     */
    public long raysSoFar() {
        long n = stats.total();
        for (TraceContext c : running) {
            n += c.stats.total();
        }
        return n;
    }

    /** How to sample (sampler, n_s, target error, MaxDepth, passes); unset values come from the scene. */
    public Renderer settings(RenderSettings s) {
        this.settings = s;
        return this;
    }

    /**
     * A plan derived beforehand for this scene ({@code RenderPlan.derive}, e.g. for a cost check, or with
     * some exact skips off): the render uses it when it was derived for the settings the render resolves,
     * and derives its own otherwise.
     */
    public Renderer plan(RenderPlan p) {
        this.givenPlan = p;
        return this;
    }

    /** The plan the last {@link #render()} followed (null before the first). */
    public RenderPlan plan() {
        return plan;
    }

    /** The settings the last {@link #render()} resolved from the scene and {@link #settings(RenderSettings)}. */
    public RenderSettings resolvedSettings() {
        return plan == null ? null : plan.settings();
    }

    /**
     * Renders only pixels [x0, x1) x [y0, y1): {@link #render()} then returns an image of that size whose
     * pixels are bit for bit those of the whole image's render (each pixel depends only on the scene and
     * its neighbourhood, never on the tiling). The adaptive sampler's error estimate needs the whole
     * image and is left out ({@link SplitRender} measures it over the assembled pieces).
     */
    Renderer window(int x0, int y0, int x1, int y1) {
        this.window = new Area(x0, y0, x1, y1);
        return this;
    }

    /** Whether a {@link #window} was set. */
    boolean windowed() {
        return window != null;
    }

    /**
     * The scene has been prepared with the {@link #plan(RenderPlan) given plan} already, by
     * {@link SplitRender#prepare}: {@link #render()} does not prepare it again, so many window renders,
     * from any threads, share one BVH.
     */
    Renderer prepared() {
        this.prepared = true;
        return this;
    }

    /** A rectangle of pixels [x0, x1) x [y0, y1). */
    static final class Area {
        final int x0, y0, x1, y1;

        Area(int x0, int y0, int x1, int y1) {
            if (x0 < 0 || y0 < 0 || x1 <= x0 || y1 <= y0) {
                throw new IllegalArgumentException("empty or negative pixel rectangle [" + x0 + ", " + x1 + ") x [" + y0 + ", " + y1 + ")");
            }
            this.x0 = x0;
            this.y0 = y0;
            this.x1 = x1;
            this.y1 = y1;
        }

        boolean same(Area a) {
            return a.x0 == x0 && a.y0 == y0 && a.x1 == x1 && a.y1 == y1;
        }

        int width() {
            return x1 - x0;
        }

        int height() {
            return y1 - y0;
        }

        long pixels() {
            return (long) width() * height();
        }

        /** This rectangle grown by {@code d} pixels on each side, clipped to a w x h image. */
        Area grow(int d, int w, int h) {
            return new Area(Math.max(0, x0 - d), Math.max(0, y0 - d), Math.min(w, x1 + d), Math.min(h, y1 + d));
        }

        boolean contains(Area a) {
            return a.x0 >= x0 && a.y0 >= y0 && a.x1 <= x1 && a.y1 <= y1;
        }
    }

    /** The pixels this render covers (the whole image unless a {@link #window} was set). */
    Area area() {
        Area whole = new Area(0, 0, scene.width, scene.height);
        if (window != null && !whole.contains(window)) {
            throw new IllegalArgumentException("pixel rectangle [" + window.x0 + ", " + window.x1 + ") x [" + window.y0 + ", " + window.y1
                    + ") is not inside the " + scene.width + " x " + scene.height + " image");
        }
        return window != null ? window : whole;
    }

    /** What the last {@link #render()} cost and its estimated error; null before the first render. */
    public RenderSummary summary() {
        return summary;
    }

    /**
     * Renders the whole image (linear colours) with the settings resolved once, here, from the scene's
     * globals and {@link #settings(RenderSettings)}. Throws {@link RenderCancelledException} if
     * {@link #cancel()} was called.
     */
    public Image render() {
        long t0 = System.nanoTime();
        long cpu0 = measureCpu ? ThreadCpu.now() : 0;
        threadCpuNanos.set(0);
        RenderSettings s = settings.resolve(scene);
        String tooLarge = ray.settings.PixelBudget.refusal(scene.width, scene.height, s.sampler());
        if (tooLarge != null) {       // refused before anything is allocated for the image, whatever chose the sampler
            throw new IllegalArgumentException(tooLarge);
        }
        RenderPlan p = givenPlan != null && givenPlan.scene() == scene && givenPlan.settings().equals(s)
                ? givenPlan : RenderPlan.derive(scene, s);
        if (!prepared || p != givenPlan) {
            RenderEngine.prepare(scene, p);
        }
        plan = p;
        ns = s.samples();
        maxDepth = s.maxDepth();
        Sampler sampler = Sampler.create(s.sampler(), ns, s.seed());
        Area area = area();
        stats = new RayStats();
        Image image;
        Film film = null;
        ErrorProbe.Estimate estimate = ErrorProbe.Estimate.NONE;
        if (sampler instanceof GridSampler && !s.progressive()) {
            image = renderGrid(sampler, area);
        } else {
            SampledRender r = new SampledRender(this, scene, sampler, s.targetError(), s.progressive(), area);
            image = r.run();
            film = r.film();
            estimate = r.estimate();
        }
        double spp = film == null ? ns * ns : (double) film.totalSamples() / (double) area.pixels();
        double cpu = measureCpu && ThreadCpu.SUPPORTED ? (ThreadCpu.now() - cpu0 + threadCpuNanos.get()) / 1e9 : Double.NaN;
        summary = new RenderSummary(sampler.name(), ns, (System.nanoTime() - t0) / 1e9, cpu, stats, spp,
                estimate.rmse(), estimate.low(), estimate.high(), estimate.samplesPerPixel(), film);
        return image;
    }

    /** The scene format's grid, every pixel in one go: no film, today's exact arithmetic. */
    private Image renderGrid(Sampler grid, Area area) {
        int w = scene.width, h = scene.height, ox = area.x0, oy = area.y0;
        Image image = new Image(area.width(), area.height());
        // the regular grid's image-plane coordinates, once per sample column and row instead of per sample
        double[] planeA = new double[w * ns], planeB = new double[h * ns];
        for (int x = 0; x < w; x++) {
            for (int i = 0; i < ns; i++) {
                planeA[x * ns + i] = scene.camera.planeX(x + GridSampler.gridValue(ns, i, 0), w);
            }
        }
        for (int y = 0; y < h; y++) {
            for (int j = 0; j < ns; j++) {
                planeB[y * ns + j] = scene.camera.planeY(y + GridSampler.gridValue(ns, j * ns, 1), h);
            }
        }
        final double[] tableA = planeA, tableB = planeB;
        if (scene.camera.standardRays()) {
            // the camera's products a u and b v too, once per sample column and row (Camera.rayTerms)
            final double[] au = new double[3 * w * ns], bv = new double[3 * h * ns];
            scene.camera.rayTerms(planeA, au, planeB, bv);
            if (scene.accelerator().packetsPay()) {
                // a block of pixels' camera rays per packet: about PACKET_RAYS rays, at least a pixel's
                final int side = Math.max(1, (int) Math.sqrt((double) PACKET_RAYS / (ns * ns)));
                runGridTiles(image, new TileWork() {
                    @Override
                    public TileWorker worker(TraceContext ctx) {
                        ctx.packet.reserve(side * side * ns * ns);
                        return new TileWorker() {
                            @Override
                            public void tile(int x0, int y0, int x1, int y1) {
                                packetTile(ctx, x0, y0, x1, y1, au, bv, side, grid, image, ox, oy);
                            }
                        };
                    }
                });
                return image;
            }
            runGridTiles(image, new TileWork() {
                @Override
                public TileWorker worker(TraceContext ctx) {
                    double[] dirs = new double[3 * ns * ns];
                    return new TileWorker() {
                        @Override
                        public void tile(int x0, int y0, int x1, int y1) {
                            gridTile(ctx, x0, y0, x1, y1, au, bv, dirs, grid, image, ox, oy);
                        }
                    };
                }
            });
            return image;
        }
        runGridTiles(image, new TileWork() {
            @Override
            public TileWorker worker(TraceContext ctx) {
                Vector3d c = new Vector3d();
                return new TileWorker() {
                    @Override
                    public void tile(int x0, int y0, int x1, int y1) {
                        for (int y = y0; y < y1; y++) {
                            for (int x = x0; x < x1; x++) {
                                renderGridPixel(ctx, x, y, c, tableA, tableB, grid);
                                image.set(x - ox, y - oy, c.x, c.y, c.z);
                            }
                        }
                    }
                };
            }
        });
        return image;
    }

    /**
     * Pixels [x0, x1) x [y0, y1) of the grid render into {@code image} (whose pixel (0, 0) is image pixel
     * (ox, oy)), for a camera with {@link Camera#standardRays()}: each camera ray is {@link Camera#setRay}'s,
     * bit for bit, (a u + b v - w) normalised from the tables of {@link Camera#rayTerms}, written into the
     * ray here, so a sample costs no call but its trace (about 4% of classic's render CPU, C1 and C2 alike).
     * A pixel's directions are made first, into {@code dirs} (3 n_s^2 doubles, the thread's), then traced.
     * Sums and means as {@link #renderGridPixel}.
     */
    private void gridTile(TraceContext ctx, int x0, int y0, int x1, int y1, double[] au, double[] bv, double[] dirs,
                          Sampler grid, Image image, int ox, int oy) {
        // a pixel a call (gridPixel), not the pixels' loops here: a tile's loops would count thousands of
        // back-edges an invocation, so C2 compiled this method on stack at each of its loops before it
        // compiled it whole (three C2 compilations of one method, docs/performance.md, session 40); a
        // pixel a call is compiled once, whole, after about a thousand pixels
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                gridPixel(ctx, x, y, au, bv, dirs, grid, image, ox, oy);
            }
        }
    }

    /** Pixel (x, y) of {@link #gridTile}. */
    private void gridPixel(TraceContext ctx, int x, int y, double[] au, double[] bv, double[] dirs, Sampler grid,
                           Image image, int ox, int oy) {
        Camera cam = scene.camera;
        double ex = cam.eye.x, ey = cam.eye.y, ez = cam.eye.z, wx = cam.w.x, wy = cam.w.y, wz = cam.w.z;
        int n = ns, count = n * n;
        Vector3d c = ctx.color(0);
        Ray ray = ctx.ray(0);
        Vector3d o = ray.origin, d = ray.direction;
        PixelSample sample = ctx.sample;
        // the pixel's directions first, then its traces: the square roots and divisions of one
        // ray do not wait for the previous ray's, so they overlap instead of adding up
        for (int j = 0, q = 0; j < n; j++) {
            int jb = 3 * (y * n + j);
            double bx = bv[jb], by = bv[jb + 1], bz = bv[jb + 2];
            for (int i = 0, ia = 3 * x * n; i < n; i++, q += 3, ia += 3) {
                double dx = au[ia] + bx - wx, dy = au[ia + 1] + by - wy, dz = au[ia + 2] + bz - wz;
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                dirs[q] = dx / len;
                dirs[q + 1] = dy / len;
                dirs[q + 2] = dz / len;
            }
        }
        double r = 0, g = 0, b = 0;
        for (int s = 0, q = 0; s < count; s++, q += 3) {
            sample.start(grid, x, y, s);
            o.x = ex;
            o.y = ey;
            o.z = ez;
            d.x = dirs[q];
            d.y = dirs[q + 1];
            d.z = dirs[q + 2];
            ray.tMin = 0;
            ray.tMax = Double.POSITIVE_INFINITY;
            ray.depth = 0;
            scene.traceCamera(ray, ctx, c);
            if (Double.isFinite(c.x) && Double.isFinite(c.y) && Double.isFinite(c.z)) {
                r += c.x;
                g += c.y;
                b += c.z;
            } else {
                ctx.stats.invalidSamples++;   // last line of defence: a NaN never reaches a pixel
            }
        }
        image.set(x - ox, y - oy, r / count, g / count, b / count);
    }

    /** Camera rays per packet ({@link #packetTile}): a square of pixels whose samples make about this many. */
    static final int PACKET_RAYS = Integer.getInteger("ray.packetRays", 16);

    /**
     * {@link #gridTile} with the camera rays cast in packets ({@link Scene#castCameras}), for an
     * accelerator that says they pay: the tile in squares of {@code side} x {@code side} pixels, each
     * square's rays (pixel by pixel, each pixel's samples in order; the same rays as {@link #gridTile}'s,
     * bit for bit) cast together, then shaded and summed pixel by pixel, sample by sample, as there. A
     * sample's colour depends on nothing but its pixel and number, so the order of the squares does not
     * change the image.
     */
    private void packetTile(TraceContext ctx, int x0, int y0, int x1, int y1, double[] au, double[] bv, int side,
                            Sampler grid, Image image, int ox, int oy) {
        // a square a call, for the reason gridTile gives (five on-stack C2 compilations of this method on
        // mesh1m before the whole one, docs/performance.md, session 40)
        for (int by = y0; by < y1; by += side) {
            int ye = Math.min(by + side, y1);
            for (int bx = x0; bx < x1; bx += side) {
                packetSquare(ctx, bx, by, Math.min(bx + side, x1), ye, au, bv, grid, image, ox, oy);
            }
        }
    }

    /**
     * Pixels [bx, xe) x [by, ye) of {@link #packetTile}: their camera rays as one packet. One loop over the
     * square's pixels for the rays and one for the shading, each pixel's samples in a call of its own
     * ({@link #packetRays}, {@link #packetShade}): a square's nested loops counted about 90 back-edges a call
     * at n_s 1, enough for C2 to compile this method on stack before whole (gridTile's reason); now 2 a
     * pixel.
     */
    private void packetSquare(TraceContext ctx, int bx, int by, int xe, int ye, double[] au, double[] bv,
                              Sampler grid, Image image, int ox, int oy) {
        RayPacket p = ctx.packet;
        int sw = xe - bx, pixels = sw * (ye - by), count = ns * ns;
        for (int i = 0; i < pixels; i++) {
            packetRays(p.rays, i * count, bx + i % sw, by + i / sw, au, bv);
        }
        p.size = pixels * count;
        scene.castCameras(p, ctx);
        for (int i = 0; i < pixels; i++) {
            packetShade(ctx, p, i * count, bx + i % sw, by + i / sw, grid, image, ox, oy);
        }
    }

    /** Pixel (x, y)'s camera rays of {@link #packetSquare} into {@code rays[k..]}, sample by sample as {@link #gridPixel}'s. */
    private void packetRays(Ray[] rays, int k, int x, int y, double[] au, double[] bv) {
        Camera cam = scene.camera;
        double ex = cam.eye.x, ey = cam.eye.y, ez = cam.eye.z, wx = cam.w.x, wy = cam.w.y, wz = cam.w.z;
        int n = ns;
        for (int j = 0; j < n; j++) {
            int jb = 3 * (y * n + j);
            double bx3 = bv[jb], by3 = bv[jb + 1], bz3 = bv[jb + 2];
            for (int i = 0, ia = 3 * x * n; i < n; i++, ia += 3) {
                double dx = au[ia] + bx3 - wx, dy = au[ia + 1] + by3 - wy, dz = au[ia + 2] + bz3 - wz;
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                Ray ray = rays[k++];
                Vector3d o = ray.origin, d = ray.direction;
                o.x = ex;
                o.y = ey;
                o.z = ez;
                d.x = dx / len;
                d.y = dy / len;
                d.z = dz / len;
                ray.tMin = 0;
                ray.tMax = Double.POSITIVE_INFINITY;
                ray.depth = 0;
            }
        }
    }

    /** Pixel (x, y) of {@link #packetSquare}, its samples the packet's rays k.., shaded, summed and written. */
    private void packetShade(TraceContext ctx, RayPacket p, int k, int x, int y, Sampler grid, Image image, int ox, int oy) {
        int count = ns * ns;
        Vector3d c = ctx.color(0);
        PixelSample sample = ctx.sample;
        double r = 0, g = 0, b = 0;
        for (int s = 0; s < count; s++, k++) {
            sample.start(grid, x, y, s);
            scene.shadeCamera(p, k, ctx, c);
            if (Double.isFinite(c.x) && Double.isFinite(c.y) && Double.isFinite(c.z)) {
                r += c.x;
                g += c.y;
                b += c.z;
            } else {
                ctx.stats.invalidSamples++;   // last line of defence: a NaN never reaches a pixel
            }
        }
        image.set(x - ox, y - oy, r / count, g / count, b / count);
    }

    /** One render thread's work on tiles: made once per thread with that thread's context. */
    interface TileWork {
        TileWorker worker(TraceContext ctx);
    }

    interface TileWorker {
        /** Renders pixels [x0, x1) x [y0, y1) and writes them into the image. */
        void tile(int x0, int y0, int x1, int y1);
    }

    /**
     * Hands the image's tiles, spread over the image ({@link #spreadStride}), to the render threads, each with its own context; reports
     * each finished tile of {@code image} to the listener; adds the threads' ray counts to {@link #stats()}.
     * Rethrows the first failure; throws {@link RenderCancelledException} when cancelled.
     */
    void runTiles(Image image, TileWork work) {
        runTiles(image, work, true, area(), null);
    }

    /**
     * {@link #runTiles(Image, TileWork)} for the grid render's work, whose workers write each pixel's
     * final value (rendering a pixel twice writes it twice, the same), so it is its own warm-up.
     */
    private void runGridTiles(Image image, TileWork work) {
        runTiles(image, work, true, area(), work);
    }

    /** Warm-up pixels for a w x h area: {@link #WARM_UP_PIXELS}, at most one in 1024 of its pixels. */
    static int warmUpPixels(int w, int h) {
        return (int) Math.min(WARM_UP_PIXELS, (long) w * h / 1024);
    }

    /**
     * Warm-up pixel {@code k} of a w x h area, as {@code y * w + x}: the R2 sequence (Roberts 2018, the
     * additive recurrence on the plastic number's powers), whose first n points fall about evenly over
     * the unit square for every n.
     */
    static int warmUpPixel(int k, int w, int h) {
        double fx = 0.5 + k * 0.7548776662466927, fy = 0.5 + k * 0.5698402909980532;
        int x = (int) ((fx - Math.floor(fx)) * w), y = (int) ((fy - Math.floor(fy)) * h);
        return Math.min(y, h - 1) * w + Math.min(x, w - 1);
    }

    void runTiles(Image image, TileWork work, boolean report, Area area) {
        runTiles(image, work, report, area, null);
    }

    /**
     * {@link #runTiles(Image, TileWork)} over the pixels of {@code area} (tile corners are image
     * coordinates), telling the listener about finished tiles only when {@code report}. First, when
     * {@link #warmUp(boolean)} is on and {@code warmUpWork} is given, the area's {@link #warmUpPixels}
     * pixels of {@link #warmUpPixel}, one at a time, each by a worker of {@code warmUpWork} on a context
     * of the thread's own whose rays are not counted: a work that leaves nothing behind, or writes a
     * pixel's final value (its tile writes the same again).
     */
    void runTiles(Image image, TileWork work, boolean report, Area area, TileWork warmUpWork) {
        int w = area.width(), h = area.height(), ax = area.x0, ay = area.y0;
        int warm = warmUp && warmUpWork != null ? warmUpPixels(w, h) : 0;
        final int size = tileSize(w, h, threads);
        int tilesX = (w + size - 1) / size, tilesY = (h + size - 1) / size, total = tilesX * tilesY;
        final long stride = spreadStride(total);
        AtomicInteger next = new AtomicInteger(), done = new AtomicInteger(), warmed = new AtomicInteger();
        int n = Math.max(1, Math.min(threads, total));
        List<Thread> workers = new ArrayList<>();
        List<TraceContext> contexts = new ArrayList<>();
        Throwable[] failure = new Throwable[1];
        for (int t = 0; t < n; t++) {
            // an anonymous class, not a lambda: linking a lambda costs milliseconds at start-up
            Runnable run = new Runnable() {
                @Override
                public void run() {
                    // Made by the thread that uses it, so its scratch objects (rays, records, counters,
                    // the accelerator's query) sit in this thread's allocation buffer. Made by one thread
                    // for all, two threads' hot objects shared cache lines, and every ray's writes
                    // bounced those lines between the cores (classic: 0.74 CPU s on two threads against 0.60 on one).
                    try {
                        TraceContext ctx = new TraceContext(maxDepth);
                        synchronized (contexts) {
                            contexts.add(ctx);
                            running = List.copyOf(contexts);   // its rays are seen as they are cast
                        }
                        if (warm > 0) {
                            TraceContext uncounted = new TraceContext(maxDepth);
                            TraceContext.bind(uncounted);
                            TileWorker first = warmUpWork.worker(uncounted);
                            for (int k; !cancelled && (k = warmed.getAndIncrement()) < warm; ) {
                                int p = warmUpPixel(k, w, h), x = ax + p % w, y = ay + p / w;
                                first.tile(x, y, x + 1, y + 1);
                            }
                        }
                        TraceContext.bind(ctx);
                        TileWorker worker = work.worker(ctx);
                        for (int k; !cancelled && (k = next.getAndIncrement()) < total; ) {
                            int tile = (int) (k * stride % total);
                            int x0 = ax + (tile % tilesX) * size, y0 = ay + (tile / tilesX) * size;
                            int x1 = Math.min(ax + w, x0 + size), y1 = Math.min(ay + h, y0 + size);
                            worker.tile(x0, y0, x1, y1);
                            if (report) {
                                listener.tileDone(image, x0, y0, x1, y1, done.incrementAndGet(), total);
                            }
                        }
                    } catch (Throwable e) {
                        synchronized (failure) {
                            if (failure[0] == null) {
                                failure[0] = e;
                            }
                        }
                        cancelled = true;
                    } finally {
                        TraceContext.bind(null);
                        if (measureCpu) {
                            threadCpuNanos.addAndGet(ThreadCpu.now());   // a new thread per pass: its whole clock is this pass
                        }
                    }
                }
            };
            Thread th = new Thread(null, run, "render-" + t, stackBytes(maxDepth));
            th.setDaemon(true);
            workers.add(th);
            th.start();
        }
        for (Thread th : workers) {
            try {
                th.join();
            } catch (InterruptedException e) {
                cancelled = true;
                Thread.currentThread().interrupt();
            }
        }
        running = List.of();
        for (TraceContext ctx : contexts) {
            stats.add(ctx.stats);
        }
        if (failure[0] != null) {
            // rethrown as itself, even a checked exception a user's class threw sneakily: wrapping it
            // would hide its class and call its (user-written) getMessage() here
            throw Renderer.<RuntimeException>sneaky(failure[0]);
        }
        if (cancelled) {
            throw new RenderCancelledException();
        }
    }

    /**
     * The tile side for a w x h image on {@code threads} threads: {@value #TILE}, halved (down to single
     * pixels) while the image would have fewer than four tiles per thread, so a small but costly image
     * still keeps every core busy to the end. Every pixel depends only on the scene, so the tiling
     * never changes the image.
     */
    public static int tileSize(int w, int h, int threads) {
        int size = TILE;
        while (size > 1 && (long) ((w + size - 1) / size) * ((h + size - 1) / size) < 4L * threads) {
            size /= 2;
        }
        return size;
    }

    /**
     * Tiles are handed out in the order k * stride mod total (stride about 0.618 total, coprime with
     * it): each stretch of the order is spread over the whole image, so the share of pixels done is an
     * honest estimate of the share of work done (in scan order an empty sky first makes it race ahead).
     */
    static long spreadStride(int total) {
        if (total <= 2) {
            return 1;
        }
        long s = Math.max(1, Math.round(total * 0.6180339887498949));
        while (gcd(s, total) != 1) {
            s++;
        }
        return s;
    }

    private static long gcd(long a, long b) {
        while (b != 0) {
            long t = a % b;
            a = b;
            b = t;
        }
        return a;
    }

    /** Runs {@code r} (passes of {@link #runTiles}) without adding its rays to {@link #stats()}. */
    void uncounted(Runnable r) {
        RayStats kept = stats;
        stats = new RayStats();
        try {
            r.run();
        } finally {
            stats = kept;
        }
    }

    /** Renders probes ({@link SplitRender#probe}) without a {@link #render()}: the MaxDepth its contexts follow. */
    Renderer maxDepth(int d) {
        this.maxDepth = d;
        return this;
    }

    /** The rays counted so far by this render's passes (added to by each {@link #runTiles}). */
    RayStats counted() {
        return stats;
    }

    ProgressListener listener() {
        return listener;
    }

    @SuppressWarnings("unchecked")
    private static <T extends Throwable> T sneaky(Throwable t) throws T {
        throw (T) t;
    }

    /**
     * The mean of pixel (x, y)'s n_s x n_s grid samples with the scene's own settings, written into
     * {@code out} (the framework's {@code Scene.renderPixel}; the scene is prepared already).
     */
    public void renderPixel(TraceContext ctx, int x, int y, Vector3d out) {
        ns = RenderSettings.of(scene).samples();
        int w = scene.width, h = scene.height;
        double[] planeA = new double[(x + 1) * ns], planeB = new double[(y + 1) * ns];
        for (int i = 0; i < ns; i++) {
            planeA[x * ns + i] = scene.camera.planeX(x + GridSampler.gridValue(ns, i, 0), w);
            planeB[y * ns + i] = scene.camera.planeY(y + GridSampler.gridValue(ns, i * ns, 1), h);
        }
        renderGridPixel(ctx, x, y, out, planeA, planeB, new GridSampler(ns));
    }

    /** {@link #renderPixel} for the regular grid, with the image-plane coordinates from the tables. */
    private void renderGridPixel(TraceContext ctx, int x, int y, Vector3d out, double[] planeA, double[] planeB, Sampler grid) {
        int count = ns * ns;
        double r = 0, g = 0, b = 0;
        Vector3d c = ctx.color(0);
        Ray ray = ctx.ray(0);
        for (int j = 0, s = 0; j < ns; j++) {
            double pb = planeB[y * ns + j];
            for (int i = 0; i < ns; i++, s++) {
                ctx.sample.start(grid, x, y, s);
                scene.camera.setRay(ray, planeA[x * ns + i], pb);
                scene.traceCamera(ray, ctx, c);
                if (Double.isFinite(c.x) && Double.isFinite(c.y) && Double.isFinite(c.z)) {
                    r += c.x;
                    g += c.y;
                    b += c.z;
                } else {
                    ctx.stats.invalidSamples++;   // last line of defence: a NaN never reaches a pixel
                }
            }
        }
        out.set(r / count, g / count, b / count);
    }

    /** The current thread's CPU clock in nanoseconds (0 where the JVM has none); loaded only when a render measures CPU. */
    private static final class ThreadCpu {
        private static final java.lang.management.ThreadMXBean MX = java.lang.management.ManagementFactory.getThreadMXBean();
        static final boolean SUPPORTED = MX.isCurrentThreadCpuTimeSupported() && MX.isThreadCpuTimeEnabled();

        static long now() {
            return SUPPORTED ? Math.max(0, MX.getCurrentThreadCpuTime()) : 0;
        }
    }
}
