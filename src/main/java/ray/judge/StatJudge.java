package ray.judge;

import java.util.LinkedHashMap;
import java.util.Map;

/**
 * Judges a stochastic image against a stochastic reference (area lights, jittered, Sobol or adaptive
 * sampling, a student's own sampling), statistically as Nori (EPFL) checks its Monte Carlo code, never
 * pixel by pixel: for every pixel and every {@code region} x {@code region} block, and each channel, Welch's
 * t-test of the candidate's mean against the reference's with both measured variances. The family of all
 * these tests is held to an overall false-alarm rate {@code alpha} by Sidak's correction, and a rejection
 * counts only when the means differ by more than {@code minSteps}. A right image passes with probability at
 * least 1 - alpha; a biased one fails once its bias stands out of the noise (regions find small biases over
 * many pixels, pixels find large local ones).
 *
 * <p>Credit is the share of the reference's content (pixels off its most common colour) outside rejected
 * pixels and regions; the heat map shows each pixel's largest |t| on the log scale of {@link HeatMap#ofSteps}.
 */
public final class StatJudge {

    private StatJudge() {
    }

    public static Judgement judge(Samples reference, Samples candidate) {
        return judge(reference, candidate, StatPolicy.DEFAULT);
    }

    /** Judges {@code candidate} against {@code reference} (see the class comment). */
    public static Judgement judge(Samples reference, Samples candidate, StatPolicy policy) {
        int w = reference.width, h = reference.height;
        if (candidate.width != w || candidate.height != h) {
            Map<String, Double> m = new LinkedHashMap<>();
            m.put("score", 0.0);
            return new Judgement(0, false, Difference.SIZE, String.format("FAIL: the image is %dx%d, the reference %dx%d",
                    candidate.width, candidate.height, w, h), m, candidate.width, candidate.height, new double[0], new boolean[0], false);
        }
        int rs = policy.region(), rx = (w + rs - 1) / rs, ry = (h + rs - 1) / rs;
        int tests = 3 * (w * h + (rs > 1 ? rx * ry : 0));
        double level = StatTest.sidak(policy.alpha(), tests), margin = policy.minSteps() / 255;
        boolean[] wrong = new boolean[w * h];
        double[] map = new double[w * h];
        int pixelRejections = 0, regionRejections = 0;
        double smallest = 1;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                boolean rejected = false;
                for (int c = 0; c < 3; c++) {
                    StatTest.Estimate a = candidate.pixel(x, y, c), b = reference.pixel(x, y, c);
                    double p = StatTest.pValue(a, b), t = tStat(a, b);
                    map[y * w + x] = Math.max(map[y * w + x], Math.min(255, Math.abs(t)));
                    smallest = Math.min(smallest, p);
                    rejected |= p < level && Math.abs(a.mean() - b.mean()) > margin;
                }
                if (rejected) {
                    wrong[y * w + x] = true;
                    pixelRejections++;
                }
            }
        }
        if (rs > 1) {
            for (int by = 0; by < ry; by++) {
                for (int bx = 0; bx < rx; bx++) {
                    int x0 = bx * rs, y0 = by * rs, x1 = Math.min(w, x0 + rs), y1 = Math.min(h, y0 + rs);
                    boolean rejected = false;
                    for (int c = 0; c < 3; c++) {
                        StatTest.Estimate a = candidate.region(x0, y0, x1, y1, c), b = reference.region(x0, y0, x1, y1, c);
                        double p = StatTest.pValue(a, b);
                        smallest = Math.min(smallest, p);
                        rejected |= p < level && Math.abs(a.mean() - b.mean()) > margin;
                    }
                    if (rejected) {
                        regionRejections++;
                        for (int y = y0; y < y1; y++) {
                            for (int x = x0; x < x1; x++) {
                                wrong[y * w + x] = true;
                            }
                        }
                    }
                }
            }
        }
        int wrongCount = 0;
        for (boolean b : wrong) {
            wrongCount += b ? 1 : 0;
        }
        int content = ImageJudge.contentPixels(ImageJudge.steps(reference.means()), policy.minSteps());
        boolean passed = pixelRejections == 0 && regionRejections == 0;
        double score = passed ? 1 : Math.max(0, 1 - (double) wrongCount / content);
        Difference where = passed ? Difference.NONE
                : wrongCount >= ImageJudge.WHOLE_SHARE * content ? Difference.WHOLE_IMAGE : Difference.REGION;
        Map<String, Double> m = new LinkedHashMap<>();
        m.put("score", score);
        m.put("wrong_share", (double) wrongCount / (w * h));
        m.put("wrong_pixels", (double) wrongCount);
        m.put("content_pixels", (double) content);
        m.put("tests", (double) tests);
        m.put("test_level", level);
        m.put("pixel_rejections", (double) pixelRejections);
        m.put("region_rejections", (double) regionRejections);
        m.put("smallest_p", smallest);
        m.put("max_abs_t", max(map));
        m.put("flip_mean", Flip.mean(Flip.errorMap(reference.means(), candidate.means())));
        String msg = String.format("%s: %d of %d pixel tests and %d of %d region tests reject at the Sidak-corrected"
                        + " level %.3g (alpha %.3g over %d tests, differences above %.2g steps); smallest p = %.3g; %s; credit %.0f%%",
                passed ? "PASS" : "FAIL", pixelRejections, w * h, regionRejections, rs > 1 ? rx * ry : 0, level,
                policy.alpha(), tests, policy.minSteps(), smallest, where.summary(), 100 * score);
        return new Judgement(score, passed, where, msg, m, w, h, map, wrong, false);
    }

    private static double tStat(StatTest.Estimate a, StatTest.Estimate b) {
        double v = a.varianceOfMean() + b.varianceOfMean(), d = a.mean() - b.mean();
        return v == 0 ? (d == 0 ? 0 : Double.POSITIVE_INFINITY) : d / Math.sqrt(v);
    }

    private static double max(double[] v) {
        double m = 0;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }
}
