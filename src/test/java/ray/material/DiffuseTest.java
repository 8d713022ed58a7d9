package ray.material;

import static ray.material.ShadingFixture.assertColor;
import static ray.material.ShadingFixture.assertFormsAgree;
import static ray.material.ShadingFixture.fast;
import static ray.material.ShadingFixture.light;
import static ray.material.ShadingFixture.record;
import static ray.material.ShadingFixture.scene;
import static ray.material.ShadingFixture.v;
import static ray.material.ShadingFixture.viewRay;

import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.light.PointLight;

/**
 * L = k_a I_a + sum k_d (I / r^2) max(0, n.l), with k_a = (0.1, 0.2, 0.3), I_a = (0.5, 0.5, 1) and
 * k_d = (0.8, 0.4, 0.2). The light at (0, 3, 4) is at r = 5 with l = (0, 0.6, 0.8), so n.l = 0.8;
 * I = (25, 50, 75) gives I / r^2 = (1, 2, 3).
 */
class DiffuseTest {

    private static Diffuse material() {
        Diffuse d = new Diffuse();
        d.ambientColor = v(0.1, 0.2, 0.3);
        d.diffuseColor = v(0.8, 0.4, 0.2);
        d.init();
        return d;
    }

    private static Scene sceneWith(PointLight... lights) {
        return scene(v(0.5, 0.5, 1), lights);
    }

    @Test
    void ambientPlusLambertFromColouredLight() {
        Scene s = sceneWith(light(0, 3, 4, 25, 50, 75));
        // (0.05 + 0.8*1*0.8, 0.1 + 0.4*2*0.8, 0.3 + 0.2*3*0.8)
        assertColor(0.69, 0.74, 0.78, fast(material(), viewRay(), record(), s), "lit");
        assertFormsAgree(material(), viewRay(), record(), s);
    }

    @Test
    void lightBehindSurfaceGivesAmbientOnly() {
        Scene s = sceneWith(light(0, 3, -4, 25, 50, 75));
        assertColor(0.05, 0.1, 0.3, fast(material(), viewRay(), record(), s), "n.l = -0.8");
    }

    @Test
    void lightInTangentPlaneGivesAmbientOnly() {
        Scene s = sceneWith(light(5, 0, 0, 25, 50, 75));
        assertColor(0.05, 0.1, 0.3, fast(material(), viewRay(), record(), s), "n.l = 0");
    }

    /** Twice as far: I / r^2 = (25, 50, 75) / 100, a quarter of the diffuse term. */
    @Test
    void intensityFallsOffAsInverseSquare() {
        Scene s = sceneWith(light(0, 6, 8, 25, 50, 75));
        // (0.05 + 0.8*0.25*0.8, 0.1 + 0.4*0.5*0.8, 0.3 + 0.2*0.75*0.8)
        assertColor(0.21, 0.26, 0.42, fast(material(), viewRay(), record(), s), "r = 10");
    }

    @Test
    void lightsAddUp() {
        Scene s = sceneWith(light(0, 3, 4, 25, 50, 75), light(0, 6, 8, 25, 50, 75), light(0, 0, -3, 9, 9, 9));
        assertColor(0.05 + 0.64 + 0.16, 0.1 + 0.64 + 0.16, 0.3 + 0.48 + 0.12,
                fast(material(), viewRay(), record(), s), "two lights in front, one behind");
    }

    /** A red light on a surface that reflects no red: only ambient remains. */
    @Test
    void colouredLightIsFilteredPerChannel() {
        Diffuse green = new Diffuse();
        green.diffuseColor = v(0, 1, 0);
        Scene s = sceneWith(light(0, 0, 2, 40, 0, 0));
        assertColor(0, 0, 0, fast(green, viewRay(), record(), s), "red light, green surface");
    }

    /** The viewer's position does not matter to a diffuse surface. */
    @Test
    void viewDirectionDoesNotMatter() {
        Scene s = sceneWith(light(0, 3, 4, 25, 50, 75));
        ray.Ray oblique = new ray.Ray(v(4, 0, 3), v(-4, 0, -3));
        assertColor(0.69, 0.74, 0.78, fast(material(), oblique, record(), s), "oblique");
    }

    @Test
    void noLightsGiveAmbientOnly() {
        assertColor(0.05, 0.1, 0.3, fast(material(), viewRay(), record(), sceneWith()), "no lights");
    }
}
