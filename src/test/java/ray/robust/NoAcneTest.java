package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.num;
import static ray.robust.RobustSupport.vec;

import javax.vecmath.Vector3d;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.light.PointLight;
import ray.render.Image;

/**
 * No shadow acne on a large flat floor lit at a grazing angle (n.l about 0.02), the classic worst case
 * for self-intersection: the floor is a sphere of radius 1e4 (flat at this view), two triangles 2e3
 * across, or those triangles back to back with copies wound the other way (a two-sided floor: coincident
 * surfaces, where a shadow ray leaving the top must not hit the downward-facing copy), at scales 1e-4 to 1e4 and moved a million scene units away (and, as the property tests'
 * range, at 1e-6 and at 1e6 moved 1e12 away). Nothing else is in the scene,
 * so no point of the floor is in shadow: every floor pixel must be exactly the unshadowed
 * {@code k_a I_a + k_d (I / r^2) max(0, n.l)} of scene-format.md, evaluated here at the camera ray's hit.
 */
class NoAcneTest {

    private static final int W = 96, H = 72;

    private static String scene(String floor, double s, double t) {
        StringBuilder b = new StringBuilder("Width " + W + "\nHeight " + H + "\nAmbientLight [0.05 0.05 0.05]\nBGColor [0 0 1]\n\n");
        b.append("Camera Camera\nVector3d eye ").append(vec(t, s * 1.5 + t, s * 6 + t)).append("\nVector3d target ")
                .append(vec(t, t, -10 * s + t)).append("\nVector3d up [0 1 0]\ndouble yFOV 50\n\n");
        b.append("Material Diffuse floorMat\nVector3d ambientColor [1 1 1]\nVector3d diffuseColor [0.8 0.8 0.8]\n\n");
        if (floor.equals("sphere")) {
            double r = 1e4;
            b.append("Surface Sphere\nVector3d center ").append(vec(t, -r * s + t, t)).append("\ndouble radius ")
                    .append(num(r * s)).append("\nref material floorMat\n\n");
        } else {
            double e = 1e3;
            if (floor.equals("two-sided")) {
                // the same two triangles wound the other way: a floor seen from below too, back to back
                b.append("Surface Triangle\nVector3d v0 ").append(vec(-e * s + t, t, -e * s + t)).append("\nVector3d v1 ")
                        .append(vec(e * s + t, t, e * s + t)).append("\nVector3d v2 ").append(vec(-e * s + t, t, e * s + t))
                        .append("\nref material floorMat\n\n");
                b.append("Surface Triangle\nVector3d v0 ").append(vec(-e * s + t, t, -e * s + t)).append("\nVector3d v1 ")
                        .append(vec(e * s + t, t, -e * s + t)).append("\nVector3d v2 ").append(vec(e * s + t, t, e * s + t))
                        .append("\nref material floorMat\n\n");
            }
            b.append("Surface Triangle\nVector3d v0 ").append(vec(-e * s + t, t, -e * s + t)).append("\nVector3d v1 ")
                    .append(vec(-e * s + t, t, e * s + t)).append("\nVector3d v2 ").append(vec(e * s + t, t, e * s + t))
                    .append("\nref material floorMat\n\n");
            b.append("Surface Triangle\nVector3d v0 ").append(vec(-e * s + t, t, -e * s + t)).append("\nVector3d v1 ")
                    .append(vec(e * s + t, t, e * s + t)).append("\nVector3d v2 ").append(vec(e * s + t, t, -e * s + t))
                    .append("\nref material floorMat\n\n");
        }
        // height 1 at 60 units: n.l ~ 0.017; I chosen so the lit floor is ~0.5
        double i = 1.3e5 * s * s;
        b.append("Light PointLight\nVector3d position ").append(vec(-60 * s + t, s + t, -15 * s + t))
                .append("\nVector3d intensity ").append(vec(i, i, i)).append("\n\n");
        return b.toString();
    }

    /**
     * Trap: shadow acne, the speckled self-shadowing of a surface by its own shadow rays when the spawn
     * offset is smaller than the hit point's rounding error (a fixed epsilon at large scale or far from
     * the origin, or no offset at all), worst at grazing light where a tiny error along the normal is a
     * long way along the shadow ray.
     */
    @ParameterizedTest(name = "{0} floor, scale {1}, translation {2}")
    @CsvSource({"sphere, 1e-4, 0", "sphere, 1, 0", "sphere, 1e4, 0", "sphere, 1e-4, 100", "sphere, 1, 1e6", "sphere, 1e4, 1e10",
        "sphere, 1e-6, 0", "sphere, 1e6, 1e12",
        "triangles, 1e-4, 0", "triangles, 1, 0", "triangles, 1e4, 0", "triangles, 1, 1e6", "triangles, 1e4, 1e10", "triangles, 1e6, 1e12",
        "two-sided, 1e-4, 0", "two-sided, 1, 0", "two-sided, 1e4, 1e10"})
    void grazingLightOnLargeFloorHasNoAcne(String floor, double s, double t) {
        Scene scene = RobustSupport.parse(scene(floor, s, t), "floor.txt");
        Image img = RobustSupport.render(scene);
        Vector3d light = ((PointLight) scene.lights.get(0)).position;
        Vector3d intensity = ((PointLight) scene.lights.get(0)).intensity;
        int floorPixels = 0, dark = 0, wrong = 0;
        String first = null;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                Ray ray = scene.camera.getRayThrough(x + 0.5, y + 0.5, W, H);
                IntersectionRecord rec = new IntersectionRecord();
                if (!scene.intersect(ray, rec)) {
                    continue;
                }
                floorPixels++;
                // the unshadowed value: k_a I_a + k_d (I / r^2) max(0, n.l), k_a = 1, I_a = 0.05, k_d = 0.8
                Vector3d l = RobustSupport.sub(light, rec.location);
                double r2 = l.lengthSquared();
                l.normalize();
                double expected = 0.05 + 0.8 * intensity.x / r2 * Math.max(0, rec.normal.dot(l));
                int want = Image.toByte(expected), got = RobustSupport.byteAt(img, y * W + x, 0);
                if (got < want - 1) {
                    dark++;
                }
                if (Math.abs(got - want) > 1) {
                    wrong++;
                    if (first == null) {
                        first = "pixel (" + x + ", " + y + "): " + got + ", expected " + want;
                    }
                }
            }
        }
        assertTrue(floorPixels > W * H / 3, "the floor covers too little of the image: " + floorPixels);
        assertEquals(0, dark, dark + " acne pixels (" + String.format("%.1f%%", 100.0 * dark / floorPixels) + " of the "
                + floorPixels + " floor pixels darker than the unshadowed value); first: " + first);
        assertEquals(0, wrong, wrong + " floor pixels off the unshadowed value; first: " + first);
    }
}
