package ray.judge;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.function.DoubleBinaryOperator;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Ray;
import ray.Scene;
import ray.parse.Parser;
import ray.render.Film;
import ray.render.Renderer;
import ray.render.Sampler;
import ray.settings.RenderSettings;

/**
 * The engine's own stochastic parts under the t-tests of {@link StatTest} (Nori's way): each family holds
 * its false-alarm rate to 1% (Sidak), is seeded, and must also reject a planted bias, so that it can fail.
 * The samplers' pixel means against analytic integrals, an area light's pixel means against its analytic
 * irradiance, and the adaptive sampler's error estimate (two independent probes' product) against the
 * error it estimates.
 */
class EngineStatisticsTest {

    static final double ALPHA = 0.01;

    // ---- samplers: the mean of f over a pixel's n x n samples estimates the integral of f over the pixel ----

    /** Smooth, with an edge, on the diagonal: integrals over [0, 1)^2 known in closed form. */
    static final DoubleBinaryOperator[] F = {
        (u, v) -> Math.exp(u) * Math.sin(3 * v),
        (u, v) -> u * u + v * v < 0.6 ? 1 : 0,
        (u, v) -> u > v ? 1 : 0};
    static final double[] INTEGRAL = {(Math.E - 1) * (1 - Math.cos(3)) / 3, Math.PI * 0.6 / 4, 0.5};
    static final String[] NAMES = {"exp(u) sin(3v)", "quarter disc r^2 = 0.6", "u > v"};

    /** The per-pixel estimates of f over {@code pixels} pixels (each its own scramble: independent), dimensions (d, d + 1). */
    static StatTest.Estimate pixelMeans(Sampler s, DoubleBinaryOperator f, int dim, int pixels) {
        double[] est = new double[pixels];
        int spp = s.samplesPerPixel();
        for (int p = 0; p < pixels; p++) {
            int x = p % 64, y = p / 64;
            double sum = 0;
            for (int i = 0; i < spp; i++) {
                sum += f.applyAsDouble(s.get(x, y, i, dim), s.get(x, y, i, dim + 1));
            }
            est[p] = sum / spp;
        }
        return StatTest.Estimate.of(est);
    }

    @Test
    void jitteredAndSobolPixelMeansAreTheIntegrals() {
        StatTest.Family family = new StatTest.Family(ALPHA);
        StatTest.Family biased = new StatTest.Family(ALPHA);
        for (String name : new String[] {"jittered", "sobol"}) {
            for (int n : new int[] {1, 2, 4}) {
                Sampler s = Sampler.create(name, n, 7);
                for (int dim : new int[] {0, 2}) {
                    for (int k = 0; k < F.length; k++) {
                        String what = name + " " + n + "x" + n + " dims " + dim + "," + (dim + 1) + " " + NAMES[k];
                        StatTest.Estimate e = pixelMeans(s, F[k], dim, 4096);
                        family.test(what, e, INTEGRAL[k]);
                        // the same estimates 2% too large: a bias of that size must not pass
                        biased.test(what, new StatTest.Estimate(1.02 * e.mean(), 1.02 * 1.02 * e.varianceOfMean(), e.dof()),
                                INTEGRAL[k]);
                    }
                }
            }
        }
        System.out.println("samplers: " + family.summary());
        assertTrue(family.passed(), family.summary());
        assertTrue(biased.rejections() >= biased.tests() / 2, "a 2% bias is found in most tests: " + biased.summary());
    }

    // ---- an area light: a pixel's mean against the analytic irradiance ----

    static final double H = 0.6, KD = 0.5, I = 0.8, FOV = 20;
    static final int SIZE = 16;

    /**
     * A camera looking straight down at a Diffuse floor under a 1 x 1 area light 0.6 above it (close, so that
     * where its points go matters), 2 x 2 light samples per pixel sample.
     */
    static String areaScene(double intensity) {
        return "Width " + SIZE + "\nHeight " + SIZE + "\nAASamples 4\nBGColor [0 0 0]\nAmbientLight [0 0 0]\n"
                + "Camera Camera\nVector3d eye [0.3 5 0.2]\nVector3d target [0.3 0 0.2]\nVector3d up [0 0 -1]\ndouble yFOV " + FOV + "\n"
                + "Material Diffuse floor\nVector3d diffuseColor [" + KD + " " + KD + " " + KD + "]\n"
                + "Surface Triangle\nVector3d v0 [-20 0 20]\nVector3d v1 [20 0 20]\nVector3d v2 [20 0 -20]\nref material floor\n"
                + "Surface Triangle\nVector3d v0 [-20 0 20]\nVector3d v1 [20 0 -20]\nVector3d v2 [-20 0 -20]\nref material floor\n"
                + "Light AreaLight\nVector3d position [0 " + H + " 0]\nVector3d edge1 [1 0 0]\nVector3d edge2 [0 0 1]\n"
                + "Vector3d intensity [" + intensity + " " + intensity + " " + intensity + "]\nint samples 2\n";
    }

