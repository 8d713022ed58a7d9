package ray.judge;

import org.apache.commons.math3.distribution.TDistribution;

/**
 * Student's t-tests for Monte Carlo estimates, as Nori (EPFL's teaching renderer, {@code ttest.cpp} and
 * {@code hypothesis.cpp}) checks its stochastic code: an estimate's mean against a known value (one sample),
 * or two estimates' means against each other with their own measured variances (Welch's unequal-variance
 * test, Welch-Satterthwaite degrees of freedom), each giving a two-sided p-value; a family of m tests is
 * held to an overall false-alarm rate alpha by testing each at Sidak's 1 - (1 - alpha)^(1/m).
 *
 * <p>An {@link Estimate} is the mean of n independent samples and the variance of that mean (s^2 / n), with
 * n - 1 degrees of freedom. Anything whose variance is measured the same way fits: a pixel's samples, a
 * region's pixels, several independent renders of one pixel.
 */
public final class StatTest {

    private StatTest() {
    }

    /**
     * A sample mean, the estimated variance of that mean and its degrees of freedom (n - 1 for n samples).
     */
    public record Estimate(double mean, double varianceOfMean, double dof) {
        public Estimate {
            if (!(varianceOfMean >= 0) || !(dof > 0)) {
                throw new IllegalArgumentException("an estimate needs a variance >= 0 and dof > 0: " + varianceOfMean + ", " + dof);
            }
        }

        /** The estimate from n samples' mean and their sample variance s^2 (denominator n - 1). */
        public static Estimate ofSamples(double mean, double sampleVariance, long n) {
            if (n < 2) {
                throw new IllegalArgumentException("a variance needs at least two samples, got " + n);
            }
            return new Estimate(mean, sampleVariance / n, n - 1);
        }

        /** The estimate of the samples' mean, their variance measured (two passes). */
        public static Estimate of(double... samples) {
            double m = 0;
            for (double v : samples) {
                m += v;
            }
            m /= samples.length;
            double s = 0;
            for (double v : samples) {
                s += (v - m) * (v - m);
            }
            return ofSamples(m, s / (samples.length - 1), samples.length);
        }

        public double standardError() {
            return Math.sqrt(varianceOfMean);
        }
    }

    /** Sidak's per-test level: m independent tests at it have a family-wise false-alarm rate of exactly alpha. */
    public static double sidak(double alpha, int tests) {
        if (!(alpha > 0 && alpha < 1) || tests < 1) {
            throw new IllegalArgumentException("sidak needs 0 < alpha < 1 and tests >= 1: " + alpha + ", " + tests);
        }
        return -Math.expm1(Math.log1p(-alpha) / tests);
    }

    /** The two-sided p-value of a t statistic with {@code dof} degrees of freedom (infinite t: 0). */
    public static double twoSidedP(double t, double dof) {
        if (Double.isNaN(t)) {
            return 1;
        }
        if (Double.isInfinite(t)) {
            return 0;
        }
        double tail = new TDistribution(null, dof).cumulativeProbability(-Math.abs(t));
        return Math.min(1, 2 * tail);
    }

    /**
     * One-sample t-test (Nori's {@code students_t_test}): is the estimate's expected value {@code expected}?
     * The p-value; an estimate with no variance that misses the value exactly gets 0, one that hits it 1.
     */
    public static double pValue(Estimate e, double expected) {
        double d = e.mean - expected;
        if (e.varianceOfMean == 0) {
            return d == 0 ? 1 : 0;
        }
        return twoSidedP(d / Math.sqrt(e.varianceOfMean), e.dof);
    }

    /** Welch's t-test: do the two estimates have the same expected value? The p-value. */
    public static double pValue(Estimate a, Estimate b) {
        double v = a.varianceOfMean + b.varianceOfMean, d = a.mean - b.mean;
        if (v == 0) {
            return d == 0 ? 1 : 0;
        }
        return twoSidedP(d / Math.sqrt(v), welchDof(a, b));
    }

    /** The Welch-Satterthwaite degrees of freedom of a difference of two estimates. */
    public static double welchDof(Estimate a, Estimate b) {
        double v = a.varianceOfMean + b.varianceOfMean;
        double den = (a.varianceOfMean == 0 ? 0 : a.varianceOfMean * a.varianceOfMean / a.dof)
                + (b.varianceOfMean == 0 ? 0 : b.varianceOfMean * b.varianceOfMean / b.dof);
        return den == 0 ? Math.max(a.dof, b.dof) : v * v / den;
    }

    /**
     * A family of tests judged together: add each test's p-value, then {@link #passed()} says whether none
     * rejects its null hypothesis at the Sidak-corrected level for the family's size.
     */
    public static final class Family {
        private final double alpha;
        private int tests;
        private double smallestP = 1;
        private String worst = "";
        private final java.util.List<Double> ps = new java.util.ArrayList<>();

        /** A family with overall false-alarm rate {@code alpha} (Nori's default: 0.01). */
        public Family(double alpha) {
            if (!(alpha > 0 && alpha < 1)) {
                throw new IllegalArgumentException("alpha must lie in (0, 1): " + alpha);
            }
            this.alpha = alpha;
        }

        /** Records one test's p-value under a name (for messages). */
        public Family add(String name, double p) {
            tests++;
            ps.add(p);
            if (p < smallestP || tests == 1) {
                smallestP = p;
                worst = name;
            }
            return this;
        }

        /** One-sample test of {@code e} against {@code expected}. */
        public Family test(String name, Estimate e, double expected) {
            return add(name + String.format(" (mean %.6g +- %.2g, expected %.6g)", e.mean, e.standardError(), expected),
                    pValue(e, expected));
        }

        /** Welch test of {@code a} against {@code b}. */
        public Family test(String name, Estimate a, Estimate b) {
            return add(name + String.format(" (%.6g +- %.2g against %.6g +- %.2g)", a.mean, a.standardError(), b.mean,
                    b.standardError()), pValue(a, b));
        }

        public int tests() {
            return tests;
        }

        /** The per-test level: Sidak's correction of alpha for the tests added so far. */
        public double level() {
            return tests == 0 ? alpha : sidak(alpha, tests);
        }

        /** How many tests reject at the corrected level. */
        public int rejections() {
            double level = level();
            int n = 0;
            for (double p : ps) {
                if (p < level) {
                    n++;
                }
            }
            return n;
        }

        public boolean passed() {
            return rejections() == 0;
        }

        public double smallestP() {
            return smallestP;
        }

        /** A line naming the worst test, its p-value and the corrected level. */
        public String summary() {
            return String.format("%d of %d tests reject at the Sidak-corrected level %.3g (alpha %.3g); smallest p = %.3g: %s",
                    rejections(), tests, level(), alpha, smallestP, worst);
        }
    }
}
