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
     * The adaptive sampler's estimate of the RMSE of the clamped image against the converged one, in
     * 8-bit steps, measured at probe pixels ({@code ErrorProbe}); NaN for the other samplers.
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

    /** One line for the render summary, e.g. {@code adaptive: 5.3 samples per pixel, estimated error 0.41 (8-bit steps RMSE)}. */
    public String line() {
        String spp = String.valueOf(Math.round(meanSamplesPerPixel * 10) / 10.0);
        return sampler + ": " + spp + " samples per pixel"
                + (Double.isNaN(estimatedRmse) ? "" : ", estimated error " + Math.round(estimatedRmse * 100) / 100.0
                + " (RMSE in 8-bit steps)");
    }
}