    /** k_d (I / A) times the solid angle of the light [-0.5, 0.5]^2 at height H seen from floor point (x, z). */
    static double irradiance(double x, double z) {
        return KD * I * (corner(0.5 - x, 0.5 - z) - corner(-0.5 - x, 0.5 - z) - corner(0.5 - x, -0.5 - z) + corner(-0.5 - x, -0.5 - z));
    }

    static double corner(double a, double b) {
        return Math.atan(a * b / (H * Math.sqrt(a * a + b * b + H * H)));
    }

    /** The expected value of pixel (x, y): the irradiance averaged over the pixel's footprint on the floor (16 x 16 midpoints). */
    static double expected(Scene scene, int x, int y) {
        Ray ray = new Ray(new Vector3d(), new Vector3d());
        double sum = 0;
        int m = 16;
        for (int j = 0; j < m; j++) {
            for (int i = 0; i < m; i++) {
                scene.camera.setRayThrough(ray, x + (i + 0.5) / m, y + (j + 0.5) / m, SIZE, SIZE);
                double t = -ray.origin.y / ray.direction.y;
                sum += irradiance(ray.origin.x + t * ray.direction.x, ray.origin.z + t * ray.direction.z);
            }
        }
        return sum / (m * m);
    }

    @Test
    void anAreaLightsPixelMeansAreItsIrradiance() throws Exception {
        for (String sampler : new String[] {"jittered", "sobol"}) {
            Scene scene = Parser.parse(areaScene(I), "area.txt", new ArrayList<>());
            Renderer r = new Renderer(scene).threads(2).settings(new RenderSettings().sampler(sampler).seed(3));
            r.render();
            Film film = r.summary().film;
            Samples samples = Samples.of(film);
            StatTest.Family family = new StatTest.Family(ALPHA), dimmer = new StatTest.Family(ALPHA);
            double expectedSum = 0;
            for (int y = 0; y < SIZE; y++) {
                for (int x = 0; x < SIZE; x++) {
                    StatTest.Estimate e = samples.pixel(x, y, 1);
                    double want = expected(scene, x, y);
                    family.test(sampler + " pixel (" + x + ", " + y + ")", e, want);
                    dimmer.test(sampler + " pixel (" + x + ", " + y + ") against 3% more", e, 1.03 * want);
                    expectedSum += want;
                }
            }
            for (int by = 0; by < SIZE; by += 4) {        // 4 x 4 regions: small biases over many pixels
                for (int bx = 0; bx < SIZE; bx += 4) {
                    double want = 0;
                    for (int y = by; y < by + 4; y++) {
                        for (int x = bx; x < bx + 4; x++) {
                            want += expected(scene, x, y) / 16;
                        }
                    }
                    family.test(sampler + " region (" + bx + ", " + by + ")", samples.region(bx, by, bx + 4, by + 4, 1), want);
                }
            }
            int n = SIZE * SIZE;
            StatTest.Estimate image = samples.region(0, 0, SIZE, SIZE, 1);
            family.test(sampler + " image mean", image, expectedSum / n);
            dimmer.test(sampler + " image mean against 3% more", image, 1.03 * expectedSum / n);
            System.out.println("area light, " + sampler + ": " + family.summary());
            assertTrue(family.passed(), family.summary());
            assertFalse(dimmer.passed(), "a 3% error in the light must be found: " + dimmer.summary());
        }
    }

