package ray.robust;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.num;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import ray.Scene;
import ray.render.Image;

/**
 * Scale and translation invariance: the same scene scaled by 1e-4 to 1e4 (light intensities by the
 * square, so I / r^2 is unchanged) or moved up to 1e6 units away renders the same image, to one 8-bit
 * step per channel on 99.9% of the pixels. The scene has what a fixed epsilon gets wrong: a sphere
 * resting on a floor (contact shadow), a mirror sphere (reflections of nearby surfaces), a thin gap
 * between a sphere and a wall, a light grazing the floor, shadows from a one-sided triangle.
 */
class InvarianceTest {

    private static final int W = 96, H = 72;

    /** The scene with every position p mapped to s p + t, radii to s r, intensities to s^2 I. */
    static String scene(double s, double tx, double ty, double tz) {
        StringBuilder b = new StringBuilder();
        b.append("Width " + W + "\nHeight " + H + "\nMaxDepth 4\nBGColor [0.1 0.12 0.2]\nAmbientLight [0.1 0.1 0.1]\n\n");
        java.util.function.BiFunction<String, double[], String> pt = (field, p) ->
                "Vector3d " + field + " " + RobustSupport.vec(s * p[0] + tx, s * p[1] + ty, s * p[2] + tz) + "\n";
        b.append("Camera Camera\n").append(pt.apply("eye", new double[] {0.4, 2.2, 7})).append(pt.apply("target", new double[] {0, 0.6, 0}))
                .append("Vector3d up [0 1 0]\ndouble yFOV 40\n\n");
        b.append("Material Diffuse floorMat\nVector3d ambientColor [0.3 0.3 0.3]\nVector3d diffuseColor [0.6 0.6 0.55]\n\n");
        b.append("Material BlinnPhong shiny\nVector3d ambientColor [0.1 0.1 0.2]\nVector3d diffuseColor [0.3 0.3 0.7]\n"
                + "Vector3d specularColor [0.8 0.8 0.8]\ndouble exponent 40\n\n");
        b.append("Material Glazed mirror\nref base shiny\ndouble mirrorCoefficient 0.6\n\n");
        b.append("Material Diffuse red\nVector3d ambientColor [0.2 0 0]\nVector3d diffuseColor [0.8 0.1 0.1]\n\n");
        // floor y = 0, two triangles facing +y
        triangle(b, pt, new double[] {-20, 0, -20}, new double[] {-20, 0, 20}, new double[] {20, 0, 20}, "floorMat");
        triangle(b, pt, new double[] {-20, 0, -20}, new double[] {20, 0, 20}, new double[] {20, 0, -20}, "floorMat");
        // a wall triangle facing the camera (+z), a sphere almost touching it (gap 0.01)
        triangle(b, pt, new double[] {1.0, 0, -2}, new double[] {3.5, 0, -2}, new double[] {2.2, 2.4, -2}, "red");
        sphere(b, pt, s, new double[] {2.2, 0.5, -1.49}, 0.5, "shiny");
        // a sphere resting on the floor, a mirror sphere, a small sphere
        sphere(b, pt, s, new double[] {0, 1, 0}, 1, "shiny");
        sphere(b, pt, s, new double[] {-2.2, 0.7, -1}, 0.7, "mirror");
        sphere(b, pt, s, new double[] {1.3, 0.3, 1.4}, 0.3, "red");
        light(b, pt, s, new double[] {4, 6, 3}, 30);
        light(b, pt, s, new double[] {-9, 0.6, 2.5}, 60);     // grazing the floor
        return b.toString();
    }

    private static void triangle(StringBuilder b, java.util.function.BiFunction<String, double[], String> pt,
                                 double[] v0, double[] v1, double[] v2, String mat) {
        b.append("Surface Triangle\n").append(pt.apply("v0", v0)).append(pt.apply("v1", v1)).append(pt.apply("v2", v2))
                .append("ref material " + mat + "\n\n");
    }

    private static void sphere(StringBuilder b, java.util.function.BiFunction<String, double[], String> pt, double s,
                               double[] c, double r, String mat) {
        b.append("Surface Sphere\n").append(pt.apply("center", c)).append("double radius " + num(s * r) + "\n")
                .append("ref material " + mat + "\n\n");
    }

    private static void light(StringBuilder b, java.util.function.BiFunction<String, double[], String> pt, double s,
                              double[] p, double intensity) {
        double i = intensity * s * s;
        b.append("Light PointLight\n").append(pt.apply("position", p))
                .append("Vector3d intensity " + RobustSupport.vec(i, i, i) + "\n\n");
    }

    private static Image original;

    private static synchronized Image original() {
        if (original == null) {
            original = RobustSupport.render(RobustSupport.parse(scene(1, 0, 0, 0), "original.txt"));
        }
        return original;
    }

    /**
     * Trap: fixed epsilons (an offset or tMin of 1e-4) are tuned for one scale. Scaled down, they jump
     * over the contact shadow under a resting sphere and through the gap to the wall; scaled up or far
     * from the origin, they are smaller than the rounding error and shadows turn to acne. Also any
     * absolute threshold in the camera, the BVH or the degenerate-triangle test.
     */
    @ParameterizedTest(name = "scale {0}, translation ({1}, {2}, {3})")
    @CsvSource({
        "1e-4, 0, 0, 0", "1e-2, 0, 0, 0", "0.37, 0, 0, 0", "3.3, 0, 0, 0", "1e2, 0, 0, 0", "1e4, 0, 0, 0",
        "1, 1e6, 0, 0", "1, 0, -1e6, 0", "1, 7e5, 7e5, -7e5", "1, -1e6, 1e6, 1e6", "1, 123456.789, -3.25, 987654.321",
        "1e-4, 100, -100, 100", "1e4, 1e10, 0, 0"})
    void sceneRendersTheSameScaledAndTranslated(double s, double tx, double ty, double tz) {
        Scene scene = RobustSupport.parse(scene(s, tx, ty, tz), "moved.txt");
        Image img = RobustSupport.render(scene);
        int bad = RobustSupport.pixelsDifferingByMoreThanOneStep(original(), img);
        int allowed = (int) Math.floor(0.001 * W * H);
        assertTrue(bad <= allowed, bad + " of " + W * H + " pixels (" + String.format("%.2f%%", 100.0 * bad / (W * H))
                + ") differ by more than one 8-bit step from the unmoved scene; at most " + allowed + " (0.1%) may");
    }
}
