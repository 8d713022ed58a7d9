package ray.render;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import ray.RayStats;
import ray.Scene;
import ray.TraceContext;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * One render split into rectangles that other processes render (Spark's executors: {@code raytracer-spark}),
 * assembled into the image and summary {@link Renderer#render()} gives, bit for bit, for every sampler:
 *
 * <pre>
 * // on each worker, once per scene: the scene parsed and prepared (plan, BVH) for the settings
 * Prepared p = SplitRender.prepare(scene, settings);
 * Piece piece = SplitRender.render(p, threads, x0, y0, x1, y1);     // any rectangles covering the image once
 * // on the driver
 * Assembly a = new Assembly(width, height);
 * a.add(piece); ...
 * for (ProbeTile t : a.probeTiles(64)) a.addProbes(SplitRender.probe(p, threads, t));   // adaptive only
 * Image image = a.image(); RenderSummary summary = a.summary(seconds);
 * </pre>
 *
 * Each pixel depends only on the scene and, for the adaptive sampler, on the first samples of its eight
 * neighbours (a window renders that ring's first batch too, uncounted). The adaptive sampler's error
 * estimate needs the whole film: the assembly picks the probe pixels as {@link ErrorProbe} does and
 * hands them out again as {@link ProbeTile}s; their contributions are summed in scan order on the
 * driver. Rays are counted once: a piece counts its own pixels' rays, a probe tile its probes'.
 */
public final class SplitRender {

    private SplitRender() {
    }

    /** A scene readied once (plan, BVH) for renders with one resolved setting: shared by any number of renders and threads. */
    public static final class Prepared {
        private final Scene scene;
        private final RenderSettings settings;
        private final RenderPlan plan;

        Prepared(Scene scene, RenderSettings settings, RenderPlan plan) {
            this.scene = scene;
            this.settings = settings;
            this.plan = plan;
        }

        public Scene scene() {
            return scene;
        }

        /** The settings resolved from the scene's globals and the ones given. */
        public RenderSettings settings() {
            return settings;
        }
    }

    /** Readies {@code scene} (render plan, BVH) for renders with {@code settings} (resolved against the scene here), once. */
    public static Prepared prepare(Scene scene, RenderSettings settings) {
        RenderSettings s = settings.resolve(scene);
        RenderPlan plan = RenderPlan.derive(scene, s);
        RenderEngine.prepare(scene, plan);
        return new Prepared(scene, s, plan);
    }

    /** Renders pixels [x0, x1) x [y0, y1) of a {@link #prepare}d scene on {@code threads} threads. */
    public static Piece render(Prepared prepared, int threads, int x0, int y0, int x1, int y1) {
        Renderer r = new Renderer(prepared.scene).threads(threads).settings(prepared.settings).plan(prepared.plan)
                .window(x0, y0, x1, y1).prepared();
        Image image = r.render();
        RenderSummary s = r.summary();
        long samples = s.film != null ? s.film.totalSamples() : (long) s.samplesPerSide * s.samplesPerSide * image.width * image.height;
        Film film = s.film != null && prepared.settings.adaptive() ? s.film : null;
        return new Piece(x0, y0, image, film, samples, r.stats(), s.sampler, s.samplesPerSide);
    }

    /** The probes of one {@link ProbeTile}: each probed pixel's squared-error contribution (before its chance). */
    public static ProbeResult probe(Prepared prepared, int threads, ProbeTile tile) {
        Scene scene = prepared.scene;
        Renderer r = new Renderer(scene).threads(threads).maxDepth(prepared.settings.maxDepth());
        int[] index = new int[tile.width * tile.height];
        java.util.Arrays.fill(index, -1);
        for (int k = 0; k < tile.xs.length; k++) {
            index[(tile.ys[k] - tile.y0) * tile.width + tile.xs[k] - tile.x0] = k;
        }
        double[] values = new double[tile.xs.length];
        Renderer.Area area = new Renderer.Area(tile.x0, tile.y0, tile.x0 + tile.width, tile.y0 + tile.height);
        r.runTiles(null, new Renderer.TileWork() {
            @Override
            public Renderer.TileWorker worker(TraceContext ctx) {
                ErrorProbe.Probes probes = new ErrorProbe.Probes(scene, ctx);
                return new Renderer.TileWorker() {
                    @Override
                    public void tile(int x0, int y0, int x1, int y1) {
                        for (int y = y0; y < y1; y++) {
                            for (int x = x0; x < x1; x++) {
                                int k = index[(y - tile.y0) * tile.width + x - tile.x0];
                                if (k >= 0) {
                                    values[k] = probes.contribution(x, y, tile.size[k], tile.rgb, 3 * k);
                                }
                            }
                        }
                    }
                };
            }
        }, false, area);
        return new ProbeResult(tile, values, r.counted());
    }

    /** One rectangle's render: its linear pixels, its film (adaptive sampler only), its samples and rays. */
    public static final class Piece implements Serializable {
        private static final long serialVersionUID = 1L;
        public final int x0, y0;
        public final Image image;
        final Film film;
        final long samples;
        public final RayStats stats;
        final String sampler;
        final int samplesPerSide;

        Piece(int x0, int y0, Image image, Film film, long samples, RayStats stats, String sampler, int samplesPerSide) {
            this.x0 = x0;
            this.y0 = y0;
            this.image = image;
            this.film = film;
            this.samples = samples;
            this.stats = stats;
            this.sampler = sampler;
            this.samplesPerSide = samplesPerSide;
        }

        /** Pixels in the piece. */
        public long pixels() {
            return (long) image.width * image.height;
        }
    }

    /** Probe pixels of one rectangle: where, how many samples in each set, and the image's colour there. */
    public static final class ProbeTile implements Serializable {
        private static final long serialVersionUID = 1L;
        public final int x0, y0, width, height;
        final int[] xs, ys, size;
        final double[] rgb;

        ProbeTile(int x0, int y0, int width, int height, int[] xs, int[] ys, int[] size, double[] rgb) {
            this.x0 = x0;
            this.y0 = y0;
            this.width = width;
            this.height = height;
            this.xs = xs;
            this.ys = ys;
            this.size = size;
            this.rgb = rgb;
        }

        /** Probed pixels in the tile. */
        public int probes() {
            return xs.length;
        }
    }

    /** What a probe tile measured, and the rays it cast. */
    public static final class ProbeResult implements Serializable {
        private static final long serialVersionUID = 1L;
        final int[] xs, ys;
        final double[] values;
        public final RayStats stats;

        ProbeResult(ProbeTile tile, double[] values, RayStats stats) {
            this.xs = tile.xs;
            this.ys = tile.ys;
            this.values = values;
            this.stats = stats;
        }
    }

    /**
     * The driver's side: pieces in (any order), then for the adaptive sampler the probe tiles out and
     * their results in, then the image and the summary {@link Renderer#render()} would have given.
     * Holds the image (24 bytes a pixel) and, for the adaptive sampler, the film (76 bytes a pixel more).
     */
    public static final class Assembly {
        private final int width, height;
        private final Image image;
        private final BitSet covered;
        private long coveredPixels, samples;
        private final RayStats stats = new RayStats();
        private Film film;
        private String sampler;
        private int samplesPerSide;
        private ErrorProbe.Plan plan;
        private double[] contribution;
        private int probesExpected, probesIn;

        public Assembly(int width, int height) {
            this.width = width;
            this.height = height;
            this.image = new Image(width, height);
            this.covered = new BitSet(width * height);
        }

        /** Adds a piece; a pixel covered twice is refused (a rerun task's copy must not be added again). */
        public void add(Piece p) {
            int w = p.image.width, h = p.image.height;
            if (p.x0 < 0 || p.y0 < 0 || p.x0 + w > width || p.y0 + h > height) {
                throw new IllegalArgumentException("piece at (" + p.x0 + ", " + p.y0 + ") of " + w + " x " + h + " is outside the " + width + " x " + height + " image");
            }
            for (int y = 0; y < h; y++) {
                int row = (p.y0 + y) * width + p.x0;
                if (covered.nextSetBit(row) >= 0 && covered.nextSetBit(row) < row + w) {
                    throw new IllegalArgumentException("piece at (" + p.x0 + ", " + p.y0 + ") overlaps pixels already added");
                }
            }
            for (int y = 0; y < h; y++) {
                int row = (p.y0 + y) * width + p.x0;
                covered.set(row, row + w);
                System.arraycopy(p.image.rgb, 3 * y * w, image.rgb, 3 * row, 3 * w);
            }
            if (p.film != null) {
                if (film == null) {
                    film = new Film(width, height);
                }
                film.place(p.film, p.x0, p.y0);
            }
            coveredPixels += (long) w * h;
            samples += p.samples;
            stats.add(p.stats);
            sampler = p.sampler;
            samplesPerSide = p.samplesPerSide;
        }

        /** Whether every pixel has come in. */
        public boolean complete() {
            return coveredPixels == (long) width * height;
        }

        /**
         * The adaptive sampler's probes, cut into tiles of {@code tile} x {@code tile} pixels (only tiles
         * holding a probe); empty for the other samplers. Call once, when {@link #complete()}.
         */
        public List<ProbeTile> probeTiles(int tile) {
            requireComplete();
            List<ProbeTile> out = new ArrayList<>();
            if (film == null) {
                return out;
            }
            plan = ErrorProbe.plan(film);
            contribution = new double[width * height];
            for (int ty = 0; ty < height; ty += tile) {
                for (int tx = 0; tx < width; tx += tile) {
                    int x1 = Math.min(width, tx + tile), y1 = Math.min(height, ty + tile), n = 0;
                    for (int y = ty; y < y1; y++) {
                        for (int x = tx; x < x1; x++) {
                            n += plan.chance()[y * width + x] > 0 ? 1 : 0;
                        }
                    }
                    if (n == 0) {
                        continue;
                    }
                    int[] xs = new int[n], ys = new int[n], size = new int[n];
                    double[] rgb = new double[3 * n];
                    int k = 0;
                    for (int y = ty; y < y1; y++) {
                        for (int x = tx; x < x1; x++) {
                            int p = y * width + x;
                            if (plan.chance()[p] > 0) {
                                xs[k] = x;
                                ys[k] = y;
                                size[k] = plan.size()[p];
                                System.arraycopy(image.rgb, 3 * p, rgb, 3 * k, 3);
                                k++;
                            }
                        }
                    }
                    out.add(new ProbeTile(tx, ty, x1 - tx, y1 - ty, xs, ys, size, rgb));
                    probesExpected += n;
                }
            }
            return out;
        }

        /** Adds a probe tile's result (each once). */
        public void addProbes(ProbeResult r) {
            if (plan == null) {
                throw new IllegalStateException("no probes were handed out");
            }
            for (int k = 0; k < r.values.length; k++) {
                int p = r.ys[k] * width + r.xs[k];
                contribution[p] = r.values[k] / plan.chance()[p];
            }
            probesIn += r.values.length;
            stats.add(r.stats);
        }

        /** The assembled image (linear colours), as {@link Renderer#render()} returns it. */
        public Image image() {
            requireComplete();
            return image;
        }

        /** Rays cast by the pieces and probes added so far. */
        public RayStats stats() {
            return stats;
        }

        /** The render's summary, as {@link Renderer#summary()} gives it; {@code seconds} is the caller's wall time. */
        public RenderSummary summary(double seconds) {
            requireComplete();
            ErrorProbe.Estimate e = ErrorProbe.Estimate.NONE;
            if (film != null) {
                if (plan == null || probesIn != probesExpected) {
                    throw new IllegalStateException("the adaptive sampler's probes are not all in (" + probesIn + " of " + probesExpected + ")");
                }
                e = ErrorProbe.finish(plan, contribution);
            }
            double spp = (double) samples / ((double) width * height);
            return new RenderSummary(sampler, samplesPerSide, seconds, stats, spp, e.rmse(), e.low(), e.high(), e.samplesPerPixel(), film);
        }

        private void requireComplete() {
            if (!complete()) {
                throw new IllegalStateException("only " + coveredPixels + " of " + (long) width * height + " pixels are in");
            }
        }
    }
}