    /** Two renders with other seeds are two independent estimates of the same image: StatJudge passes them; 5% more light fails. */
    @Test
    void statJudgePassesAnotherSeedAndFailsAStrongerLight() throws Exception {
        Samples reference = film(areaScene(I), 11), other = film(areaScene(I), 12), stronger = film(areaScene(1.05 * I), 13);
        Judgement same = StatJudge.judge(reference, other), wrong = StatJudge.judge(reference, stronger);
        System.out.println("another seed: " + same.message());
        System.out.println("5% stronger light: " + wrong.message());
        assertTrue(same.passed(), same.message());
        assertFalse(wrong.passed(), wrong.message());
        assertTrue(wrong.metric("region_rejections") > 0, wrong.message());
    }

    /**
     * The grader's path: several independent 8-bit renders (other seeds, rounded as the PNG holds them) of the
     * reference and of the candidate. Another program's right renders pass; 5% more light fails.
     */
    @Test
    void statJudgeOnIndependentEightBitRenders() throws Exception {
        Samples reference = renders(areaScene(I), 20), other = renders(areaScene(I), 30), stronger = renders(areaScene(1.05 * I), 40);
        Judgement same = StatJudge.judge(reference, other), wrong = StatJudge.judge(reference, stronger);
        System.out.println("8-bit renders, other seeds: " + same.message());
        System.out.println("8-bit renders, 5% stronger light: " + wrong.message());
        assertTrue(same.passed(), same.message());
        assertFalse(wrong.passed(), wrong.message());
    }

    /** Four renders with seeds from {@code seed}, each rounded to 8 bits. */
    static Samples renders(String text, int seed) throws Exception {
        java.util.List<ray.render.Image> out = new ArrayList<>();
        for (int k = 0; k < 4; k++) {
            Scene scene = Parser.parse(text, "area.txt", new ArrayList<>());
            out.add(Images.quantised(new Renderer(scene).threads(2)
                    .settings(new RenderSettings().sampler("jittered").seed(seed + k)).render()));
        }
        return Samples.of(out);
    }

    static Samples film(String text, int seed) throws Exception {
        Scene scene = Parser.parse(text, "area.txt", new ArrayList<>());
        Renderer r = new Renderer(scene).threads(2).settings(new RenderSettings().sampler("jittered").seed(seed));
        r.render();
        return Samples.of(r.summary().film);
    }

    // ---- the adaptive estimate: E[(I - A)(I - B)] = d^2 for independent probes A and B ----

    /**
     * The adaptive sampler's error probe estimates a pixel's squared error d^2 = (I - truth)^2 by the
     * product of its differences from two independently scrambled Sobol estimates (ErrorProbe). Here, over
     * an edge of known coverage, a 2 x 2 grid pixel I and probes of 16 Sobol points with independent seeds:
     * the mean product is d^2 (and not the biased (I - A)^2, which the probe's own noise inflates).
     */
    @Test
    void theProbeProductEstimatesTheSquaredErrorWithoutBias() {
        DoubleBinaryOperator edge = (u, v) -> v < 0.3 + 0.37 * u ? 1 : 0;     // coverage 0.3 + 0.185 = 0.485
        double truth = 0.485;
        Sampler grid = Sampler.create("grid", 2);
        double image = 0;
        for (int i = 0; i < 4; i++) {
            image += edge.applyAsDouble(grid.get(0, 0, i, 0), grid.get(0, 0, i, 1)) / 4;
        }
        double d2 = (image - truth) * (image - truth);
        int k = 4000;
        double[] product = new double[k], single = new double[k];
        for (int s = 0; s < k; s++) {
            double a = sobolMean(edge, 2 * s + 1), b = sobolMean(edge, 2 * s + 2);
            product[s] = (image - a) * (image - b);
            single[s] = (image - a) * (image - a);
        }
        StatTest.Family family = new StatTest.Family(ALPHA).test("probe product", StatTest.Estimate.of(product), d2);
        StatTest.Family naive = new StatTest.Family(ALPHA).test("one probe squared", StatTest.Estimate.of(single), d2);
        System.out.println("adaptive estimate: " + family.summary());
        assertTrue(family.passed(), family.summary());
        assertFalse(naive.passed(), "the one-probe estimate is biased by the probe's own variance: " + naive.summary());
    }

    static double sobolMean(DoubleBinaryOperator f, int seed) {
        Sampler s = Sampler.create("sobol", 4, seed);
        double sum = 0;
        for (int i = 0; i < 16; i++) {
            sum += f.applyAsDouble(s.get(0, 0, i, 0), s.get(0, 0, i, 1));
        }
        return sum / 16;
    }
}
