package ray.render;

import javax.vecmath.Vector3d;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;

/**
 * A render through a {@link Film} with any {@link Sampler}: every pixel takes its samples in index
 * order (all of them, or in passes of 1, 4, 16, ... samples per pixel when progressive), or, for the
 * {@link AdaptiveSampler}, a first batch and then more only while the pixel's estimated standard error
 * is at or above the target. The film sums each pixel's samples in index order, so the pixels do not
 * depend on how the work is split into passes or threads.
 */
final class SampledRender {

    private final Renderer renderer;
    private final Scene scene;
    private final Sampler sampler;
    private final double target;
    private final boolean progressive;
    private final Film film;
    private final Image image;

    SampledRender(Renderer renderer, Scene scene, Sampler sampler, double targetError, boolean progressive) {
        this.renderer = renderer;
        this.scene = scene;
        this.sampler = sampler;
        this.target = targetError;
        this.progressive = progressive;
        this.film = new Film(scene.width, scene.height);
        this.image = new Image(scene.width, scene.height);
    }

    Film film() {
        return film;
    }

    Image run() {
        int all = sampler.samplesPerPixel();
        if (sampler instanceof AdaptiveSampler a) {
            int passes = progressive ? 2 : 1;
            if (progressive) {   // a first look: each pixel's first sample, reused by the adaptive pass
                pass(new Samples(a.order(0), a.order(0) + 1), 0, passes);
            }
            pass(new Adaptive(a), passes - 1, passes);
            return image;
        }
        int[] bounds = progressive ? passBounds(all) : new int[] {0, all};
        for (int p = 0; p + 1 < bounds.length; p++) {
            pass(new Samples(bounds[p], bounds[p + 1]), p, bounds.length - 1);
        }
        return image;
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

    private void pass(Renderer.TileWork work, int pass, int passes) {
        renderer.runTiles(image, work);
        if (progressive) {
            renderer.listener().passDone(image, pass, passes);
        }
    }

    /**
     * Traces sample {@code index} of pixel (x, y) into {@code c}; a NaN or infinite result is counted
     * and replaced by black, so it never reaches a pixel.
     */
    void trace(TraceContext ctx, int x, int y, int index, Vector3d c) {
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

    /** Samples [from, to) of every pixel, added to the film in index order. */
    private final class Samples implements Renderer.TileWork {
        private final int from, to;

        Samples(int from, int to) {
            this.from = from;
            this.to = to;
        }

        @Override
        public Renderer.TileWorker worker(TraceContext ctx) {
            Vector3d c = new Vector3d();
            return new Renderer.TileWorker() {
                @Override
                public void tile(int x0, int y0, int x1, int y1) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) {
                            for (int s = from; s < to; s++) {
                                trace(ctx, x, y, s, c);
                                film.add(x, y, c.x, c.y, c.z);
                            }
                        }
                    }
                    film.writeTo(image, x0, y0, x1, y1);
                }
            };
        }
    }

    /** Each pixel finished in one go by the adaptive rule; a sample taken by a first pass is reused. */
    private final class Adaptive implements Renderer.TileWork {
        private final AdaptiveSampler a;

        Adaptive(AdaptiveSampler a) {
            this.a = a;
        }

        @Override
        public Renderer.TileWorker worker(TraceContext ctx) {
            AdaptivePixel pixel = new AdaptivePixel(a, target, SampledRender.this, ctx);
            return new Renderer.TileWorker() {
                @Override
                public void tile(int x0, int y0, int x1, int y1) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) {
                            pixel.render(x, y, film);
                        }
                    }
                    film.writeTo(image, x0, y0, x1, y1);
                }
            };
        }
    }
}
