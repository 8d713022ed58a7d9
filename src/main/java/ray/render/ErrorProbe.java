package ray.render;

import javax.vecmath.Vector3d;
import ray.Scene;
import ray.TraceContext;

/**
 * Measures how far a finished adaptive image is from the converged one, instead of trusting a model of
 * the grid's error. No formula on a pixel's own samples can know it: a grid is exact on an edge that
 * runs along a row of cell boundaries and off by up to 1 / (2 n_s) on one just beside it, with the same
 * samples. So a few probe pixels are rendered again, twice, with two independently scrambled sets of
 * Owen-scrambled Sobol points, and the image's mean squared error is estimated from them
 * (Horvitz-Thompson).
 *
 * <p><b>Why two sets and a product.</b> With one probe P per pixel, (I - P)^2 estimates d^2 + var(P),
 * d = I - truth: the probe's own error counts in, and where the image is good it is as large as the
 * error measured. With two independent probes A and B, E[(I - A)(I - B)] = d^2 exactly (each is an
 * unbiased estimate of the pixel's integral, and their errors are independent), so the probe's noise
 * adds spread but no bias. (The product equals (I - (A + B) / 2)^2 - (A - B)^2 / 4: the pooled probe's
 * squared difference minus an unbiased estimate of its own variance.)
 *
 * <p><b>Which pixels.</b> Pixel i is probed with probability p_i proportional to the largest
 * per-sample variance in its 3 x 3 neighbourhood over its own sample count (what its mean's variance
 * would be had its samples disagreed like its neighbours': a pixel that stopped early beside an edge is
 * where a missed edge hides), at least a quarter of the largest squared difference between its mean and
 * a neighbour's over its count (the spread of a pixel that the edge between them halves: samples that
 * all agree on a contrast), plus a third of the mean of those (so every pixel can be picked; three
 * quarters of the probes go where samples disagree), and contributes (I - A)(I - B) / p_i. The pixels
 * are picked by systematic sampling in scan order (fixed count, spread over the image). How each of
 * these choices was measured against the alternatives is in docs/accuracy.md.
 *
 * <p><b>How many samples.</b> Each set has {@link #halfSamples} of the pixel's own count (twice it, so
 * a set alone is better than the pixel it judges), {@link #CALM} where the neighbourhood's samples all
 * agree (nothing varies there, and a feature the image missed shows with few samples too). The number
 * of probes is set so that they cost {@link #BUDGET} samples per pixel ({@link #probeCount}): a fixed,
 * reported price ({@link Estimate#samplesPerPixel}). Nothing depends on threads.
 *
 * <p><b>Its spread.</b> A 95% interval comes with the estimate, from the spread of the probes'
 * contributions (the with-replacement variance formula). It cannot see error in pixels no probe hit,
 * so at very small errors (below about {@link #RESOLUTION} steps, where a few pixels hold most of it)
 * it can be too narrow, and the estimate does not resolve the error to a factor of 1.5 (docs/accuracy.md).
 */
final class ErrorProbe {

    private static final int SEED_A = 0xe770be, SEED_B = 0x5eb0b1;
    /** Samples in each set of a probe whose 3 x 3 neighbourhood's samples all agree. */
    static final int CALM = 16;
    /** What the probes cost, in samples per pixel of the image (both sets). */
    static final double BUDGET = 2;
    /** RMSE (8-bit steps) below which the estimate does not resolve the error to a factor of 1.5. */
    static final double RESOLUTION = 0.05;

    /** What the probes measured: RMSE in 8-bit steps, its 95% interval, and the probes' cost. */
    record Estimate(double rmse, double low, double high, int probes, double samplesPerPixel) {
        static final Estimate NONE = new Estimate(Double.NaN, Double.NaN, Double.NaN, 0, 0);
    }

    private final Scene scene;
    private final Film film;
    private final Image image;

    /** The probes of a finished adaptive render of the whole of {@code scene}: its film and image. */
    ErrorProbe(Scene scene, Film film, Image image) {
        this.scene = scene;
        this.film = film;
        this.image = image;
    }

    /**
     * Which pixels to probe and with how many samples: {@code chance[p]} > 0 for a probed pixel p (its
     * probability of having been picked), {@code size[p]} the samples in each of its two sets.
     */
    record Plan(double[] chance, int[] size, int picked, long samples) {
    }

