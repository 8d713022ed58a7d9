package ray.render;

import javax.vecmath.Vector3d;
import ray.Scene;
import ray.TraceContext;

/**
 * Measures how far a finished adaptive image is from the converged one, instead of trusting a model of
 * the grid's error. No formula on a pixel's own samples can know it: a grid is exact on an edge that
 * runs along a row of cell boundaries and off by up to 1 / (2 n_s) on one just beside it, with the same
 * samples. So a few probe pixels are rendered again with more samples (Owen-scrambled Sobol,
 * (1.5 n_s)^2, at least 8 x 8, at most 32 x 32) and the image's mean squared error is estimated from
 * them (Horvitz-Thompson): pixel i is probed with probability p_i proportional to the largest sample
 * variance of its mean in its 3 x 3 neighbourhood plus the mean of those (so every pixel can be
 * picked, the doubtful ones and their neighbours more often),
 * and contributes d_i^2 / p_i, d_i being its clamped difference from its probe. One pixel in 128 is
 * probed (256 to 8,192), picked by systematic sampling in scan order (fixed count, spread over the
 * image: less spread in the estimate than independent draws); the probes cost about one sample per
 * pixel at n_s = 8 and a half at n_s = 4. Nothing depends on threads. The probe's own error (about half
 * the image's at n_s = 8) is counted in, so the estimate leans high.
 */
final class ErrorProbe {

    private static final int SEED = 0xe770be;

    private final SampledRender render;
    private final Renderer renderer;
    private final Scene scene;
    private final Film film;
    private final Image image;

    ErrorProbe(SampledRender render, Renderer renderer, Scene scene, Film film, Image image) {
        this.render = render;
        this.renderer = renderer;
        this.scene = scene;
        this.film = film;
        this.image = image;
    }

    /** The estimated RMSE of the clamped image in 8-bit steps; {@code ns} is the render's n_s. */
    double measure(int ns) {
        int w = scene.width, h = scene.height, pixels = w * h;
        double[] own = new double[pixels];
        for (int p = 0; p < pixels; p++) {
            double v = film.varianceOfMean(p % w, p / w);
            own[p] = v > 0 ? v : 0;
        }
        // a pixel beside one whose samples disagree may have missed the same edge: the 3 x 3 maximum
        double[] weight = SampledRender.neighbourhoodMax(own, w, h);
        double sum = 0;
        for (double v : weight) {
            sum += v;
        }
        double floor = sum > 0 ? sum / pixels : 1, total = sum + floor * pixels;
        int probes = Math.max(Math.min(pixels, 256), Math.min(8192, pixels / 128));
        // systematic sampling in scan order: a pixel is probed when the running sum of the chances
        // passes a whole number (shifted by one hashed offset); each pixel's chance is its own
        double[] chance = new double[pixels];
        double offset = Sampler.unit(Sampler.hash(w, h, SEED, 1)), running = 0;
        for (int p = 0; p < pixels; p++) {
            double c = Math.min(1, probes * (weight[p] + floor) / total);
            chance[p] = Math.floor(running + offset) < Math.floor(running + c + offset) ? c : 0;
            running += c;
        }
        int side = Math.min(32, Math.max(8, (3 * ns + 1) / 2));
        Sampler probe = new SobolSampler(side);
        double[] contribution = new double[pixels];
        renderer.runTiles(image, new Renderer.TileWork() {
            @Override
            public Renderer.TileWorker worker(TraceContext ctx) {
                Vector3d c = new Vector3d();
                return new Renderer.TileWorker() {
                    @Override
                    public void tile(int x0, int y0, int x1, int y1) {
                        for (int y = y0; y < y1; y++) {
                            for (int x = x0; x < x1; x++) {
                                int p = y * w + x;
                                if (chance[p] > 0) {
                                    contribution[p] = squaredError(ctx, probe, x, y, c) / chance[p];
                                }
                            }
                        }
                    }
                };
            }
        }, false);
        double squared = 0;
        for (double d : contribution) {
            squared += d;
        }
        return Math.sqrt(squared / pixels);
    }

    /** The squared difference (8-bit steps, mean over r, g, b, clamped) between pixel (x, y) and its probe. */
    private double squaredError(TraceContext ctx, Sampler probe, int x, int y, Vector3d c) {
        double r = 0, g = 0, b = 0;
        int n = probe.samplesPerPixel();
        for (int s = 0; s < n; s++) {
            render.trace(ctx, probe, x, y, s, c);
            r += c.x;
            g += c.y;
            b += c.z;
        }
        int i = 3 * (y * image.width + x);
        double dr = Film.clamp(image.rgb[i]) - Film.clamp(r / n);
        double dg = Film.clamp(image.rgb[i + 1]) - Film.clamp(g / n);
        double db = Film.clamp(image.rgb[i + 2]) - Film.clamp(b / n);
        return (dr * dr + dg * dg + db * db) / 3 * 255 * 255;
    }
}
