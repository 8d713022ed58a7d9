package ray.render;

import javax.vecmath.Vector3d;

/**
 * Per-pixel accumulation of samples, apart from the 8-bit image (pbrt's {@code RGBFilm}, Mitsuba's
 * {@code ImageBlock}): the sum of the linear colours and the sample count give the pixel's value; a
 * running mean and variance (Welford's M2) per channel of the samples clamped to [0, 1] give its
 * estimated error, which adaptive sampling and the render summary use (the PNG clamps to [0, 1] too).
 * Each pixel is written by one thread at a time.
 */
public final class Film implements java.io.Serializable {

    private static final long serialVersionUID = 1L;

    public final int width;
    public final int height;
    private final double[] sum;
    private final double[] clampedMean;
    private final double[] m2;
    private final int[] count;

    public Film(int width, int height) {
        this.width = width;
        this.height = height;
        sum = new double[3 * width * height];
        clampedMean = new double[3 * width * height];
        m2 = new double[3 * width * height];
        count = new int[width * height];
    }

    /** Adds one sample's colour to pixel (x, y). */
    public void add(int x, int y, double r, double g, double b) {
        int p = y * width + x, i = 3 * p;
        int n = ++count[p];
        sum[i] += r;
        sum[i + 1] += g;
        sum[i + 2] += b;
        welford(i, r, n);
        welford(i + 1, g, n);
        welford(i + 2, b, n);
    }

    private void welford(int i, double value, int n) {
        double c = clamp(value), old = clampedMean[i];
        double mean = old + (c - old) / n;
        m2[i] += (c - old) * (c - mean);
        clampedMean[i] = mean;
    }

    /**
     * Replaces pixel (x, y) with {@code n} samples summing to {@code s} (r, g, b) whose clamped values
     * have means {@code mean} and Welford M2 {@code m2s} per channel (a pixel finished in one go).
     */
    public void set(int x, int y, int n, double[] s, double[] mean, double[] m2s) {
        int p = y * width + x, i = 3 * p;
        count[p] = n;
        for (int c = 0; c < 3; c++) {
            sum[i + c] = s[c];
            clampedMean[i + c] = mean[c];
            m2[i + c] = m2s[c];
        }
    }

    /** Samples in pixel (x, y). */
    public int count(int x, int y) {
        return count[y * width + x];
    }

    /** Sum of pixel (x, y)'s samples in channel c (0 r, 1 g, 2 b). */
    public double sum(int x, int y, int c) {
        return sum[3 * (y * width + x) + c];
    }

    /** The pixel's value: the mean of its samples (black while it has none). */
    public void mean(int x, int y, Vector3d out) {
        int p = y * width + x, i = 3 * p, n = count[p];
        if (n == 0) {
            out.set(0, 0, 0);
        } else {
            out.set(sum[i] / n, sum[i + 1] / n, sum[i + 2] / n);
        }
    }

    /**
     * The estimated variance of pixel (x, y)'s clamped mean, averaged over the three channels, in
     * 8-bit steps squared: s^2 / n per channel; NaN with fewer than two samples.
     */
    public double varianceOfMean(int x, int y) {
        int p = y * width + x, i = 3 * p, n = count[p];
        if (n < 2) {
            return Double.NaN;
        }
        return (m2[i] + m2[i + 1] + m2[i + 2]) / (3.0 * (n - 1) * n) * 255 * 255;
    }

    /** The mean of pixel (x, y)'s samples clamped to [0, 1] in channel c (0 r, 1 g, 2 b): the value the variance belongs to. */
    public double clampedMean(int x, int y, int c) {
        return clampedMean[3 * (y * width + x) + c];
    }

    /**
     * The sample variance s^2 (denominator n - 1) of pixel (x, y)'s clamped samples in channel c, in units of
     * the [0, 1] range squared; NaN with fewer than two samples.
     */
    public double sampleVariance(int x, int y, int c) {
        int n = count[y * width + x];
        return n < 2 ? Double.NaN : m2[3 * (y * width + x) + c] / (n - 1);
    }

    /** Writes the pixels' means into {@code image} (same size). */
    public void writeTo(Image image) {
        for (int p = 0, n = width * height; p < n; p++) {
            int c = count[p], i = 3 * p;
            if (c > 0) {
                image.rgb[i] = sum[i] / c;
                image.rgb[i + 1] = sum[i + 1] / c;
                image.rgb[i + 2] = sum[i + 2] / c;
            }
        }
    }

    /** Writes rows [y0, y1) x columns [x0, x1) of the pixels' means into {@code image}. */
    public void writeTo(Image image, int x0, int y0, int x1, int y1) {
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int p = y * width + x, c = count[p], i = 3 * p;
                if (c > 0) {
                    image.set(x, y, sum[i] / c, sum[i + 1] / c, sum[i + 2] / c);
                }
            }
        }
    }

    /** A new film of pixels [x0, x0 + w) x [y0, y0 + h) of this one. */
    Film crop(int x0, int y0, int w, int h) {
        Film out = new Film(w, h);
        for (int y = 0; y < h; y++) {
            int from = (y0 + y) * width + x0, to = y * w;
            System.arraycopy(count, from, out.count, to, w);
            System.arraycopy(sum, 3 * from, out.sum, 3 * to, 3 * w);
            System.arraycopy(clampedMean, 3 * from, out.clampedMean, 3 * to, 3 * w);
            System.arraycopy(m2, 3 * from, out.m2, 3 * to, 3 * w);
        }
        return out;
    }

    /** Copies {@code part}'s pixels into this film with its corner at (x0, y0). */
    void place(Film part, int x0, int y0) {
        for (int y = 0; y < part.height; y++) {
            int from = y * part.width, to = (y0 + y) * width + x0;
            System.arraycopy(part.count, from, count, to, part.width);
            System.arraycopy(part.sum, 3 * from, sum, 3 * to, 3 * part.width);
            System.arraycopy(part.clampedMean, 3 * from, clampedMean, 3 * to, 3 * part.width);
            System.arraycopy(part.m2, 3 * from, m2, 3 * to, 3 * part.width);
        }
    }

    /** Total samples over all pixels. */
    public long totalSamples() {
        long t = 0;
        for (int c : count) {
            t += c;
        }
        return t;
    }

    static double clamp(double v) {
        return v > 0 ? Math.min(v, 1) : 0;
    }
}
