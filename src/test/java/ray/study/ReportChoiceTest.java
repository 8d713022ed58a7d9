package ray.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import ray.render.Image;

/**
 * The study picks settings a person can trust: a setting is only faster when its CPU times' middle half
 * over the repeats does not overlap the other's, a tie goes to the setting with fewer samples, the
 * recommendation over all scenes follows the same rules, and the plots' log axes label 1, 2 and 5 in
 * every decade.
 */
class ReportChoiceTest {

    /** A row with RMSE {@code rmse} (fraction of the range), {@code spp} samples and CPU times median/quartiles. */
    static Row row(String sampler, String label, double rmse, double spp, double cpu, double q1, double q3) {
        Image a = new Image(1, 1), ref = new Image(1, 1);
        a.rgb[0] = a.rgb[1] = a.rgb[2] = rmse;
        return new Row(new Setting(sampler, label, 4, 1, 5), cpu, q1, q3, 100, ImageError.of(a, ref),
                StudyRenderer.Estimate.NONE, spp, cpu, q1, q3, 3);
    }

    static Row row(String label, double rmse, double spp, double cpu, double q1, double q3) {
        return row("adaptive", label, rmse, spp, cpu, q1, q3);
    }

    @Test
    void aTimeWithinTheNoiseIsATieAndTiesGoToTheCheaperSetting() {
        Row t1 = row("target=1", 0.005, 8.0, 0.1000, 0.095, 0.110);
        Row t2 = row("target=2", 0.005, 5.0, 0.1003, 0.098, 0.104);     // 0.3 ms slower by the median: noise
        assertSame(t2, Report.cheapest(List.of(t1, t2), 0.01), "the same error, times that overlap: fewer samples wins");
        assertSame(t2, Report.cheapest(List.of(t2, t1), 0.01), "whatever the order");
        Row fast = row("target=4", 0.008, 9.0, 0.050, 0.049, 0.051);
        assertSame(fast, Report.cheapest(List.of(t1, t2, fast), 0.01), "clearly faster (ranges apart) wins despite more samples");
        Row bad = row("target=8", 0.02, 2.0, 0.01, 0.01, 0.01);
        assertSame(fast, Report.cheapest(List.of(t1, t2, fast, bad), 0.01), "a setting above the error allowed never counts");
        assertEquals(null, Report.cheapest(List.of(bad), 0.01));
    }

    @Test
    void theRecommendationOverAllScenesIsTheSettingThatReaches40DbMostOftenAndCheapestWithinTheNoise() {
        double ok = 0.005, poor = 0.02;            // 40 dB is an RMSE of 0.01
        SceneStudy.Outcome a = outcome("a", row("grid", "n_s=4", ok, 16, 1.0, 0.98, 1.02), row("adaptive", "target=2", ok, 5, 0.50, 0.48, 0.53),
                row("adaptive", "target=1", ok, 8, 0.49, 0.47, 0.52), row("grid", "n_s=2", poor, 4, 0.2, 0.19, 0.21));
        SceneStudy.Outcome b = outcome("b", row("grid", "n_s=4", ok, 16, 1.0, 0.98, 1.02), row("adaptive", "target=2", ok, 6, 0.60, 0.58, 0.62),
                row("adaptive", "target=1", ok, 9, 0.59, 0.57, 0.61), row("grid", "n_s=2", ok, 4, 0.2, 0.19, 0.21));
        String rec = Report.recommendation(List.of(a, b));
        assertTrue(rec.startsWith("For scenes like these, use adaptive with target=2: it reaches PSNR 40 dB in 2 of 2 scenes"), rec);
        assertTrue(rec.contains("grid with n_s=4"), "the grid setting that does as well, for comparison: " + rec);
        // a setting cheaper by far but reaching 40 dB in fewer scenes is not recommended
        assertTrue(!rec.contains("n_s=2"), rec);
    }

    static SceneStudy.Outcome outcome(String name, Row... rows) {
        return new SceneStudy.Outcome(name, null, 1, 1, null, List.of(rows), List.of(), List.of(""));
    }

