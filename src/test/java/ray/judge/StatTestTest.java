package ray.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** The t-tests against SciPy 1.x's ttest_ind(equal_var=False) / ttest_1samp on a textbook pair, Sidak, and the false-alarm rate. */
class StatTestTest {

    static final double[] A = {19.8, 20.4, 19.6, 17.8, 18.5, 18.9, 18.3, 18.9, 19.5, 22.0};
    static final double[] B = {28.2, 26.6, 20.1, 23.3, 25.2, 22.1, 17.7, 27.6, 20.6, 13.7, 23.2, 17.5, 20.6, 18.0, 23.9,
        21.6, 24.3, 20.4, 23.9, 13.3};

    @Test
    void welchAgreesWithScipy() {
        StatTest.Estimate a = StatTest.Estimate.of(A), b = StatTest.Estimate.of(B);
        assertEquals(-2.225512039969852, (a.mean() - b.mean()) / Math.sqrt(a.varianceOfMean() + b.varianceOfMean()), 1e-12);
        assertEquals(24.524634944257343, StatTest.welchDof(a, b), 1e-9);
        assertEquals(0.035484530830010394, StatTest.pValue(a, b), 1e-9);
        assertEquals(StatTest.pValue(a, b), StatTest.pValue(b, a), 1e-15);
    }

    @Test
    void oneSampleAgreesWithScipy() {
        assertEquals(0.3564463329049763, StatTest.pValue(StatTest.Estimate.of(A), 19.0), 1e-9);
        assertEquals(0.07338803477074037, StatTest.twoSidedP(2.0, 10), 1e-12);
        assertEquals(0.07338803477074037, StatTest.twoSidedP(-2.0, 10), 1e-12);
    }

    @Test
    void sidakHoldsTheFamilyRate() {
        assertEquals(0.01, StatTest.sidak(0.01, 1), 1e-15);
        for (int m : new int[] {2, 10, 1000, 1_000_000}) {
            double level = StatTest.sidak(0.01, m);
            assertEquals(0.01, -Math.expm1(m * Math.log1p(-level)), 1e-12, "m = " + m);
            assertTrue(level < 0.01 / m * 1.01 && level > 0.01 / m, "close to Bonferroni for small alpha: " + level);
        }
    }

    @Test
    void noVarianceMeansExactlyRightOrSurelyWrong() {
        StatTest.Estimate e = new StatTest.Estimate(0.5, 0, 10);
        assertEquals(1, StatTest.pValue(e, 0.5));
        assertEquals(0, StatTest.pValue(e, 0.5000001));
        assertEquals(0, StatTest.pValue(e, new StatTest.Estimate(0.6, 0, 3)));
    }

    /**
     * Under the null hypothesis a family at alpha = 0.05 fails about 5% of the time, whatever its size: 300
     * seeded families of 20 Welch tests of two normal samples with unequal variances each.
     */
    @Test
    void falseAlarmsHappenAtTheFamilyRateAndAShiftIsFound() {
        Random rnd = new Random(15);
        int failed = 0, families = 300;
        for (int f = 0; f < families; f++) {
            StatTest.Family fam = new StatTest.Family(0.05);
            for (int t = 0; t < 20; t++) {
                fam.test("t" + t, StatTest.Estimate.of(normal(rnd, 12, 0, 1)), StatTest.Estimate.of(normal(rnd, 30, 0, 3)));
            }
            failed += fam.passed() ? 0 : 1;
        }
        // binomial(300, 0.05): mean 15, sd 3.8
        assertTrue(failed >= 4 && failed <= 27, failed + " of " + families + " families failed");
        System.out.println("false alarms: " + failed + " of " + families + " families at alpha 0.05");
        StatTest.Family shifted = new StatTest.Family(0.05);
        shifted.test("shifted", StatTest.Estimate.of(normal(rnd, 200, 0.4, 1)), StatTest.Estimate.of(normal(rnd, 200, 0, 1)));
        assertFalse(shifted.passed(), shifted.summary());
    }

    static double[] normal(Random rnd, int n, double mean, double sd) {
        double[] v = new double[n];
        for (int i = 0; i < n; i++) {
            v[i] = mean + sd * rnd.nextGaussian();
        }
        return v;
    }
}
