package ray.render;

import javax.vecmath.Vector3d;
import ray.TraceContext;

/**
 * One render thread's adaptive sampling of a pixel: take the {@link AdaptiveSampler}'s first batch,
 * then double the count while the estimated standard error of the pixel's mean (s / sqrt(n) of the
 * samples clamped to [0, 1], averaged over r, g, b in squares, in 8-bit steps) is not below the target,
 * up to all n_s x n_s samples. The pixel is the sum of the samples taken, added in grid order, over
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

    AdaptivePixel(AdaptiveSampler sampler, double target, SampledRender render, TraceContext ctx) {
        this.sampler = sampler;
        this.target = target;
        this.render = render;
        this.ctx = ctx;
        int all = sampler.samplesPerPixel();
        colors = new double[3 * all];
        taken = new boolean[all];
    }

    void render(int x, int y, Film film) {
        int all = sampler.samplesPerPixel();
        java.util.Arrays.fill(taken, false);
        for (int ch = 0; ch < 3; ch++) {
            mean[ch] = 0;
            m2[ch] = 0;
        }
        int k = 0;
        if (film.count(x, y) == 1) {   // the progressive first pass took the first sample already
            c.set(film.sum(x, y, 0), film.sum(x, y, 1), film.sum(x, y, 2));
            keep(sampler.order(0), ++k);
        }
        double limit = target * target;
        for (int goal = sampler.firstBatch(); ; goal = Math.min(all, 2 * k)) {
            for (; k < goal; ) {
                int index = sampler.order(k);
                render.trace(ctx, x, y, index, c);
                keep(index, ++k);
            }
            if (k == all || (m2[0] + m2[1] + m2[2]) / (3.0 * (k - 1) * k) * 255 * 255 < limit) {
                break;
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
        film.set(x, y, k, sum, mean, m2);
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
