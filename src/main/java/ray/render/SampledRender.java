package ray.render;

import javax.vecmath.Vector3d;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;

/**
 * A render through a {@link Film} with any {@link Sampler}: every pixel takes its samples in index
 * order (all of them, or in passes of 1, 4, 16, ... samples per pixel when progressive), or, for the
 * {@link AdaptiveSampler}, two passes: a first batch for every pixel (kept), then each pixel on its own,
 * taking more only while its estimated standard error is at or above the target, and at least a few
 * more near a possible edge ({@link #nudgedPixels}); then the {@link ErrorProbe} measures the result.
 * The film sums each pixel's samples in index order, so the pixels do not depend on how the work is
 * split into passes or threads.
 */
final class SampledRender {

    /** Neighbouring first-batch means further apart than this (8-bit steps) mark a possible edge. */
    static final double EDGE_STEPS = 8;

    private final Renderer renderer;
    private final Scene scene;
    private final Sampler sampler;
    private final double target;
    private final boolean progressive;
    /** The pixels rendered (the whole image, or the renderer's window). */
    private final Renderer.Area area;
    /**
     * The pixels the film and image hold: the area, and for the adaptive sampler a ring of one pixel
     * around it (clipped to the image), whose first batch the area's edge pixels judge edges by.
     */
    private final Renderer.Area frame;
    private final Film film;
    private final Image image;
    private ErrorProbe.Estimate estimate = ErrorProbe.Estimate.NONE;

    SampledRender(Renderer renderer, Scene scene, Sampler sampler, double targetError, boolean progressive, Renderer.Area area) {
        this.renderer = renderer;
        this.scene = scene;
        this.sampler = sampler;
        this.target = targetError;
        this.progressive = progressive;
        this.area = area;
        this.frame = sampler instanceof AdaptiveSampler ? area.grow(1, scene.width, scene.height) : area;
        this.film = new Film(frame.width(), frame.height());
        this.image = new Image(frame.width(), frame.height());
    }

    /** The film of the area's pixels (the whole image's own, or a copy cut out of the frame). */
    Film film() {
        return frame.same(area) ? film : film.crop(area.x0 - frame.x0, area.y0 - frame.y0, area.width(), area.height());
    }


    /** The adaptive render's measured estimate of its RMSE in 8-bit steps ({@code NONE} for the other samplers). */
    ErrorProbe.Estimate estimate() {
        return estimate;
    }

    Image run() {
        int all = sampler.samplesPerPixel();
        if (sampler instanceof AdaptiveSampler a) {
            // first every pixel's first batch (kept, to be reused), then each pixel refined on its own
            int b0 = a.firstBatch();
            double[] first = new double[3 * b0 * film.width * film.height];
            FirstBatch firstBatch = new FirstBatch(a, first);
            pass(firstBatch, area, 0, 2);
            ring(firstBatch);
            pass(new Adaptive(a, first, nudgedPixels()), area, 1, 2);
            if (!renderer.windowed()) {   // a window's estimate is measured over the assembled image (SplitRender)
                estimate = new ErrorProbe(scene, film, image).measure(renderer);
                return image;
            }
            return cropped();
        }
        int[] bounds = progressive ? passBounds(all) : new int[] {0, all};
        for (int p = 0; p + 1 < bounds.length; p++) {
            pass(new Samples(bounds[p], bounds[p + 1]), area, p, bounds.length - 1);
        }
        return image;
    }

    /**
     * The first batch of the frame's ring around the area (a window's render only): what the area's
     * edge pixels compare themselves with. Its rays are not counted: the render that owns those pixels
     * counts them.
     */
    private void ring(Renderer.TileWork firstBatch) {
        if (frame.same(area)) {
            return;
        }
        Renderer.Area[] sides = {
            area.y0 > frame.y0 ? new Renderer.Area(frame.x0, frame.y0, frame.x1, area.y0) : null,
            area.y1 < frame.y1 ? new Renderer.Area(frame.x0, area.y1, frame.x1, frame.y1) : null,
            area.x0 > frame.x0 ? new Renderer.Area(frame.x0, area.y0, area.x0, area.y1) : null,
            area.x1 < frame.x1 ? new Renderer.Area(area.x1, area.y0, frame.x1, area.y1) : null};
        renderer.uncounted(() -> {
            for (Renderer.Area side : sides) {
                if (side != null) {
                    renderer.runTiles(image, firstBatch, false, side);
                }
            }
        });
    }

