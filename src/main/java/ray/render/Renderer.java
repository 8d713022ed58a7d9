package ray.render;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import javax.vecmath.Vector3d;
import ray.Ray;
import ray.RayStats;
import ray.Scene;
import ray.TraceContext;

/**
 * Renders a scene on all cores. The image is cut into {@value #TILE} x {@value #TILE} tiles handed out
 * in scan order to a fixed set of threads; each thread owns its {@link TraceContext} (scratch objects
 * and ray counters) and writes only its tiles' pixels. Every pixel depends only on the scene, so the
 * image is bit-identical for any thread count.
 */
public final class Renderer {

    public static final int TILE = 16;
    /** Stack per render thread: room for MaxDepth up to the parser's limit whatever -Xss says. */
    private static final long STACK_BYTES = 256L << 20;

    private final Scene scene;
    private int threads = Runtime.getRuntime().availableProcessors();
    private SamplePattern pattern = SamplePattern.GRID;
    private ProgressListener listener = ProgressListener.NONE;
    private volatile boolean cancelled;
    private final RayStats stats = new RayStats();

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

    public Renderer pattern(SamplePattern p) {
        this.pattern = p;
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

    /** Renders the whole image. Throws {@link RenderCancelledException} if {@link #cancel()} was called. */
    public Image render() {
        scene.prepare();
        int w = scene.width, h = scene.height;
        Image image = new Image(w, h);
        int tilesX = (w + TILE - 1) / TILE, tilesY = (h + TILE - 1) / TILE, total = tilesX * tilesY;
        AtomicInteger next = new AtomicInteger(), done = new AtomicInteger();
        int n = Math.max(1, Math.min(threads, total));
        // the regular grid's image-plane coordinates, once per sample column and row instead of per sample
        int ns = Math.max(1, scene.samplesPerPixel);
        double[] planeA = null, planeB = null;
        if (pattern == SamplePattern.GRID) {
            double[] off = new double[2 * ns * ns];
            SamplePattern.GRID.offsets(0, 0, ns, off);
            planeA = new double[w * ns];
            planeB = new double[h * ns];
            for (int x = 0; x < w; x++) {
                for (int i = 0; i < ns; i++) {
                    planeA[x * ns + i] = scene.camera.planeX(x + off[2 * i], w);
                }
            }
            for (int y = 0; y < h; y++) {
                for (int j = 0; j < ns; j++) {
                    planeB[y * ns + j] = scene.camera.planeY(y + off[2 * j * ns + 1], h);
                }
            }
        }
        final double[] tableA = planeA, tableB = planeB;
        List<Thread> workers = new ArrayList<>();
        List<TraceContext> contexts = new ArrayList<>();
        Throwable[] failure = new Throwable[1];
        for (int t = 0; t < n; t++) {
            TraceContext ctx = new TraceContext(scene.maxDepth);
            contexts.add(ctx);
            // an anonymous class, not a lambda: linking a lambda costs milliseconds at start-up
            Runnable work = new Runnable() {
                @Override
                public void run() {
                    TraceContext.bind(ctx);
                    Vector3d c = new Vector3d();
                    double[] offsets = new double[2 * scene.samplesPerPixel * scene.samplesPerPixel];
                    try {
                        for (int tile; !cancelled && (tile = next.getAndIncrement()) < total; ) {
                            int x0 = (tile % tilesX) * TILE, y0 = (tile / tilesX) * TILE;
                            int x1 = Math.min(w, x0 + TILE), y1 = Math.min(h, y0 + TILE);
                            for (int y = y0; y < y1; y++) {
                                for (int x = x0; x < x1; x++) {
                                    if (tableA != null) {
                                        renderGridPixel(ctx, x, y, c, tableA, tableB);
                                    } else {
                                        renderPixel(ctx, x, y, c, offsets);
                                    }
                                    image.set(x, y, c.x, c.y, c.z);
                                }
                            }
                            listener.tileDone(image, x0, y0, x1, y1, done.incrementAndGet(), total);
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
                    }
                }
            };
            Thread th = new Thread(null, work, "render-" + t, STACK_BYTES);
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
        return image;
    }

    @SuppressWarnings("unchecked")
    private static <T extends Throwable> T sneaky(Throwable t) throws T {
        throw (T) t;
    }

    /** The mean of pixel (x, y)'s n_s x n_s samples, written into {@code out}. */
    public void renderPixel(TraceContext ctx, int x, int y, Vector3d out) {
        int ns = scene.samplesPerPixel;
        renderPixel(ctx, x, y, out, new double[2 * ns * ns]);
    }

    /** {@link #renderPixel} for the regular grid, with the image-plane coordinates from the tables. */
    private void renderGridPixel(TraceContext ctx, int x, int y, Vector3d out, double[] planeA, double[] planeB) {
        int ns = Math.max(1, scene.samplesPerPixel), count = ns * ns;
        double r = 0, g = 0, b = 0;
        Vector3d c = ctx.color(0);
        Ray ray = ctx.ray(0);
        for (int j = 0, s = 0; j < ns; j++) {
            double pb = planeB[y * ns + j];
            for (int i = 0; i < ns; i++, s++) {
                scene.camera.setRay(ray, planeA[x * ns + i], pb);
                ctx.stats.camera++;
                scene.traceInto(ray, ctx, c);
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

    private void renderPixel(TraceContext ctx, int x, int y, Vector3d out, double[] offsets) {
        int ns = Math.max(1, scene.samplesPerPixel), count = ns * ns;
        pattern.offsets(x, y, ns, offsets);
        double r = 0, g = 0, b = 0;
        Vector3d c = ctx.color(0);
        for (int s = 0; s < count; s++) {
            scene.camera.setRayThrough(ctx.ray(0), x + offsets[2 * s], y + offsets[2 * s + 1], scene.width, scene.height);
            ctx.stats.camera++;
            scene.traceInto(ctx.ray(0), ctx, c);
            if (Double.isFinite(c.x) && Double.isFinite(c.y) && Double.isFinite(c.z)) {
                r += c.x;
                g += c.y;
                b += c.z;
            } else {
                ctx.stats.invalidSamples++;   // last line of defence: a NaN never reaches a pixel
            }
        }
        out.set(r / count, g / count, b / count);
    }
}