    /**
     * Samples in each of a probe's two sets for a pixel that took {@code n}: the power of two at or
     * above 2n (at least 16, at most 2,048), so each set alone is better than the pixel it judges and is
     * a (0, m, 2)-net.
     */
    static int halfSamples(int n) {
        int want = Math.max(16, Math.min(2048, 2 * n));
        return Integer.highestOneBit(want - 1) << 1;
    }

    /**
     * How many pixels to probe when a probe costs {@code expectedCost} samples on average: as many as
     * {@link #BUDGET} samples per pixel buy, at least 256 (or every pixel), at most one pixel in 8.
     */
    static int probeCount(int pixels, double expectedCost) {
        int want = (int) Math.round(BUDGET * pixels / expectedCost);
        return Math.min(pixels, Math.max(Math.min(256, pixels), Math.min(want, pixels / 8)));
    }

    /** Measures the estimated RMSE of the clamped image, the probes rendered by {@code renderer}'s threads. */
    Estimate measure(Renderer renderer) {
        Plan plan = plan(film);
        double[] contribution = new double[image.width * image.height];
        Renderer.Area whole = new Renderer.Area(0, 0, image.width, image.height);
        renderer.runTiles(image, new Renderer.TileWork() {
            @Override
            public Renderer.TileWorker worker(TraceContext ctx) {
                Probes probes = new Probes(scene, ctx);
                return new Renderer.TileWorker() {
                    @Override
                    public void tile(int x0, int y0, int x1, int y1) {
                        for (int y = y0; y < y1; y++) {
                            for (int x = x0; x < x1; x++) {
                                int p = y * image.width + x;
                                if (plan.chance[p] > 0) {
                                    contribution[p] = probes.contribution(x, y, plan.size[p], image.rgb, 3 * p) / plan.chance[p];
                                }
                            }
                        }
                    }
                };
            }
        }, false, whole);
        return finish(plan, contribution);
    }