    /** The area's pixels out of the frame's image. */
    private Image cropped() {
        Image out = new Image(area.width(), area.height());
        for (int y = 0; y < area.height(); y++) {
            System.arraycopy(image.rgb, 3 * ((y + area.y0 - frame.y0) * image.width + area.x0 - frame.x0), out.rgb, 3 * y * out.width, 3 * out.width);
        }
        return out;
    }

    /**
     * Pixels whose first batch gives no sign of an edge nearby, so that they may stop there: a pixel is
     * nudged (returns true) when its own samples or a neighbour's disagree (estimated standard error not
     * below the target), or when its mean differs from a neighbour's by more than {@link #EDGE_STEPS}
     * 8-bit steps in a channel (an edge runs between them that the first samples of either may have
     * missed: a feature smaller than the gaps between four samples shows only this way).
     */
    private boolean[] nudgedPixels() {
        int w = film.width, h = film.height;
        double[] busy = new double[w * h];
        boolean[] nudged = new boolean[w * h];
        double limit = target * target, edge = EDGE_STEPS / 255.0;
        double[] mean = new double[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = y * w + x, n = film.count(x, y);
                for (int c = 0; c < 3; c++) {
                    mean[3 * p + c] = Film.clamp(film.sum(x, y, c) / n);
                }
                busy[p] = film.varianceOfMean(x, y) < limit ? 0 : 1;
            }
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = y * w + x;
                // the right and the three lower neighbours (each pair once): both pixels of a differing pair
                for (int d = 0; d < 4; d++) {
                    int qx = x + (d == 0 || d == 2 ? 1 : d == 3 ? -1 : 0), qy = y + (d == 0 ? 0 : 1);
                    if (qx >= 0 && qx < w && qy < h && differ(mean, p, qy * w + qx, edge)) {
                        nudged[p] = true;
                        nudged[qy * w + qx] = true;
                    }
                }
            }
        }
        double[] near = neighbourhoodMax(busy, w, h);
        for (int p = 0; p < w * h; p++) {
            nudged[p] |= near[p] > 0;
        }
        return nudged;
    }

    /** The largest of {@code v} over each pixel's 3 x 3 neighbourhood (v row by row, w x h). */
    static double[] neighbourhoodMax(double[] v, int w, int h) {
        double[] out = new double[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double m = v[y * w + x];
                for (int j = Math.max(0, y - 1); j <= Math.min(h - 1, y + 1); j++) {
                    for (int i = Math.max(0, x - 1); i <= Math.min(w - 1, x + 1); i++) {
                        m = Math.max(m, v[j * w + i]);
                    }
                }
                out[y * w + x] = m;
            }
        }
        return out;
    }

    private static boolean differ(double[] mean, int p, int q, double edge) {
        return Math.abs(mean[3 * p] - mean[3 * q]) > edge || Math.abs(mean[3 * p + 1] - mean[3 * q + 1]) > edge
                || Math.abs(mean[3 * p + 2] - mean[3 * q + 2]) > edge;
    }

    /** Cumulative samples per pixel at the end of each progressive pass: 0, 1, 4, 16, ..., all. */
    static int[] passBounds(int all) {
        int count = 1;
        for (int k = 1; k < all; k *= 4) {
            count++;
        }
        int[] b = new int[count + 1];
        for (int p = 1, k = 1; p <= count; p++, k *= 4) {
            b[p] = Math.min(k, all);
        }
        return b;
    }

    private void pass(Renderer.TileWork work, Renderer.Area tiles, int pass, int passes) {
        // the first pass warms the JIT up on pixels spread over the image (a long render: Renderer.WARM_UP)
        renderer.runTiles(image, work, true, tiles, pass == 0 ? new Dropped(Math.min(sampler.samplesPerPixel(), 16)) : null);
        if (progressive) {
            renderer.listener().passDone(image, pass, passes);
        }
    }

    /**
     * Traces sample {@code index} of pixel (x, y) into {@code c}; a NaN or infinite result is counted
     * and replaced by black, so it never reaches a pixel.
     */
    void trace(TraceContext ctx, int x, int y, int index, Vector3d c) {
        trace(scene, ctx, sampler, x, y, index, c);
    }

    /** {@link #trace(TraceContext, int, int, int, Vector3d)} in {@code scene} with another sampler. */
    static void trace(Scene scene, TraceContext ctx, Sampler sampler, int x, int y, int index, Vector3d c) {
        ctx.sample.start(sampler, x, y, index);
        double dx = sampler.get(x, y, index, 0), dy = sampler.get(x, y, index, 1);
        Ray ray = ctx.ray(0);
        scene.camera.setRayThrough(ray, x + dx, y + dy, scene.width, scene.height);
        scene.traceCamera(ray, ctx, c);
        if (!(Double.isFinite(c.x) && Double.isFinite(c.y) && Double.isFinite(c.z))) {
            ctx.stats.invalidSamples++;
            c.set(0, 0, 0);
        }
    }

    /**
     * Samples [0, n) of each pixel traced and dropped: no film, no image. The warm-up of a film render
     * ({@link Renderer#runTiles(Image, Renderer.TileWork, boolean, Renderer.Area, Renderer.TileWork)}):
     * the tracing is the render's own, so the JIT profiles what the render will run.
     */
    private final class Dropped implements Renderer.TileWork {
        private final int n;

        Dropped(int n) {
            this.n = n;
        }

        @Override
        public Renderer.TileWorker worker(TraceContext ctx) {
            Vector3d c = new Vector3d();
            return new Renderer.TileWorker() {
                @Override
                public void tile(int x0, int y0, int x1, int y1) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) {
                            for (int s = 0; s < n; s++) {
                                trace(ctx, x, y, s, c);
                            }
                        }
                    }
                }
            };
        }
    }

    /** A render thread's work on a film pass: each pixel of a tile, then the tile's means into the image. */
    private abstract class FilmWorker implements Renderer.TileWorker {
        final TraceContext ctx;
        final Vector3d c = new Vector3d();

        FilmWorker(TraceContext ctx) {
            this.ctx = ctx;
        }

        abstract void pixel(int x, int y);

        @Override
        public void tile(int x0, int y0, int x1, int y1) {
            for (int y = y0; y < y1; y++) {
                for (int x = x0; x < x1; x++) {
                    pixel(x, y);
                }
            }
            film.writeTo(image, x0 - frame.x0, y0 - frame.y0, x1 - frame.x0, y1 - frame.y0);
        }
    }

    /** Samples [from, to) of every pixel, added to the film in index order. */
    private final class Samples implements Renderer.TileWork {
        private final int from, to;

        Samples(int from, int to) {
            this.from = from;
            this.to = to;
        }

        @Override
        public Renderer.TileWorker worker(TraceContext ctx) {
            return new FilmWorker(ctx) {
                @Override
                void pixel(int x, int y) {
                    for (int s = from; s < to; s++) {
                        trace(ctx, x, y, s, c);
                        film.add(x - frame.x0, y - frame.y0, c.x, c.y, c.z);
                    }
                }
            };
        }
    }

    /** The adaptive sampler's first batch for every pixel, added to the film and kept in {@code first}. */
    private final class FirstBatch implements Renderer.TileWork {
        private final AdaptiveSampler a;
        private final double[] first;

        FirstBatch(AdaptiveSampler a, double[] first) {
            this.a = a;
            this.first = first;
        }

        @Override
        public Renderer.TileWorker worker(TraceContext ctx) {
            int b0 = a.firstBatch();
            return new FilmWorker(ctx) {
                @Override
                void pixel(int x, int y) {
                    int fx = x - frame.x0, fy = y - frame.y0, base = 3 * b0 * (fy * film.width + fx);
                    for (int k = 0; k < b0; k++) {
                        trace(ctx, x, y, a.order(k), c);
                        first[base + 3 * k] = c.x;
                        first[base + 3 * k + 1] = c.y;
                        first[base + 3 * k + 2] = c.z;
                        film.add(fx, fy, c.x, c.y, c.z);
                    }
                }
            };
        }
    }

    /** Each pixel finished in one go by the adaptive rule, starting from its kept first batch. */
    private final class Adaptive implements Renderer.TileWork {
        private final AdaptiveSampler a;
        private final double[] first;
        private final boolean[] nudged;

        Adaptive(AdaptiveSampler a, double[] first, boolean[] nudged) {
            this.a = a;
            this.first = first;
            this.nudged = nudged;
        }

        @Override
        public Renderer.TileWorker worker(TraceContext ctx) {
            AdaptivePixel adaptive = new AdaptivePixel(a, target, SampledRender.this, ctx);
            return new FilmWorker(ctx) {
                @Override
                void pixel(int x, int y) {
                    int fx = x - frame.x0, fy = y - frame.y0;
                    adaptive.render(x, y, film, fx, fy, first, nudged[fy * film.width + fx]);
                }
            };
        }
    }
}
