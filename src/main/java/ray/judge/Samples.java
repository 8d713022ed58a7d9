package ray.judge;

import java.util.List;
import ray.render.Film;
import ray.render.Image;

/**
 * A stochastic image as estimates: per pixel and channel the mean of independent samples (display values
 * in [0, 1]), the estimated variance of that mean, and its degrees of freedom. From a {@link Film} (each
 * pixel's own samples, clamped to [0, 1] as the PNG clamps them) or from several independent renders of one
 * scene (their per-pixel mean and spread).
 *
 * <p>Within a pixel, stratified samplers (jittered, Sobol) place samples in strata, so the samples are not
 * independent and s^2 / n overestimates the variance of their mean: tests built on it are conservative
 * (fewer false alarms, less power). Independent renders have no such caveat.
 */
public final class Samples {

    public final int width, height;
    private final double[] mean, varianceOfMean, dof;

    private Samples(int width, int height, double[] mean, double[] varianceOfMean, double[] dof) {
        this.width = width;
        this.height = height;
        this.mean = mean;
        this.varianceOfMean = varianceOfMean;
        this.dof = dof;
    }

    /**
     * Estimates given directly: {@code mean} and {@code varianceOfMean} hold r, g, b of pixel (x, y) at
     * 3 (y w + x); {@code dof} one value per pixel (samples - 1).
     */
    public static Samples of(int width, int height, double[] mean, double[] varianceOfMean, double[] dof) {
        if (mean.length != 3 * width * height || varianceOfMean.length != mean.length || dof.length != width * height) {
            throw new IllegalArgumentException("arrays do not match a " + width + "x" + height + " image");
        }
        return new Samples(width, height, mean.clone(), varianceOfMean.clone(), dof.clone());
    }

    /** A film's pixels: clamped means, s^2 / n of their clamped samples, n - 1 (pixels need two samples or more). */
    public static Samples of(Film film) {
        int w = film.width, h = film.height;
        double[] m = new double[3 * w * h], v = new double[3 * w * h], d = new double[w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = y * w + x, n = film.count(x, y);
                if (n < 2) {
                    throw new IllegalArgumentException("pixel (" + x + ", " + y + ") has " + n
                            + " sample(s); a variance needs two or more");
                }
                d[p] = n - 1;
                for (int c = 0; c < 3; c++) {
                    m[3 * p + c] = film.clampedMean(x, y, c);
                    v[3 * p + c] = film.sampleVariance(x, y, c) / n;
                }
            }
        }
        return new Samples(w, h, m, v, d);
    }

    /** The variance of rounding to 8 bits: a uniform error of +-half a step, (1/255)^2 / 12. */
    public static final double ROUNDING_VARIANCE = 1.0 / (255.0 * 255.0 * 12);

    /**
     * Independent renders of one scene (at least two, same size, e.g. other sampler seeds): their mean and
     * spread per pixel. Renders are taken to be 8-bit images: each value carries a rounding error of variance
     * {@link #ROUNDING_VARIANCE}, added to the measured spread, so that a few renders which happen to agree to
     * the step (their measured variance 0) do not make a one- or two-step difference look certain.
     */
    public static Samples of(List<Image> renders) {
        int k = renders.size();
        if (k < 2) {
            throw new IllegalArgumentException("a variance needs two or more independent renders, got " + k);
        }
        int w = renders.get(0).width, h = renders.get(0).height;
        double[] m = new double[3 * w * h], v = new double[3 * w * h], d = new double[w * h];
        for (Image img : renders) {
            if (img.width != w || img.height != h) {
                throw new IllegalArgumentException("renders differ in size: " + w + "x" + h + " and " + img.width + "x" + img.height);
            }
            for (int i = 0; i < m.length; i++) {
                m[i] += Flip.clamp(img.rgb[i]) / k;
            }
        }
        for (Image img : renders) {
            for (int i = 0; i < m.length; i++) {
                double e = Flip.clamp(img.rgb[i]) - m[i];
                v[i] += e * e / ((k - 1.0) * k);
            }
        }
        for (int i = 0; i < v.length; i++) {
            v[i] += ROUNDING_VARIANCE / k;
        }
        java.util.Arrays.fill(d, k - 1);
        return new Samples(w, h, m, v, d);
    }

    /** Pixel (x, y)'s estimate in channel c. */
    public StatTest.Estimate pixel(int x, int y, int c) {
        int p = y * width + x;
        return new StatTest.Estimate(mean[3 * p + c], varianceOfMean[3 * p + c], dof[p]);
    }

    /**
     * The estimate of the mean over the pixels [x0, x1) x [y0, y1) in channel c: the pixels are independent,
     * so the variances add (divided by the count squared); degrees of freedom by Welch-Satterthwaite.
     */
    public StatTest.Estimate region(int x0, int y0, int x1, int y1, int c) {
        double m = 0, v = 0, den = 0;
        int count = 0;
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int p = y * width + x;
                double vi = varianceOfMean[3 * p + c];
                m += mean[3 * p + c];
                v += vi;
                den += vi * vi / dof[p];
                count++;
            }
        }
        double dofs = den == 0 ? Math.max(1, count) : v * v / den;
        return new StatTest.Estimate(m / count, v / ((double) count * count), dofs);
    }

    /** The means as an image (display values). */
    public Image means() {
        Image out = new Image(width, height);
        System.arraycopy(mean, 0, out.rgb, 0, mean.length);
        return out;
    }
}
