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
import ray.Ray;
import ray.Scene;

/**
 * L = k_a I_a + sum [k_d (I/r^2) max(0, n.l) + k_s (I/r^2) max(0, n.h)^p]. Viewer along +z, light at
 * (0, 3, 4): l = (0, 0.6, 0.8), h = normalize(0, 0.6, 1.8), n.h = 1.8 / sqrt(3.6), (n.h)^2 = 0.9
 * exactly. k_a I_a = (0.05, 0.1, 0.3), k_d (I/r^2) n.l = (0.64, 0.64, 0.48), k_s = (1, 0.5, 0.25),
 * I / r^2 = (1, 2, 3) so k_s I / r^2 = (1, 1, 0.75).
 */
class BlinnPhongTest {

    private static BlinnPhong material(double exponent) {
        BlinnPhong m = new BlinnPhong();
        m.ambientColor = v(0.1, 0.2, 0.3);
        m.diffuseColor = v(0.8, 0.4, 0.2);
        m.specularColor = v(1, 0.5, 0.25);
        m.exponent = exponent;
        m.init();
        return m;
    }

    private static Scene lit(double x, double y, double z) {
        return scene(v(0.5, 0.5, 1), light(x, y, z, 25, 50, 75));
    }

    @Test
    void diffusePlusHighlightWithExponentTwo() {
        Scene s = lit(0, 3, 4);
        assertColor(0.05 + 0.64 + 0.9, 0.1 + 0.64 + 0.9, 0.3 + 0.48 + 0.75 * 0.9,
                fast(material(2), viewRay(), record(), s), "p = 2");
        assertFormsAgree(material(2), viewRay(), record(), s);
    }

    @Test
    void exponentSharpensHighlight() {
        Scene s = lit(0, 3, 4);
        assertColor(0.05 + 0.64 + 0.81, 0.1 + 0.64 + 0.81, 0.3 + 0.48 + 0.75 * 0.81,
                fast(material(4), viewRay(), record(), s), "p = 4: 0.9^2");
        double k = Math.pow(0.9, 25);
        assertColor(0.05 + 0.64 + k, 0.1 + 0.64 + k, 0.3 + 0.48 + 0.75 * k,
                fast(material(50), viewRay(), record(), s), "p = 50: 0.9^25");
        assertColor(0.05 + 0.64 + 1, 0.1 + 0.64 + 1, 0.3 + 0.48 + 0.75,
                fast(material(0), viewRay(), record(), s), "p = 0: max(0, n.h)^0 = 1");
    }

    /** Light straight above along the mirror direction: h = n, the highlight is k_s I / r^2 for any p. */
    @Test
    void mirrorDirectionGivesFullHighlight() {
        Scene s = scene(v(0.5, 0.5, 1), light(0, 0, 5, 25, 25, 25));
        assertColor(0.05 + 0.8 + 1, 0.1 + 0.4 + 0.5, 0.3 + 0.2 + 0.25,
                fast(material(200), viewRay(), record(), s), "n.l = n.h = 1");
    }

    /**
     * The light just below the surface's plane: n.l < 0 but the half vector still leans to the
     * normal (n.h > 0). The contract: a light behind the surface adds nothing, highlight included.
     */
    @Test
    void lightBehindSurfaceAddsNoHighlight() {
        Scene s = lit(0, 3, -0.1);
        assertColor(0.05, 0.1, 0.3, fast(material(2), viewRay(), record(), s), "light behind");
        assertFormsAgree(material(2), viewRay(), record(), s);
    }

    /** Viewer at (4, 0, 3): v = (0.8, 0, 0.6); h ~ (0.8, 0.6, 1.4), (n.h)^2 = 1.96 / 2.96. */
    @Test
    void obliqueViewerMovesHighlight() {
        Scene s = lit(0, 3, 4);
        Ray oblique = new Ray(v(4, 0, 3), v(-4, 0, -3));
        double k = 1.96 / 2.96;
        assertColor(0.05 + 0.64 + k, 0.1 + 0.64 + k, 0.3 + 0.48 + 0.75 * k,
                fast(material(2), oblique, record(), s), "oblique viewer");
    }

    @Test
    void unnormalisedViewDirectionGivesSameColour() {
        Scene s = lit(0, 3, 4);
        Ray longer = new Ray(v(0, 0, 5), v(0, 0, -7));
        assertColor(0.05 + 0.64 + 0.9, 0.1 + 0.64 + 0.9, 0.3 + 0.48 + 0.75 * 0.9,
                fast(material(2), longer, record(), s), "|d| = 7");
    }

    @Test
    void inverseSquareAppliesToHighlightToo() {
        Scene s = scene(v(0.5, 0.5, 1), light(0, 6, 8, 25, 50, 75));   // r^2 = 100: a quarter
        assertColor(0.05 + 0.16 + 0.25 * 0.9, 0.1 + 0.16 + 0.25 * 0.9, 0.3 + 0.12 + 0.1875 * 0.9,
                fast(material(2), viewRay(), record(), s), "r = 10");
    }
}
