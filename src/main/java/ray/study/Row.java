package ray.study;

import java.util.Locale;

/**
 * One line of a scene's CSV: a setting, its wall time over the repeats (median and range), its CPU time
 * (median and quartiles: the middle half of the repeats, which one disturbed render does not move), how
 * many repeats were timed, its rays and its error.
 */
public record Row(Setting setting, double secondsMedian, double secondsMin, double secondsMax, long rays,
        ImageError error, StudyRenderer.Estimate estimate, double meanSpp, double cpuMedian, double cpuQ1, double cpuQ3,
        int repeats) {

    /** As above with no CPU times (NaN) and one repeat. */
    public Row(Setting setting, double secondsMedian, double secondsMin, double secondsMax, long rays,
            ImageError error, StudyRenderer.Estimate estimate, double meanSpp) {
        this(setting, secondsMedian, secondsMin, secondsMax, rays, error, estimate, meanSpp, Double.NaN, Double.NaN, Double.NaN, 1);
    }

    /** The time a setting is judged by: CPU seconds where measured (less disturbed by other work on the machine), else wall. */
    public double cost() {
        return Double.isNaN(cpuMedian) ? secondsMedian : cpuMedian;
    }

    /**
     * The noise of {@link #cost()}: the CPU time's quartiles over the repeats (the wall time's range
     * where no CPU time was measured). Two settings whose intervals overlap are equally fast as far as
     * the study can tell.
     */
    public double costLow() {
        return Double.isNaN(cpuMedian) ? secondsMin : cpuQ1;
    }

    public double costHigh() {
        return Double.isNaN(cpuMedian) ? secondsMax : cpuQ3;
    }

    /**
     * The CSV header; the columns the issue fixes come first, then the adaptive sampler's own estimate
     * (its 95% interval, and what measuring it cost in samples per pixel, not counted in {@code spp}).
     */
    public static final String HEADER = "sampler,setting,spp,seconds_median,seconds_min,seconds_max,rays,rmse,psnr_db,"
            + "max_error,share_off_by_more_than_one,estimated_rmse,max_depth,estimated_rmse_low,estimated_rmse_high,estimate_spp,"
            + "cpu_seconds_median,cpu_seconds_q1,cpu_seconds_q3,repeats,rmse_steps,max_error_steps";

    /** The true RMSE in 8-bit steps (the unit of --target-error and of the adaptive estimate). */
    public double rmseSteps() {
        return error.rmse / ImageError.STEP;
    }

    /** The render's estimate of its own RMSE in 8-bit steps; NaN where the sampler makes none. */
    public double estimatedRmseSteps() {
        return estimate.rmseSteps();
    }

    public String csv() {
        boolean none = Double.isNaN(estimate.rmseSteps());
        return String.join(",", setting.sampler(), quote(setting.label()), num(meanSpp), num(secondsMedian), num(secondsMin),
                num(secondsMax), Long.toString(rays), num(error.rmse), num(error.psnrDb), num(error.maxError),
                num(error.shareOffByMoreThanOneStep), none ? "" : num(estimate.rmseSteps() * ImageError.STEP),
                Integer.toString(setting.maxDepth()), none ? "" : num(estimate.lowSteps() * ImageError.STEP),
                none ? "" : num(estimate.highSteps() * ImageError.STEP), none ? "" : num(estimate.samplesPerPixel()),
                num(cpuMedian), num(cpuQ1), num(cpuQ3), Integer.toString(repeats), num(rmseSteps()), num(error.maxError / ImageError.STEP));
    }

    static String num(double v) {
        if (Double.isNaN(v)) {
            return "";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        return String.format(Locale.ROOT, "%.6g", v);
    }

    private static String quote(String s) {
        return s.contains(",") || s.contains("\"") ? "\"" + s.replace("\"", "\"\"") + "\"" : s;
    }
}
