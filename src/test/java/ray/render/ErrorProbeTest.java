package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import ray.settings.RenderSettings;
import ray.Scene;
import ray.parse.Parser;

/** The adaptive render's error estimate: unbiased by the probes' own noise, with an honest interval and cost. */
class ErrorProbeTest {

    /** A sphere hiding a point light, its shadow and the horizon: all the error is on a few edges. */
    private static Scene scene() throws Exception {
        Scene s = Parser.parse(Path.of("scenes", "light-behind-object.txt"));
        s.camera.aspect = (double) s.width / s.height;
        s.width = 80;
        s.height = 60;
        return s;
    }

    /**
     * Fed an image that is nearly converged (Sobol 32 x 32, error 0.016 steps), the estimate stays near
     * that: the probes' own noise (0.1 to 0.2 steps at these edges) does not count in. The estimator
     * before this one, (I - P)^2 over one probe, reported 0.20 steps at n_s = 4 and 0.11 at n_s = 8 on
     * this very test (7 to 13 times the truth); this one 0.00 and 0.04, intervals holding the truth.
     */
    @Test
    void theProbesOwnNoiseIsNotChargedToTheImage() throws Exception {
        Image converged = new Renderer(scene()).threads(2).settings(new RenderSettings().sampler("sobol").samples(32).seed(1)).render();
        Image other = new Renderer(scene()).threads(2).settings(new RenderSettings().sampler("sobol").samples(32).seed(2)).render();
        // two independent renders: the RMS of their difference over sqrt 2 is the error of either
        double truth = SampledRenderTest.rmse(converged, other) / Math.sqrt(2);
        assertTrue(truth > 0.005 && truth < 0.025, "the converged image's own error: " + truth);
        for (int ns : new int[] {4, 8}) {
            Scene scene = scene();
            Renderer r = new Renderer(scene).threads(2).settings(new RenderSettings().sampler("adaptive").samples(ns).targetError(1));
            r.render();
            ErrorProbe.Estimate e = new ErrorProbe(scene, r.summary().film, converged).measure(r);
            assertTrue(e.rmse() < 0.06, "n_s=" + ns + ": estimated " + e.rmse() + " for an image " + truth + " off");
            assertTrue(e.low() <= truth && truth <= e.high(), "n_s=" + ns + ": interval " + e.low() + " to " + e.high() + ", truth " + truth);
        }
    }

    /** The reported cost is what the probes cast: camera rays = the image's samples + the probes'. */
    @Test
    void theReportedCostIsTheProbesRays() throws Exception {
        for (int ns : new int[] {2, 4, 8}) {
            Scene scene = scene();
            Renderer r = new Renderer(scene).threads(2).settings(new RenderSettings().sampler("adaptive").samples(ns).targetError(1));
            r.render();
            RenderSummary s = r.summary();
            double pixels = 80 * 60;
            assertEquals((double) r.stats().get(ray.RayKind.CAMERA), (s.meanSamplesPerPixel + s.probeSamplesPerPixel) * pixels, 1e-6,
                    "n_s=" + ns);
            assertTrue(s.probeSamplesPerPixel > 0, "n_s=" + ns);
            assertTrue(s.estimatedRmseLow <= s.estimatedRmse && s.estimatedRmse <= s.estimatedRmseHigh, s.line());
        }
    }

    @Test
    void probeSetsAreAPowerOfTwoAtLeastTwiceThePixelsSamplesAndTheirCountFitsTheBudget() {
        for (int n = 1; n <= 4096; n++) {
            int m = ErrorProbe.halfSamples(n);
            assertEquals(1, Integer.bitCount(m), "n=" + n + ": " + m);
            assertTrue(m >= Math.min(2048, 2 * n) && m >= 16 && m <= 2048 && (m == 16 || m / 2 < 2 * n), "n=" + n + ": " + m);
        }
        assertEquals((int) Math.round(ErrorProbe.BUDGET * 1_000_000 / 100.0), ErrorProbe.probeCount(1_000_000, 100), "the budget buys them");
        assertEquals(1_000_000 / 8, ErrorProbe.probeCount(1_000_000, 1), "at most one pixel in 8");
        assertEquals(256, ErrorProbe.probeCount(20_000, 1000), "at least 256");
        assertEquals(100, ErrorProbe.probeCount(100, 1000), "never more than the pixels");
    }

    /** Seeds give independent images; seed 0 is the default, bit for bit. */
    @Test
    void seedsGiveIndependentSamplesAndZeroIsTheDefault() {
        for (String name : new String[] {"jittered", "sobol"}) {
            Sampler plain = Sampler.create(name, 4), zero = Sampler.create(name, 4, 0), one = Sampler.create(name, 4, 1);
            int differ = 0;
            for (int i = 0; i < 16; i++) {
                for (int d = 0; d < 4; d++) {
                    assertEquals(plain.get(3, 5, i, d), zero.get(3, 5, i, d), 0.0, name);
                    differ += plain.get(3, 5, i, d) != one.get(3, 5, i, d) ? 1 : 0;
                }
            }
            assertTrue(differ > 60, name + ": seed 1 moves the samples (" + differ + " of 64 differ)");
        }
    }
}
