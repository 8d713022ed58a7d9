package ray.render;

import ray.RayStats;

/**
 * What a finished render cost and how good it is: wall time, rays by kind, mean samples per pixel and,
 * for the film-based samplers, the estimated error of the image against a converged one.
 */
public final class RenderSummary {

    /** The sampler used and its n_s. */
    public final String sampler;
    public final int samplesPerSide;
    /** Wall time of the render (after parsing; including the BVH build), in seconds. */
    public final double seconds;
    /** Rays cast, by kind. */
    public final RayStats stats;
    /** Samples taken over pixels. */
    public final double meanSamplesPerPixel;
    /**
     * The estimated RMSE of the clamped image against the converged one, in 8-bit steps, from each
     * pixel's sample variance; NaN for the grid's fast path and with one sample per pixel.
     */
    public final double estimatedRmse;
    /** The film (null for the grid's fast path, which keeps no film). */
    public final Film film;

    RenderSummary(String sampler, int samplesPerSide, double seconds, RayStats stats, double meanSamplesPerPixel,
                  double estimatedRmse, Film film) {
        this.sampler = sampler;
        this.samplesPerSide = samplesPerSide;
        this.seconds = seconds;
        this.stats = stats;
        this.meanSamplesPerPixel = meanSamplesPerPixel;
        this.estimatedRmse = estimatedRmse;
        this.film = film;
    }

    /** The estimated RMSE of a film's clamped image (8-bit steps): sqrt of the mean per-pixel variance of the mean. */
    static double estimatedRmse(Film film) {
        double total = 0;
        for (int y = 0; y < film.height; y++) {
            for (int x = 0; x < film.width; x++) {
                double v = film.varianceOfMean(x, y);
                if (Double.isNaN(v)) {
                    return Double.NaN;
                }
                total += v;
            }
        }
        return Math.sqrt(total / ((double) film.width * film.height));
    }

    /** One line for the render summary, e.g. {@code adaptive: 5.3 samples per pixel, estimated error 0.41 (8-bit steps RMSE)}. */
    public String line() {
        String spp = String.valueOf(Math.round(meanSamplesPerPixel * 10) / 10.0);
        return sampler + ": " + spp + " samples per pixel"
                + (Double.isNaN(estimatedRmse) ? "" : ", estimated error " + Math.round(estimatedRmse * 100) / 100.0
                + " (RMSE in 8-bit steps)");
    }
}
