package ray.light;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import ray.Camera;
import ray.IntersectionRecord;
import ray.RayKind;
import ray.Scene;
import ray.TraceContext;
import ray.parse.Parser;
import ray.parse.ObjectErrors;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.Renderer;
import ray.render.Sampler;

/**
 * n x n point lights of I / n^2, one in each cell. Summed over a rectangle, sum (I/n^2) cos / r^2
 * converges to (I / A) times the integral of cos / r^2 over it; for a receiver parallel to the light
 * that integral is the solid angle the rectangle subtends, known in closed form.
 */
class AreaLightTest {

    static AreaLight light(double w, double d, double h, int n) {
        AreaLight l = new AreaLight();
        l.position = new Vector3d(0, h, 0);
        l.edge1 = new Vector3d(w, 0, 0);
        l.edge2 = new Vector3d(0, 0, d);
        l.intensity = new Vector3d(10, 20, 30);
        l.samples = n;
        l.init();
        return l;
    }

    static IntersectionRecord floorAt(double x, double z) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(x, 0, z);
        rec.normal.set(0, 1, 0);
        return rec;
    }

    /**
     * sum over samples of intensity.x * max(0, n.l): what a Diffuse material with k_d = 1 adds, for pixel
     * sample 0 of pixel (px, 0) of {@code sampler}.
     */
    static double irradiance(AreaLight l, IntersectionRecord rec, Sampler sampler, int px) {
        Scene s = new Scene();
        s.camera = new Camera();
        TraceContext.current(s).sample.start(sampler, px, 0, 0);
        LightSample out = new LightSample(TraceContext.current(s).sample);
        double e = 0;
        for (int k = 0; k < l.sampleCount(); k++) {
            if (l.sample(rec, s, k, out)) {
                e += out.intensity.x * Math.max(0, out.direction.y);
            }
        }
        return e;
    }

    /** Solid angle of the rectangle [x1, x2] x [z1, z2] at height h, seen from the origin of the floor. */
    static double solidAngle(double x1, double x2, double z1, double z2, double h) {
        return corner(x2, z2, h) - corner(x1, z2, h) - corner(x2, z1, h) + corner(x1, z1, h);
    }

    /** Signed solid angle of [0, a] x [0, b] at height h seen from below its corner (0, 0). */
    static double corner(double a, double b, double h) {
        return Math.atan(a * b / (h * Math.sqrt(a * a + b * b + h * h)));
    }

    /**
     * At every point the n x n estimate approaches (I / A) Omega, whichever sampler places the points in
     * their cells (grid: the centres, a midpoint rule); over a set of points the RMS relative error falls
     * with each doubling of n (one point's jittered error need not: that is noise), and is below 1e-3 at
     * n = 64.
     */
    @ParameterizedTest
    @ValueSource(strings = {"grid", "jittered", "sobol"})
    void irradianceConvergesToTheAnalyticSolidAngleFormula(String samplerName) {
        Sampler sampler = Sampler.create(samplerName, 1);
        try {
            assertConverges(sampler);
        } finally {
            TraceContext.current(new Scene()).sample.start(Sampler.create("grid", 1), 0, 0, 0);   // as outside a render
        }
    }

    private static void assertConverges(Sampler sampler) {
        double w = 2, d = 1.5, h = 1.2, area = w * d;
        int[] ns = {1, 2, 4, 8, 16, 32, 64};
        double[] rms = new double[ns.length];
        int points = 0;
        for (double x = -3; x <= 3; x += 0.75) {      // below the light, near its edges and well outside
            for (double z = -2; z <= 2; z += 0.8) {
                points++;
                double exact = 10 / area * solidAngle(-w / 2 - x, w / 2 - x, -d / 2 - z, d / 2 - z, h);
                for (int i = 0; i < ns.length; i++) {
                    double e = irradiance(light(w, d, h, ns[i]), floorAt(x, z), sampler, points) / exact - 1;
                    rms[i] += e * e;
                }
            }
        }
        for (int i = 0; i < ns.length; i++) {
            rms[i] = Math.sqrt(rms[i] / points);
        }
        String what = sampler.name() + ": RMS relative error for n = 1, 2, ..., 64: " + java.util.Arrays.toString(rms);
        for (int i = 1; i < ns.length; i++) {
            assertTrue(rms[i] < rms[i - 1], what);
        }
        assertTrue(rms[6] < 1e-3 && rms[6] < rms[3] / 10, what);
    }

    /** Sample k lies in cell (k mod n, k div n) and the same point gets the same samples every time. */
    @Test
    void samplesAreStratifiedOnePerCellAndDeterministic() {
        AreaLight l = light(2, 1, 3, 5);
        LightSample out = new LightSample(), again = new LightSample();
        Scene s = new Scene();
        for (int k = 0; k < 25; k++) {
            assertTrue(l.sample(floorAt(0.3, 0.2), s, k, out));
            double u = (out.position.x + 1) / 2 * 5, v = (out.position.z + 0.5) * 5;   // cell coordinates
            assertEquals(k % 5, (int) Math.floor(u), "cell column of sample " + k + " at " + out.position);
            assertEquals(k / 5, (int) Math.floor(v), "cell row of sample " + k + " at " + out.position);
            assertEquals(3, out.position.y, 0);
            l.sample(floorAt(0.3, 0.2), s, k, again);
            assertEquals(out.position, again.position);
        }
    }

    static Image render(String text, int threads) throws SceneFormatException {
        return new Renderer(Parser.parse(text, "area.txt", new ArrayList<>())).threads(threads).render();
    }

    /**
     * An area light shrunk to a point renders as the point light. With zero-length edges every sample is
     * the point light divided by n^2 exactly (n^2 = 16 is a power of two), and the n^2 terms add up to it
     * within a few ulps of the sum; with edges of 1e-7 each sample moves by at most 1e-7 of r = 4.
     */
    @Test
    void areaLightShrunkToAPointRendersAsThePointLight() throws SceneFormatException {
        String at = "Vector3d position [2 3 1]\nVector3d intensity [20 18 15]\n";
        double[] point = render(SpotLightTest.SCENE + "Light PointLight\n" + at, 2).rgb;
        for (String size : new String[] {"0", "1e-7"}) {
            double[] area = render(SpotLightTest.SCENE + "Light AreaLight\n" + at + "Vector3d edge1 [" + size + " 0 0]\nVector3d edge2 [0 "
                    + size + " " + size + "]\n", 2).rgb;
            double tolerance = size.equals("0") ? 1e-13 : 1e-6;
            for (int i = 0; i < point.length; i++) {
                assertEquals(point[i], area[i], tolerance * Math.max(1, point[i]), "edges " + size + ", value " + i);
            }
        }
    }

    /**
     * A large area light, its points jittered in their cells by the jittered sampler: the same image on 1
     * and 3 threads, and soft, not hard, shadows (not the point light).
     */
    @Test
    void sameImageForAnyThreadCount() throws SceneFormatException {
        String light = "Light AreaLight\nVector3d position [2 3 1]\nVector3d edge1 [1.5 0 0]\nVector3d edge2 [0 0 1.5]\n"
                + "Vector3d intensity [20 18 15]\nint samples 3\n";
        Image one = render("Sampler jittered\n" + SpotLightTest.SCENE + light, 1), three = render("Sampler jittered\n" + SpotLightTest.SCENE + light, 3);
        assertArrayEquals(one.rgb, three.rgb);
        double[] point = render(SpotLightTest.SCENE + "Light PointLight\nVector3d position [2 3 1]\nVector3d intensity [20 18 15]\n", 1).rgb;
        assertTrue(!java.util.Arrays.equals(point, one.rgb));
    }

    /** Each sample whose light is in front of the surface costs one shadow ray. */
    @Test
    void eachSampleIsOneShadowRay() throws SceneFormatException {
        String text = """
                Width 1
                Height 1

                Camera Camera
                Vector3d eye [0 0 5]

                Material Diffuse white

                Surface Triangle
                Vector3d v0 [-10 -10 0]
                Vector3d v1 [10 -10 0]
                Vector3d v2 [0 10 0]
                ref material white

                Light AreaLight
                Vector3d position [0 0 2]
                Vector3d edge1 [1 0 0]
                Vector3d edge2 [0 1 0]
                int samples 3
                """;
        Renderer r = new Renderer(Parser.parse(text, "count.txt", new ArrayList<>())).threads(1);
        r.render();
        assertEquals(9, r.stats().get(RayKind.SHADOW));
    }

    @Test
    void badFieldsAreRejectedWithTheirLine() {
        String[][] cases = {
                {"int samples 0", "samples must be from 1 to 64 (n x n shadow rays per point), got 0"},
                {"int samples 65", "samples must be from 1 to 64"},
        };
        for (String[] c : cases) {
            ObjectErrors.assertRefused("Light AreaLight", c[0], c[1]);
        }
    }
}
