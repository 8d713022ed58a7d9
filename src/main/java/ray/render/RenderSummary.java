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
    /**
     * CPU time of the render in seconds: the calling thread's (plan, scene preparation, BVH build) and
     * every render thread's, read from the threads' own clocks, so other work in the process or on the
     * machine does not count; NaN unless {@link Renderer#measureCpu(boolean)} asked for it. The fork/join
     * pool's share of a parallel BVH build (meshes of 16,384 primitives and more) is not in it.
     */
    public final double cpuSeconds;
    /** Rays cast, by kind. */
    public final RayStats stats;
    /** Samples taken over pixels. */
    public final double meanSamplesPerPixel;
    /**
     * The adaptive sampler's estimate of the RMSE of the clamped image against the converged one, in
     * 8-bit steps, measured at probe pixels ({@code ErrorProbe}); NaN for the other samplers.
     */
    public final double estimatedRmse;
    /**
     * The approximate 95% interval of {@link #estimatedRmse} (8-bit steps; NaN without an estimate):
     * the probes are a sample of the pixels, so the estimate has a spread of its own, reported with it.
     */
    public final double estimatedRmseLow, estimatedRmseHigh;
    /** What the estimate cost: the probes' samples over the image's pixels (not in {@link #meanSamplesPerPixel}). */
    public final double probeSamplesPerPixel;
    /**
     * The error (RMSE, 8-bit steps) below which {@link #estimatedRmse} is not resolved to a factor of
     * 1.5: an estimate and a truth both below it agree that the error is below it (a twentieth of a step).
     */
    public static final double ESTIMATE_RESOLUTION = ErrorProbe.RESOLUTION;
    /** The film (null for the grid's fast path, which keeps no film). */
    public final Film film;

    RenderSummary(String sampler, int samplesPerSide, double seconds, RayStats stats, double meanSamplesPerPixel,
                  double estimatedRmse, double estimatedRmseLow, double estimatedRmseHigh, double probeSamplesPerPixel,
                  Film film) {
        this(sampler, samplesPerSide, seconds, Double.NaN, stats, meanSamplesPerPixel, estimatedRmse, estimatedRmseLow, estimatedRmseHigh,
                probeSamplesPerPixel, film);
    }

    RenderSummary(String sampler, int samplesPerSide, double seconds, double cpuSeconds, RayStats stats, double meanSamplesPerPixel,
                  double estimatedRmse, double estimatedRmseLow, double estimatedRmseHigh, double probeSamplesPerPixel,
                  Film film) {
        this.sampler = sampler;
        this.samplesPerSide = samplesPerSide;
        this.seconds = seconds;
        this.cpuSeconds = cpuSeconds;
        this.stats = stats;
        this.meanSamplesPerPixel = meanSamplesPerPixel;
        this.estimatedRmse = estimatedRmse;
        this.estimatedRmseLow = estimatedRmseLow;
        this.estimatedRmseHigh = estimatedRmseHigh;
        this.probeSamplesPerPixel = probeSamplesPerPixel;
        this.film = film;
    }

    /**
     * One line for the render summary, e.g. {@code adaptive: 5.3 samples per pixel, estimated error 0.41
     * (RMSE in 8-bit steps; 95% interval 0.35 to 0.47, measured with 0.5 more samples per pixel)}.
     */
    public String line() {
        String spp = String.valueOf(Math.round(meanSamplesPerPixel * 10) / 10.0);
        return sampler + ": " + spp + " samples per pixel"
                + (Double.isNaN(estimatedRmse) ? "" : ", estimated error " + round2(estimatedRmse)
                + " (RMSE in 8-bit steps; 95% interval " + round2(estimatedRmseLow) + " to " + round2(estimatedRmseHigh)
                + ", measured with " + Math.round(probeSamplesPerPixel * 10) / 10.0 + " more samples per pixel)");
    }

    private static double round2(double v) {
        return Math.round(v * 100) / 100.0;
    }
}
