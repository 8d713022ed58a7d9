package ray.light;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.ObjectErrors;
import ray.parse.SceneFormatException;
import ray.render.Image;

/** I max(0, cos t)^e / r^2 inside the cone, nothing outside; (180, 0) is a point light exactly. */
class SpotLightTest {

    static SpotLight spot(Vector3d position, Vector3d direction, double cutoff, double exponent) {
        SpotLight s = new SpotLight();
        s.position = position;
        s.direction = direction;
        s.intensity = new Vector3d(25, 50, 75);
        s.cutoffAngle = cutoff;
        s.exponent = exponent;
        s.init();
        return s;
    }

    static IntersectionRecord at(double x, double y, double z) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(x, y, z);
        rec.normal.set(0, 0, 1);
        return rec;
    }

    static Scene empty() {
        Scene s = new Scene();
        s.camera = new Camera();
        return s;
    }

    /** A light 5 above the origin pointing down: a point at horizontal distance x is at angle atan(x/5). */
    @Test
    void falloffIsCosineToTheExponentOverRSquared() {
        SpotLight s = spot(new Vector3d(0, 0, 5), new Vector3d(0, 0, -2), 40, 3);
        LightSample out = new LightSample();
        for (double x : new double[] {0, 1, 2.5, 4}) {   // 0, 11.3, 26.6, 38.7 degrees: inside the cone
            assertTrue(s.sample(at(x, 0, 0), empty(), 0, out), "x " + x);
            double r2 = 25 + x * x, cos = 5 / Math.sqrt(r2);
            assertEquals(25 * Math.pow(cos, 3) / r2, out.intensity.x, 1e-12, "x " + x);
            assertEquals(75 * Math.pow(cos, 3) / r2, out.intensity.z, 1e-12, "x " + x);
            assertFalse(out.shadowTested, "a spot light's samples still need a shadow ray");
        }
        assertFalse(s.sample(at(4.3, 0, 0), empty(), 0, out), "40.7 degrees: outside the 40-degree cone");
        assertFalse(s.sample(at(0, 0, 6), empty(), 0, out), "behind the light");
        // exactly on the cone's edge counts as inside (t > cutoffAngle is cut), up to the cosine's rounding
        SpotLight edge = spot(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1), 45, 0);
        assertTrue(edge.sample(at(4.999999, 0, 0), empty(), 0, out));
        assertFalse(edge.sample(at(5.000001, 0, 0), empty(), 0, out));
    }

    /** Seeded: with cutoff 180 and exponent 0, every sample equals the point light's bit for bit. */
    @Test
    void wideOpenSpotSamplesArePointLightSamples() {
        long seed = 9_180L;
        Random rnd = new Random(seed);
        LightSample a = new LightSample(), b = new LightSample();
        for (int i = 0; i < 5_000; i++) {
            double scale = Math.pow(10, -4 + 8 * rnd.nextDouble());
            Vector3d p = new Vector3d(scale * rnd.nextGaussian(), scale * rnd.nextGaussian(), scale * rnd.nextGaussian());
            Vector3d d = new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            PointLight point = new PointLight();
            point.position = new Vector3d(p);
            point.intensity = new Vector3d(25, 50, 75);
            point.init();
            SpotLight s = spot(new Vector3d(p), d, 180, 0);
            IntersectionRecord rec = at(scale * rnd.nextGaussian(), scale * rnd.nextGaussian(), scale * rnd.nextGaussian());
            String what = "seed " + seed + " case " + i;
            boolean lit = point.sample(rec, empty(), 0, a);
            assertEquals(lit, s.sample(rec, empty(), 0, b), what);
            if (lit) {
                assertEquals(a.intensity, b.intensity, what);
                assertEquals(a.direction, b.direction, what);
                assertEquals(a.distance, b.distance, what);
            }
        }
    }

    static final String SCENE = """
            Width 48
            Height 36
            AmbientLight [0.1 0.1 0.1]

            Camera Camera
            Vector3d eye [0 2 6]
            Vector3d target [0 0 0]

            Material BlinnPhong shiny
            Vector3d ambientColor [0.2 0.1 0.1]
            Vector3d diffuseColor [0.7 0.3 0.2]

            Material Glazed mirror
            ref base shiny
            double mirrorCoefficient 0.4

            Surface Sphere
            Vector3d center [-0.8 0 0]
            double radius 1
            ref material mirror

            Surface Sphere
            Vector3d center [1.2 -0.4 1]
            double radius 0.6
            ref material shiny

            Surface Triangle
            Vector3d v0 [-10 -1 -10]
            Vector3d v1 [0 -1 10]
            Vector3d v2 [10 -1 -10]
            ref material shiny

            """;

    /** A whole scene lit by the wide-open spot renders bit-identical to the same scene lit by a point light. */
    @Test
    void wideOpenSpotRendersExactlyAsPointLight() throws SceneFormatException {
        String light = "Vector3d position [2 4 3]\nVector3d intensity [20 18 15]\n";
        Image point = render(SCENE + "Light PointLight\n" + light);
        for (String dir : new String[] {"[0 0 -1]", "[0 -1 0]", "[0 1 0]", "[1e-3 7 -2]"}) {
            Image spot = render(SCENE + "Light SpotLight\n" + light + "Vector3d direction " + dir
                    + "\ndouble cutoffAngle 180\ndouble exponent 0\n");
            assertArrayEquals(point.rgb, spot.rgb, "direction " + dir);
        }
        // and a narrower cone does change it, so the comparison can fail
        Image narrow = render(SCENE + "Light SpotLight\n" + light + "Vector3d direction [-2 -4 -3]\ndouble cutoffAngle 20\n");
        assertFalse(java.util.Arrays.equals(point.rgb, narrow.rgb));
    }

    static Image render(String text) throws SceneFormatException {
        return new ray.render.Renderer(Parser.parse(text, "spot.txt", new ArrayList<>())).render();
    }

    @Test
    void badFieldsAreRejectedWithTheirLine() {
        String[][] cases = {
                {"Vector3d direction [0 0 0]", "spot light direction must be a finite vector of non-zero length"},
                {"double cutoffAngle 0", "cutoffAngle must be in (0, 180] degrees, got 0.0"},
                {"double cutoffAngle 190", "cutoffAngle must be in (0, 180] degrees, got 190.0"},
                {"double exponent -1", "exponent must be a finite number >= 0, got -1.0"},
        };
        for (String[] c : cases) {
            ObjectErrors.assertRefused("Light SpotLight", c[0], c[1]);
        }
    }
}