    @Test
    void logAxesLabelOneTwoAndFiveInEveryDecade() {
        assertEquals("0.02", Plots.oneTwoFive(0.02));
        assertEquals("0.05", Plots.oneTwoFive(0.05));
        assertEquals("", Plots.oneTwoFive(0.03));
        assertEquals("1", Plots.oneTwoFive(1.0));
        assertEquals("", Plots.oneTwoFive(7.0));
        assertEquals("50", Plots.oneTwoFive(50.0));
        assertEquals("0.1", Plots.oneTwoFive(0.1));
        assertEquals("", Plots.oneTwoFive(0.0));
    }

    @Test
    void bothEndsOfEachAxisAreLabelledValues() {
        assertEquals(0.02, Plots.oneTwoFiveBelow(0.031), 1e-12);
        assertEquals(0.05, Plots.oneTwoFiveAbove(0.031), 1e-12);
        assertEquals(50, Plots.oneTwoFiveAbove(47.2), 1e-9);
        assertEquals(0.5, Plots.oneTwoFiveBelow(0.9), 1e-12);
        assertEquals(1, Plots.oneTwoFiveAbove(1.0), 1e-12);
        assertEquals(10, Plots.oneTwoFiveAbove(5.5), 1e-12);
        for (double v : new double[] {0.0123, 0.7, 3.3, 47.2, 120}) {
            assertEquals(false, Plots.oneTwoFive(Plots.oneTwoFiveBelow(v)).isEmpty(), v + " below");
            assertEquals(false, Plots.oneTwoFive(Plots.oneTwoFiveAbove(v)).isEmpty(), v + " above");
        }
    }

    @Test
    void namesOfPointsOnOneSpotNeverOverlapAndOneCurvesShareAName() {
        // material-glazed: the grid's n_s=4, adaptive's target=2 and target=1 on nearly one spot; MaxDepth 4 and 5 on one
        List<PointLabels.Point> pts = List.of(new PointLabels.Point(0, 0, "4", "grid"), new PointLabels.Point(0, 0, "t=2", "adaptive"),
                new PointLabels.Point(0, 0, "t=1", "adaptive"), new PointLabels.Point(0, 0, "d=3", "depth"),
                new PointLabels.Point(0, 0, "d=4", "depth"), new PointLabels.Point(0, 0, "d=5", "depth"));
        int[] sx = {300, 306, 309, 100, 140, 142}, sy = {200, 201, 201, 100, 100, 102};
        List<PointLabels.Placed> placed = PointLabels.place(pts, sx, sy, new java.awt.geom.Rectangle2D.Double(0, 0, 600, 400),
                t -> 6 * t.length(), 11);
        assertEquals(List.of("4", "t=2,1", "d=3", "d=4,5"), placed.stream().map(PointLabels.Placed::text).toList());
        for (int i = 0; i < placed.size(); i++) {
            for (int j = i + 1; j < placed.size(); j++) {
                assertTrue(!placed.get(i).box().intersects(placed.get(j).box()), placed.get(i) + " and " + placed.get(j));
            }
            for (int k = 0; k < sx.length; k++) {
                assertTrue(!placed.get(i).box().contains(sx[k], sy[k]), placed.get(i) + " covers point " + k);
            }
        }
    }

    @Test
    void eachPointIsNamedBriefly() {
        assertEquals("4", Plots.shortLabel(row("grid", "n_s=4", 0, 16, 1, 1, 1)));
        assertEquals("t=0.5", Plots.shortLabel(row("target=0.5", 0, 16, 1, 1, 1)));
        Row depth = new Row(new Setting("grid", "MaxDepth=3 n_s=4", 4, 0, 3), 1, 1, 1, 1, ImageError.of(new Image(1, 1), new Image(1, 1)),
                StudyRenderer.Estimate.NONE, 16);
        assertEquals("d=3", Plots.shortLabel(depth), "the n_s is in the curve's name");
    }
}