    /** Picks the pixels to probe from the film of a finished adaptive render of the whole image. */
    static Plan plan(Film film) {
        int w = film.width, h = film.height, pixels = w * h;
        // per-sample variance: how much the samples disagree, whatever their count
        double[] disagree = new double[pixels];
        for (int p = 0; p < pixels; p++) {
            int n = film.count(p % w, p / w);
            double v = film.varianceOfMean(p % w, p / w) * n;
            disagree[p] = v > 0 ? v : 0;
        }
        // a pixel beside one whose samples disagree may have missed the same edge with its fewer
        // samples: the 3 x 3 maximum of the spread over its own count (its error if its samples had
        // disagreed as much); and a pixel whose mean differs from a neighbour's by d may hide the edge
        // between them: d^2 / 4 is the spread of a pixel that edge halves
        double[] weight = SampledRender.neighbourhoodMax(disagree, w, h);
        double[] mean = new double[3 * pixels];
        for (int p = 0; p < pixels; p++) {
            int n = film.count(p % w, p / w);
            for (int c = 0; c < 3; c++) {
                mean[3 * p + c] = Film.clamp(film.sum(p % w, p / w, c) / n);
            }
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = y * w + x, n = film.count(x, y);
                double contrast = 0;
                for (int j = Math.max(0, y - 1); j <= Math.min(h - 1, y + 1); j++) {
                    for (int i = Math.max(0, x - 1); i <= Math.min(w - 1, x + 1); i++) {
                        int q = j * w + i;
                        for (int c = 0; c < 3; c++) {
                            double d = mean[3 * p + c] - mean[3 * q + c];
                            contrast = Math.max(contrast, d * d);
                        }
                    }
                }
                weight[p] = Math.max(weight[p], contrast / 4 * 255 * 255) / n;
            }
        }
        double sum = 0;
        for (double v : weight) {
            sum += v;
        }
        // a quarter of the probes spread by the floor alone, three quarters by the samples' disagreement
        double floor = sum > 0 ? sum / pixels / 3 : 1, total = sum + floor * pixels;
        // each probe set twice the samples of the pixel it judges (so it is as good or better), 16 to 2,048
        int[] size = new int[pixels];
        double expected = 0;
        for (int p = 0; p < pixels; p++) {
            size[p] = weight[p] > 0 ? halfSamples(film.count(p % w, p / w)) : CALM;
            expected += (weight[p] + floor) / total * 2 * size[p];
        }
        int probes = probeCount(pixels, expected);
        // systematic sampling in scan order: a pixel is probed when the running sum of the chances
        // passes a whole number (shifted by one hashed offset); each pixel's chance is its own
        double[] chance = new double[pixels];
        double offset = Sampler.unit(Sampler.hash(w, h, SEED_A, 1)), running = 0;
        int picked = 0;
        for (int p = 0; p < pixels; p++) {
            double c = Math.min(1, probes * (weight[p] + floor) / total);
            if (Math.floor(running + offset) < Math.floor(running + c + offset)) {
                chance[p] = c;
                picked++;
            }
            running += c;
        }
        long samples = 0;
        for (int p = 0; p < pixels; p++) {
            if (chance[p] > 0) {
                samples += 2L * size[p];
            }
        }
        return new Plan(chance, size, picked, samples);
    }

    /**
     * The estimate from each pixel's contribution (zero where not probed; the probe's squared error
     * over its chance), summed in scan order: the same number however the probes were split up.
     */
    static Estimate finish(Plan plan, double[] contribution) {
        int pixels = contribution.length, picked = plan.picked;
        double[] chance = plan.chance;
        double squared = 0;
        for (double d : contribution) {
            squared += d;
        }
        // spread: with-replacement formula over the picked probes, n z_k against the total
        double spread = 0;
        for (int p = 0; p < pixels; p++) {
            if (chance[p] > 0) {
                double z = picked * contribution[p] - squared;
                spread += z * z;
            }
        }
        double half = picked > 1 ? 1.96 * Math.sqrt(spread / ((double) picked * (picked - 1))) : Double.POSITIVE_INFINITY;
        return new Estimate(Math.sqrt(Math.max(0, squared) / pixels), Math.sqrt(Math.max(0, squared - half) / pixels),
                Math.sqrt(Math.max(0, squared + half) / pixels), picked, (double) plan.samples / pixels);
    }

    /** One render thread's probing: the two Sobol sets of each size in use (powers of two: index log2 m), made as needed. */
    static final class Probes {
        private final Scene scene;
        private final TraceContext ctx;
        private final SobolSampler[] a = new SobolSampler[12], b = new SobolSampler[12];
        private final Vector3d c = new Vector3d(), pa = new Vector3d(), pb = new Vector3d();

        Probes(Scene scene, TraceContext ctx) {
            this.scene = scene;
            this.ctx = ctx;
        }

        /**
         * (I - A)(I - B) for pixel (x, y) whose image colour I is at {@code rgb[i..i+2]}, against probes A
         * and B of {@code m} samples each (clamped; mean over r, g, b; 8-bit steps squared): an unbiased
         * estimate of the pixel's squared error, possibly negative.
         */
        double contribution(int x, int y, int m, double[] rgb, int i) {
            int k = Integer.numberOfTrailingZeros(m);
            if (a[k] == null) {
                int side = (int) Math.ceil(Math.sqrt(m));
                a[k] = new SobolSampler(side, SEED_A, m);
                b[k] = new SobolSampler(side, SEED_B, m);
            }
            mean(a[k], x, y, pa);
            mean(b[k], x, y, pb);
            double r = Film.clamp(rgb[i]), g = Film.clamp(rgb[i + 1]), bl = Film.clamp(rgb[i + 2]);
            return ((r - pa.x) * (r - pb.x) + (g - pa.y) * (g - pb.y) + (bl - pa.z) * (bl - pb.z)) / 3 * 255 * 255;
        }

        /** The mean of pixel (x, y)'s samples from {@code probe}, clamped to [0, 1] per channel, into {@code out}. */
        private void mean(SobolSampler probe, int x, int y, Vector3d out) {
            double r = 0, g = 0, bl = 0;
            int n = probe.count();
            for (int s = 0; s < n; s++) {
                SampledRender.trace(scene, ctx, probe, x, y, s, c);
                r += c.x;
                g += c.y;
                bl += c.z;
            }
            out.set(Film.clamp(r / n), Film.clamp(g / n), Film.clamp(bl / n));
        }
    }
}
