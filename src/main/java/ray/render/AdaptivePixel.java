package ray.render;

import javax.vecmath.Vector3d;
import ray.TraceContext;

/**
 * One render thread's adaptive sampling of a pixel: from the {@link AdaptiveSampler}'s first batch
 * (taken by an earlier pass), double the count while the estimated standard error of the pixel's mean
 * (s / sqrt(n) of the samples clamped to [0, 1], averaged over r, g, b in squares, in 8-bit steps) is
 * not below the target, up to all n_s x n_s samples; a nudged pixel (see {@code SampledRender}) takes
 * at least {@link #NUDGED} whatever its first batch says. The pixel is the sum of the samples taken, added in grid order, over
 * their count: with every sample taken it is the grid's pixel bit for bit. Scratch arrays are made once
 * per thread.
 */
final class AdaptivePixel {

    private final AdaptiveSampler sampler;
    private final double target;
    private final SampledRender render;
    private final TraceContext ctx;
    private final double[] colors;
    private final boolean[] taken;
    private final double[] sum = new double[3], mean = new double[3], m2 = new double[3];
    private final Vector3d c = new Vector3d();
    /** Samples a nudged pixel takes at least (a feature its first four missed shows this way). */
    static final int NUDGED = 16;

    AdaptivePixel(AdaptiveSampler sampler, double target, SampledRender render, TraceContext ctx) {
        this.sampler = sampler;
        this.target = target;
        this.render = render;
        this.ctx = ctx;
        int all = sampler.samplesPerPixel();
        colors = new double[3 * all];
        taken = new boolean[all];
    }

    /**
     * Finishes pixel (x, y), held at (fx, fy) of the film: its first batch is in {@code first} (and the
     * film); {@code nudged} asks for at least {@link #NUDGED} samples whatever the first batch says.
     */
    void render(int x, int y, Film film, int fx, int fy, double[] first, boolean nudged) {
        int all = sampler.samplesPerPixel(), b0 = sampler.firstBatch();
        java.util.Arrays.fill(taken, false);
        for (int ch = 0; ch < 3; ch++) {
            mean[ch] = 0;
            m2[ch] = 0;
        }
        int k = 0;
        for (int base = 3 * b0 * (fy * film.width + fx); k < b0; ) {
            c.set(first[base + 3 * k], first[base + 3 * k + 1], first[base + 3 * k + 2]);
            keep(sampler.order(k), ++k);
        }
        double limit = target * target;
        int least = nudged ? Math.min(all, NUDGED) : b0;
        while (k < all && (k < least || !((m2[0] + m2[1] + m2[2]) / (3.0 * (k - 1) * k) * 255 * 255 < limit))) {
            for (int goal = Math.min(all, 2 * k); k < goal; ) {
                int index = sampler.order(k);
                render.trace(ctx, x, y, index, c);
                keep(index, ++k);
            }
        }
        // the pixel's value: taken samples summed in grid order (the grid's own arithmetic)
        double r = 0, g = 0, b = 0;
        for (int i = 0; i < all; i++) {
            if (taken[i]) {
                r += colors[3 * i];
                g += colors[3 * i + 1];
                b += colors[3 * i + 2];
            }
        }
        sum[0] = r;
        sum[1] = g;
        sum[2] = b;
        film.set(fx, fy, k, sum, mean, m2);
    }

    /** Stores the colour in {@link #c} as grid sample {@code index}, the {@code n}-th taken. */
    private void keep(int index, int n) {
        taken[index] = true;
        colors[3 * index] = c.x;
        colors[3 * index + 1] = c.y;
        colors[3 * index + 2] = c.z;
        welford(0, c.x, n);
        welford(1, c.y, n);
        welford(2, c.z, n);
    }

    private void welford(int ch, double value, int n) {
        double v = Film.clamp(value), old = mean[ch];
        mean[ch] = old + (v - old) / n;
        m2[ch] += (v - old) * (v - mean[ch]);
    }
}
