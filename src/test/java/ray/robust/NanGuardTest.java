package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.forEachSeed;
import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.unit;
import static ray.robust.RobustSupport.vec;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.light.PointLight;
import ray.material.BlinnPhong;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;

/**
 * No NaN or infinity reaches a pixel or a shading result: lights on surfaces and at the shading point,
 * zero-length directions, coincident surfaces, facing mirrors; and the camera set-ups that have no
 * defined frame are refused at load with the line named.
 */
class NanGuardTest {

    private static boolean finite(Vector3d v) {
        return Double.isFinite(v.x) && Double.isFinite(v.y) && Double.isFinite(v.z);
    }

    /**
     * Trap: l = (light - p) / |light - p| and I / r^2 with r = 0 (0 / 0 = NaN, I / 0 = infinity) when a
     * light sits exactly at the shading point, or overflow when it is 1e-160 away. The framework's
     * shade() on a hand-built record must give the ambient term alone at r = 0 and finite values at any r.
     */
    @Test
    void lightAtTheShadingPointGivesFiniteShading() {
        Scene scene = RobustSupport.scene(List.of());
        scene.ambientLight.set(0.5, 0.5, 0.5);
        BlinnPhong m = new BlinnPhong();
        m.ambientColor.set(0.2, 0.4, 0.6);
        m.init();
        PointLight light = new PointLight();
        light.intensity.set(3, 3, 3);
        scene.lights.add(light);
        Ray ray = new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1));
        for (double dist : new double[] {0, 1e-320, 1e-200, 1e-160, 1e-150, 1e-100, 1e-8, 1}) {
            IntersectionRecord rec = new IntersectionRecord();
            rec.location.set(1, 2, 0);
            rec.normal.set(0, 0, 1);
            rec.t = 5;
            light.position.set(1, 2, dist);
            Vector3d c = m.shade(ray, rec, scene);
            assertTrue(finite(c), "light " + dist + " from the shading point gave " + c);
            if (dist == 0) {
                // k_a I_a only: the light has no direction and no finite amount (scene-format: no contribution)
                assertEquals(new Vector3d(0.1, 0.2, 0.3), c, "light at the shading point");
            }
        }
    }

    /**
     * Trap: a zero-length direction: 1 / 0 in the slab test and the triangle set-up, 0 / 0 in the
     * normalisation of the sphere's quadratic. Tracing it returns the background and hits nothing.
     */
    @Test
    void zeroLengthDirectionHitsNothing() {
        Scene scene = RobustSupport.parse(InvarianceTest.scene(1, 0, 0, 0), "scene.txt");
        scene.prepare();
        for (Vector3d o : new Vector3d[] {new Vector3d(0, 1, 0), new Vector3d(0.4, 2.2, 7), new Vector3d(0, 0, 0), new Vector3d(-20, 0, -20)}) {
            for (Vector3d d : new Vector3d[] {new Vector3d(0, 0, 0), new Vector3d(-0.0, 0.0, -0.0)}) {
                Ray ray = new Ray(o, d);
                ray.tMin = 0;
                Vector3d c = scene.trace(ray);
                assertEquals(scene.backgroundColor, c, "zero direction from " + o);
                assertFalse(scene.intersect(ray, new IntersectionRecord()), "zero direction from " + o + " hit something");
                assertFalse(scene.occluded(ray), "zero direction from " + o + " is occluded");
            }
        }
    }

    /**
     * Trap: a light exactly on a surface: n.l = 0 on that surface (0 * infinity if r is 0 as well), and
     * shadow rays end on the surface. Lights on a sphere, at a floor vertex and inside the floor: no NaN
     * or infinite sample; a floor point that sees the light on the sphere from outside is lit by it
     * (the surface a light sits on does not shadow it), while the lights in the floor's plane add
     * nothing there (n.l = 0).
     */
    @Test
    void lightsExactlyOnSurfacesRenderFinite() {
        String text = "Width 64\nHeight 48\nAmbientLight [0.1 0.1 0.1]\n\nCamera Camera\nVector3d eye [0 1 6]\nVector3d target [0 0.5 0]\n\n"
                + "Material Diffuse m\nVector3d ambientColor [0.2 0.2 0.2]\nVector3d diffuseColor [0.7 0.7 0.7]\n\n"
                + "Material BlinnPhong b\nVector3d diffuseColor [0.3 0.6 0.3]\ndouble exponent 0\n\n"
                + "Surface Triangle\nVector3d v0 [-5 0 -5]\nVector3d v1 [-5 0 5]\nVector3d v2 [5 0 5]\nref material m\n\n"
                + "Surface Triangle\nVector3d v0 [-5 0 -5]\nVector3d v1 [5 0 5]\nVector3d v2 [5 0 -5]\nref material m\n\n"
                + "Surface Sphere\nVector3d center [0 1 0]\ndouble radius 1\nref material b\n\n"
                + "Light PointLight\nVector3d position [1 1 0]\nVector3d intensity [2 2 2]\n\n"          // on the sphere
                + "Light PointLight\nVector3d position [5 0 5]\nVector3d intensity [9 9 9]\n\n"          // a floor vertex
                + "Light PointLight\nVector3d position [-1.5 0 1]\nVector3d intensity [2 2 2]\n\n";     // inside the floor
        Scene scene = RobustSupport.parse(text, "lights-on-surfaces.txt");
        Image img = RobustSupport.render(scene);
        for (double v : img.rgb) {
            assertTrue(Double.isFinite(v), "non-finite pixel value " + v);
        }
        // floor point (3, 0, 1): k_a I_a + k_d (I / r^2) n.l for the light at (1, 1, 0): l = (-2, 1, -1), r^2 = 6
        Vector3d eye = scene.camera.eye;
        Ray ray = new Ray(eye, new Vector3d(3 - eye.x, 0 - eye.y, 1 - eye.z));
        ray.tMin = 0;
        Vector3d c = scene.trace(ray);
        double expected = 0.2 * 0.1 + 0.7 * 2 / 6 * (1 / Math.sqrt(6));
        assertEquals(expected, c.x, 1e-9, "floor point lit by the light sitting on the sphere");
    }

    /**
     * Trap: z-fighting between coincident surfaces turning into self-shadowing (a shadow ray from one
     * copy hitting the other) or NaN. Every surface of the invariance scene twice (spheres identical,
     * triangles with their vertices rotated): the image must equal the single scene's.
     */
    @Test
    void coincidentSurfacesRenderLikeOne() {
        String base = InvarianceTest.scene(1, 0, 0, 0);
        StringBuilder doubled = new StringBuilder(base);
        for (String block : base.split("\n\n")) {
            if (block.startsWith("Surface Sphere")) {
                doubled.append(block).append("\n\n");
            } else if (block.startsWith("Surface Triangle")) {
                String[] l = block.split("\n");
                // v0 v1 v2 -> v1 v2 v0: same triangle, same winding
                doubled.append(l[0]).append("\n").append(l[2].replace(" v1 ", " v0 ")).append("\n").append(l[3].replace(" v2 ", " v1 "))
                        .append("\n").append(l[1].replace(" v0 ", " v2 ")).append("\n").append(l[4]).append("\n\n");
            }
        }
        Scene one = RobustSupport.parse(base, "one.txt"), two = RobustSupport.parse(doubled.toString(), "two.txt");
        assertEquals(2 * one.surfaces.size(), two.surfaces.size());
        int bad = RobustSupport.pixelsDifferingByMoreThanOneStep(RobustSupport.render(one), RobustSupport.render(two));
        assertEquals(0, bad, bad + " pixels change when every surface is doubled");
    }

    /**
     * Trap: two mirrors facing each other: unbounded recursion (stack overflow) or a value that grows
     * without bound. One pixel looks straight at mirror A with mirror B behind the eye; each hit adds the
     * base's k_a I_a and the mirror ray is followed while depth < MaxDepth, so the pixel is exactly
     * k_a I_a (1 + k_m + ... + k_m^MaxDepth).
     */
    @ParameterizedTest(name = "MaxDepth {0}, k_m {1}")
    @CsvSource({"0, 0.9", "1, 0.9", "10, 0.9", "10, 1", "1000, 1", "1000, 0.5"})
    void facingMirrorsStopAtMaxDepth(int maxDepth, double km) {
        String text = "Width 1\nHeight 1\nMaxDepth " + maxDepth + "\nAmbientLight [1 1 1]\n\n"
                + "Camera Camera\nVector3d eye [0 0 0]\nVector3d target [0 0 -1]\n\n"
                + "Material Diffuse base\nVector3d ambientColor [0.0005 0.001 0.002]\nVector3d diffuseColor [0 0 0]\n\n"
                + "Material Glazed mirror\nref base base\ndouble mirrorCoefficient " + km + "\n\n"
                // A at z = -1 facing +z, B at z = +1 facing -z
                + "Surface Triangle\nVector3d v0 [-10 -10 -1]\nVector3d v1 [10 -10 -1]\nVector3d v2 [0 10 -1]\nref material mirror\n\n"
                + "Surface Triangle\nVector3d v0 [-10 -10 1]\nVector3d v1 [0 10 1]\nVector3d v2 [10 -10 1]\nref material mirror\n\n";
        Scene scene = RobustSupport.parse(text, "mirrors.txt");
        Image img = RobustSupport.render(scene);
        double sum = 0;
        for (int i = 0; i <= maxDepth; i++) {
            sum += Math.pow(km, i);
        }
        double[] ka = {0.0005, 0.001, 0.002};
        for (int k = 0; k < 3; k++) {
            assertEquals(ka[k] * sum, img.rgb[k], 1e-12 * sum, "channel " + k);
        }
    }

    /**
     * Trap: Camera frame u = normalize(up x w) is 0 / 0 when up is parallel to the view direction or zero,
     * and w is 0 / 0 when the eye is at the target: every pixel NaN. These are refused at load, naming
     * the file and the Camera's line.
     */
    @ParameterizedTest(name = "eye {0}, target {1}, up {2}")
    @CsvSource({"[0 0 5], [0 0 0], [0 0 1], parallel", "[0 0 5], [0 0 0], [0 0 -3], parallel",
        "[1 2 3], [2 4 6], [1 2 3], parallel", "[1e6 1e6 1e6], [1e6 1e6 1.000001e6], [0 0 1e-300], parallel",
        "[0 0 5], [0 0 0], [0 0 0], parallel", "[1 2 3], [1 2 3], [0 1 0], same point", "[0 0 0], [0 0 0], [0 1 0], same point"})
    void undefinedCameraFrameIsRefusedAtLoadNamingTheLine(String eye, String target, String up, String words) {
        String text = "Width 8\nHeight 6\n\n# a comment\nCamera Camera\nVector3d eye " + eye + "\nVector3d target " + target
                + "\nVector3d up " + up + "\n\n";
        SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(text, "cam.txt", new ArrayList<>()));
        assertTrue(e.getMessage().startsWith("cam.txt:5:"), "does not name the Camera's line: " + e.getMessage());
        assertTrue(e.getMessage().contains(words), "unclear message: " + e.getMessage());
    }

    /**
     * Trap: anything in the shading path producing NaN in odd configurations. Random small scenes at
     * random scales with lights on surfaces, at vertices and at sphere centres, coincident spheres,
     * mirrors and exponent-0 highlights: no NaN or infinite sample is ever produced.
     */
    @Test
    void randomScenesNeverProduceNaN() {
        forEachSeed(0x4a4aL, 40, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d t = unit(r);
            t.scale(s * logUniform(r, 1e-3, 1e6));
            StringBuilder b = new StringBuilder("Width 24\nHeight 18\nMaxDepth 6\nAmbientLight [0.1 0.1 0.1]\n\n");
            b.append("Camera Camera\nVector3d eye ").append(v(r, s, t, 6)).append("\nVector3d target ").append(v(t))
                    .append("\nVector3d up ").append(vec(r.nextGaussian(), r.nextGaussian() + 3, r.nextGaussian())).append("\n\n");
            b.append("Material BlinnPhong p\nVector3d ambientColor [0.1 0.1 0.1]\ndouble exponent ").append(r.nextInt(3) == 0 ? 0 : 30).append("\n\n");
            b.append("Material Glazed g\nref base p\ndouble mirrorCoefficient 0.9\n\n");
            List<Vector3d> points = new ArrayList<>();
            for (int i = 0; i < 6; i++) {
                String mat = r.nextBoolean() ? "p" : "g";
                if (r.nextBoolean()) {
                    Vector3d c = RobustSupport.add(t, s * 2 * r.nextDouble(), unit(r));
                    double rad = s * logUniform(r, 0.05, 2);
                    String block = "Surface Sphere\nVector3d center " + v(c) + "\ndouble radius " + rad + "\nref material " + mat + "\n\n";
                    b.append(block);
                    if (r.nextInt(4) == 0) {
                        b.append(block);        // a coincident copy
                    }
                    points.add(c);
                    points.add(RobustSupport.add(c, rad, unit(r)));
                } else {
                    Vector3d a = RobustSupport.add(t, s * 3 * r.nextDouble(), unit(r));
                    Vector3d c = RobustSupport.add(t, s * 3 * r.nextDouble(), unit(r));
                    Vector3d d = r.nextInt(5) == 0 ? new Vector3d(a) : RobustSupport.add(t, s * 3 * r.nextDouble(), unit(r));
                    b.append("Surface Triangle\nVector3d v0 ").append(v(a)).append("\nVector3d v1 ").append(v(c)).append("\nVector3d v2 ")
                            .append(v(d)).append("\nref material ").append(mat).append("\n\n");
                    points.add(a);
                    points.add(new Vector3d((a.x + c.x) / 2, (a.y + c.y) / 2, (a.z + c.z) / 2));
                }
            }
            for (int i = 0; i < 3; i++) {
                Vector3d p = r.nextBoolean() ? points.get(r.nextInt(points.size())) : RobustSupport.add(t, s * 4 * r.nextDouble(), unit(r));
                double in = s * s * logUniform(r, 1e-2, 1e2);
                b.append("Light PointLight\nVector3d position ").append(v(p)).append("\nVector3d intensity ").append(vec(in, in, in)).append("\n\n");
            }
            Scene scene;
            try {
                scene = Parser.parse(b.toString(), "random.txt", new ArrayList<>());
            } catch (SceneFormatException e) {
                assertTrue(e.getMessage().contains("parallel"), e.getMessage());   // only a degenerate random camera is refused
                return;
            }
            Image img = RobustSupport.render(scene);
            for (double x : img.rgb) {
                assertTrue(Double.isFinite(x), "non-finite pixel in\n" + b);
            }
        });
    }

    private static String v(Vector3d p) {
        return vec(p.x, p.y, p.z);
    }

    private static String v(Random r, double s, Vector3d t, double dist) {
        return v(RobustSupport.add(t, s * dist, unit(r)));
    }
}
