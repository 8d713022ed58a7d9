package ray;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.PngWriter;

/**
 * Tiny scenes whose pixel values follow by hand from the formulas of scene-format.md. Most use a
 * 3 x 3 image with yFOV 90 seen from [0 0 5]: the centre pixel's ray is exactly -z through the
 * origin, and pixel (i, j)'s ray runs through (5 a, 5 b, 0) with a = (2 (i + 0.5) / 3 - 1) and
 * b = (1 - 2 (j + 0.5) / 3). Expected values are written as the formula they come from.
 */
class AnalyticPixelTest {

    static final double REL = 1e-9;

    static final String CAMERA_3X3 = """
            Width 3
            Height 3

            Camera Camera
            Vector3d eye [0 0 5]
            Vector3d target [0 0 0]
            Vector3d up [0 1 0]
            double yFOV 90

            """;

    /** A large triangle in the plane z = 0 whose front (+z) faces the camera. */
    static final String FRONT_TRIANGLE = """
            Surface Triangle
            Vector3d v0 [-10 -10 0]
            Vector3d v1 [10 -10 0]
            Vector3d v2 [0 10 0]
            ref material m

            """;

    static Scene parse(String text) throws SceneFormatException {
        return Parser.parse(text, "analytic.txt", new ArrayList<>());
    }

    static void assertColor(double r, double g, double b, Vector3d actual, String what) {
        double[] e = {r, g, b}, a = {actual.x, actual.y, actual.z};
        for (int i = 0; i < 3; i++) {
            double tol = REL * Math.max(1, Math.abs(e[i]));
            assertTrue(Math.abs(e[i] - a[i]) <= tol, what + ": expected (" + r + ", " + g + ", " + b + ") but got " + actual);
        }
    }

    static void assertBytes(int r, int g, int b, Vector3d v, String what) {
        assertArrayEquals(new int[] {r, g, b}, new int[] {Image.toByte(v.x), Image.toByte(v.y), Image.toByte(v.z)},
                what + ": 8-bit value of " + v);
    }

    // ---- diffuse, Blinn-Phong, shadows ----

    /** L = k_a I_a + k_d (I / r^2) n.l, head-on (n.l = 1, r = 2) at the centre and oblique at the left. */
    @Test
    void diffuseTriangleFacingPointLight() throws Exception {
        Scene s = parse(CAMERA_3X3 + """
                AmbientLight [0.5 0.5 0.5]

                Material Diffuse m
                Vector3d ambientColor [0.1 0.24 0.3]
                Vector3d diffuseColor [0.6 0.4 0.2]

                """ + FRONT_TRIANGLE + """
                Light PointLight
                Vector3d position [0 0 2]
                Vector3d intensity [2 2 2]
                """);
        // centre: hit (0, 0, 0), light 2 away along the normal: I / r^2 = 0.5, n.l = 1
        Vector3d centre = s.renderPixel(1, 1);
        assertColor(0.1 * 0.5 + 0.6 * 0.5, 0.24 * 0.5 + 0.4 * 0.5, 0.3 * 0.5 + 0.2 * 0.5, centre, "centre pixel");
        assertBytes(89, 82, 64, centre, "centre pixel");       // 0.35, 0.32, 0.25 -> 89.75, 82.1, 64.25 floored
        // pixel (0, 1): a = -2/3, hit (-10/3, 0, 0); r^2 = 100/9 + 4 = 136/9, n.l = 2 / r = 6 / sqrt(136)
        double k = 2 * 9.0 / 136 * (6 / Math.sqrt(136));
        assertColor(0.05 + 0.6 * k, 0.12 + 0.4 * k, 0.15 + 0.2 * k, s.renderPixel(0, 1), "left pixel, oblique light");
    }

    /** Light at the eye: the centre of a sphere facing the eye has n.l = n.h = 1 and r = 4. */
    @Test
    void sphereCentreWithLightAtEye() throws Exception {
        String rest = """
                AmbientLight [0.2 0.2 0.2]

                Surface Sphere
                Vector3d center [0 0 0]
                double radius 1
                ref material m

                Light PointLight
                Vector3d position [0 0 5]
                Vector3d intensity [16 8 4]
                """;
        // I / r^2 = (16, 8, 4) / 16 = (1, 0.5, 0.25); k_a I_a = 0.5 * 0.2 = 0.1
        Scene diffuse = parse(CAMERA_3X3 + """
                Material Diffuse m
                Vector3d ambientColor [0.5 0.5 0.5]
                Vector3d diffuseColor [0.5 0.6 0.82]

                """ + rest);
        Vector3d d = diffuse.renderPixel(1, 1);
        assertColor(0.1 + 0.5 * 1, 0.1 + 0.6 * 0.5, 0.1 + 0.82 * 0.25, d, "diffuse sphere centre");
        assertBytes(153, 102, 78, d, "diffuse sphere centre");  // 0.6, 0.4, 0.305 -> 153.5, 102.5, 78.3 floored

        Scene phong = parse(CAMERA_3X3 + """
                Material BlinnPhong m
                Vector3d ambientColor [0.5 0.5 0.5]
                Vector3d diffuseColor [0.5 0.6 0.82]
                Vector3d specularColor [0.24 0.22 0.2]
                double exponent 50

                """ + rest);
        Vector3d p = phong.renderPixel(1, 1);
        // + k_s (I / r^2) 1^p
        assertColor(0.6 + 0.24 * 1, 0.4 + 0.22 * 0.5, 0.305 + 0.2 * 0.25, p, "Blinn-Phong sphere centre");
        assertBytes(214, 130, 91, p, "Blinn-Phong sphere centre");  // 0.84, 0.51, 0.355 -> 214.7, 130.55, 91.0
    }

    /** A sphere between the light and the point leaves only the ambient term k_a I_a. */
    @Test
    void pointInShadowGetsAmbientOnly() throws Exception {
        String base = CAMERA_3X3 + """
                AmbientLight [0.5 0.4 0.2]

                Material Diffuse m
                Vector3d ambientColor [0.2 0.5 1]
                Vector3d diffuseColor [0.9 0.6 0.3]

                """ + FRONT_TRIANGLE + """
                Light PointLight
                Vector3d position [3 0 3]
                Vector3d intensity [9 9 9]

                """;
        String blocker = """
                Surface Sphere
                Vector3d center [1.5 0 1.5]
                double radius 0.3
                ref material m
                """;
        // lit: r^2 = 18, n.l = 3 / sqrt(18) = 1 / sqrt 2, I / r^2 = 0.5
        double k = 0.5 / Math.sqrt(2);
        assertColor(0.1 + 0.9 * k, 0.2 + 0.6 * k, 0.2 + 0.3 * k, parse(base).renderPixel(1, 1), "lit, no blocker");
        assertColor(0.1, 0.2, 0.2, parse(base + blocker).renderPixel(1, 1), "in the blocker's shadow");
    }

    /** Coloured light on a coloured material multiplies channel by channel: k_d (I / r^2) per channel. */
    @Test
    void colouredLightTimesColouredMaterialPerChannel() throws Exception {
        Scene s = parse(CAMERA_3X3 + """
                Material Diffuse m
                Vector3d diffuseColor [0.8 0.33 0.15]

                """ + FRONT_TRIANGLE + """
                Light PointLight
                Vector3d position [0 0 2]
                Vector3d intensity [4 8 12]
                """);
        Vector3d c = s.renderPixel(1, 1);
        // I / r^2 = (1, 2, 3)
        assertColor(0.8 * 1, 0.33 * 2, 0.15 * 3, c, "coloured light");
        assertBytes(204, 168, 115, c, "coloured light");   // 204.5, 168.8, 115.25 floored
    }

    // ---- mirrors ----

    /**
     * A mirror triangle in the plane y + z = 0 (normal (0, 1, 1) / sqrt 2) at the origin turns the
     * centre ray (0, 0, -1) into (0, 1, 0): straight up to a ceiling at y = 3 facing down. A light at
     * (0, 1, 0) lights the ceiling point head-on from r = 2 and the mirror point from r = 1 at
     * n.l = 1 / sqrt 2.
     */
    static String mirrorScene(int maxDepth, String mirrorMaterial, String ceilingMaterial) {
        return CAMERA_3X3 + """
                BGColor [0.3 0.6 0.9]
                AmbientLight [0.5 0.5 0.5]
                MaxDepth %d

                Material Diffuse wall
                Vector3d ambientColor [0.2 0.1 0.4]
                Vector3d diffuseColor [0.4 0.8 0.2]

                Material Diffuse mirrorBase
                Vector3d ambientColor [0.1 0.1 0.1]
                Vector3d diffuseColor [0.3 0.2 0.1]

                Material GlazedMaterial plain
                double mirrorCoefficient 0.5

                Material GlazedMaterial based
                ref base mirrorBase
                double mirrorCoefficient 0.5

                Material GlazedMaterial glazedWall
                ref base wall
                double mirrorCoefficient 0.5

                Surface Triangle
                Vector3d v0 [-5 -3 3]
                Vector3d v1 [5 -3 3]
                Vector3d v2 [0 3 -3]
                ref material %s

                Surface Triangle
                Vector3d v0 [-10 3 -10]
                Vector3d v1 [10 3 -10]
                Vector3d v2 [0 3 10]
                ref material %s

                Light PointLight
                Vector3d position [0 1 0]
                Vector3d intensity [4 4 4]
                """.formatted(maxDepth, mirrorMaterial, ceilingMaterial);
    }

    // the ceiling's diffuse value: k_a I_a + k_d (4 / 2^2) 1
    static final double[] WALL = {0.2 * 0.5 + 0.4, 0.1 * 0.5 + 0.8, 0.4 * 0.5 + 0.2};
    // the mirror base's value at the origin: k_a I_a + k_d (4 / 1) (1 / sqrt 2)
    static final double[] BASE = {0.05 + 0.3 * 4 / Math.sqrt(2), 0.05 + 0.2 * 4 / Math.sqrt(2), 0.05 + 0.1 * 4 / Math.sqrt(2)};

    /** Glazed without a base in front of a diffuse wall: the pixel is k_m times the wall's value. */
    @Test
    void mirrorWithoutBaseShowsKmTimesWall() throws Exception {
        Vector3d c = parse(mirrorScene(10, "plain", "wall")).renderPixel(1, 1);
        assertColor(0.5 * WALL[0], 0.5 * WALL[1], 0.5 * WALL[2], c, "k_m L_mirror");
    }

    /** Glazed with a base: base shading plus k_m times the mirrored wall. */
    @Test
    void mirrorWithBaseAddsBaseShading() throws Exception {
        Vector3d c = parse(mirrorScene(10, "based", "wall")).renderPixel(1, 1);
        assertColor(BASE[0] + 0.5 * WALL[0], BASE[1] + 0.5 * WALL[1], BASE[2] + 0.5 * WALL[2], c, "L_base + k_m L_mirror");
    }

    /** MaxDepth 0 follows no mirror ray: a base-less mirror is black (not the background), a based one its base. */
    @Test
    void maxDepthZeroShowsBasesOnly() throws Exception {
        assertColor(0, 0, 0, parse(mirrorScene(0, "plain", "wall")).renderPixel(1, 1), "base-less mirror, MaxDepth 0");
        assertColor(BASE[0], BASE[1], BASE[2], parse(mirrorScene(0, "based", "wall")).renderPixel(1, 1),
                "based mirror, MaxDepth 0");
    }

    /**
     * MaxDepth counts the bounces followed. The ceiling is a glazed wall too: its mirror ray goes back
     * down to the base-less mirror, which sends it out along +z to the background. With MaxDepth 1 or 2
     * the pixel is 0.5 wall-base (the ceiling's own ray, or the mirror's after it, is cut off); with 3
     * the background arrives after three bounces: 0.5 (base + 0.5 (0.5 BGColor)).
     */
    @ParameterizedTest
    @ValueSource(ints = {1, 2, 3})
    void bouncesBetweenTwoMirrorsStopAtMaxDepth(int maxDepth) throws Exception {
        Vector3d c = parse(mirrorScene(maxDepth, "plain", "glazedWall")).renderPixel(1, 1);
        double bg = maxDepth >= 3 ? 0.125 : 0;
        assertColor(0.5 * WALL[0] + bg * 0.3, 0.5 * WALL[1] + bg * 0.6, 0.5 * WALL[2] + bg * 0.9, c, "MaxDepth " + maxDepth);
    }

    // ---- geometry cases ----

    /**
     * Eye and light at the centre of a sphere: every camera ray meets the inside at r = 2 with the
     * normal turned to face the ray, so n.l = n.h = 1 and every pixel is k_a I_a + (k_d + k_s) I / 4.
     */
    @Test
    void cameraAndLightAtSphereCentreGiveUniformImage() throws Exception {
        Scene s = parse("""
                Width 8
                Height 6
                AASamples 2
                BGColor [1 0 1]
                AmbientLight [0.2 0.2 0.2]

                Camera Camera
                Vector3d eye [0 0 0]
                Vector3d target [0 0 -1]
                Vector3d up [0 1 0]
                double yFOV 60

                Material BlinnPhong m
                Vector3d ambientColor [0.5 0.5 0.5]
                Vector3d diffuseColor [0.1 0.2 0.05]
                Vector3d specularColor [0.11 0.055 0.115]
                double exponent 20

                Surface Sphere
                Vector3d center [0 0 0]
                double radius 2
                ref material m

                Light PointLight
                Vector3d position [0 0 0]
                Vector3d intensity [8 8 8]
                """);
        double r = 0.1 + (0.1 + 0.11) * 2, g = 0.1 + (0.2 + 0.055) * 2, b = 0.1 + (0.05 + 0.115) * 2;
        Vector3d[][] img = s.renderAll();
        assertEquals(8, img.length);
        assertEquals(6, img[0].length);
        for (int x = 0; x < 8; x++) {
            for (int y = 0; y < 6; y++) {
                assertColor(r, g, b, img[x][y], "pixel " + x + "," + y);
            }
        }
        // and in the PNG: 0.52, 0.61, 0.43 -> 133.1, 156.05, 110.15 floored
        BufferedImage png = new ray.render.Renderer(s).render().toBufferedImage();
        assertEquals(133 << 16 | 156 << 8 | 110, png.getRGB(5, 2) & 0xFFFFFF);
    }

    /** A triangle seen from behind is not hit: its pixels show BGColor; wound the other way it shows. */
    @Test
    void backFacingTriangleShowsBackground() throws Exception {
        String scene = CAMERA_3X3 + """
                BGColor [0.2 0.4 0.6]
                AmbientLight [1 1 1]

                Material Diffuse m
                Vector3d ambientColor [0.9 0.1 0.1]

                Surface Triangle
                Vector3d v0 [-10 -10 0]
                Vector3d v1 [%s 0]
                Vector3d v2 [%s 0]
                ref material m
                """;
        Scene back = parse(scene.formatted("0 10", "10 -10"));      // n = (10, 20, 0) x (20, 0, 0): -z
        Scene front = parse(scene.formatted("10 -10", "0 10"));     // n = +z, towards the camera
        for (int x = 0; x < 3; x++) {
            for (int y = 0; y < 3; y++) {
                assertEquals(new Vector3d(0.2, 0.4, 0.6), back.renderPixel(x, y), "back side, pixel " + x + "," + y);
            }
        }
        assertColor(0.9, 0.1, 0.1, front.renderPixel(1, 1), "front side");
    }

    // ---- anti-aliasing ----

    /**
     * AASamples 3 on a 4 x 4 image, yFOV 90: pixel (1, 1) has sub-pixel centres at image x, y in
     * {7/6, 3/2, 11/6}, i.e. world X, Y on z = 0 in {-25/12, -5/4, -5/12} and {25/12, 5/4, 5/12}.
     * An ambient-only triangle covering X > -1.5, Y < 0.75 catches 2 of the 9 (the bottom row's
     * middle and right samples), so the pixel is (2 k_a + 7 BGColor) / 9; its centre sample alone
     * misses.
     */
    @Test
    void edgePixelIsMeanOfNineSubPixelSamples() throws Exception {
        String scene = """
                Width 4
                Height 4
                AASamples %d
                BGColor [0 0.3 0.9]
                AmbientLight [1 1 1]

                Camera Camera
                Vector3d eye [0 0 5]
                Vector3d target [0 0 0]
                Vector3d up [0 1 0]
                double yFOV 90

                Material Diffuse m
                Vector3d ambientColor [0.9 0.6 0.3]

                Surface Triangle
                Vector3d v0 [-1.5 0.75 0]
                Vector3d v1 [-1.5 -99.25 0]
                Vector3d v2 [98.5 0.75 0]
                ref material m
                """;
        assertColor(0, 0.3, 0.9, parse(scene.formatted(1)).renderPixel(1, 1), "AASamples 1: centre sample misses");
        assertColor((2 * 0.9) / 9, (2 * 0.6 + 7 * 0.3) / 9, (2 * 0.3 + 7 * 0.9) / 9,
                parse(scene.formatted(3)).renderPixel(1, 1), "AASamples 3: 2 of 9 samples hit");
    }

    /** On a lit sphere's outline, an AASamples 3 pixel is the mean of trace() at its 9 sub-pixel centres. */
    @Test
    void silhouettePixelIsMeanOfTracesAtSubPixelCentres() throws Exception {
        Scene s = parse("""
                Width 20
                Height 20
                AASamples 3
                BGColor [0.1 0.2 0.3]
                AmbientLight [0.2 0.2 0.2]

                Camera Camera
                Vector3d eye [0 0 5]
                Vector3d target [0 0 0]
                Vector3d up [0 1 0]
                double yFOV 90

                Material BlinnPhong m
                Vector3d ambientColor [0.3 0.2 0.1]
                Vector3d diffuseColor [0.6 0.4 0.2]

                Surface Sphere
                Vector3d center [0 0 0]
                double radius 1
                ref material m

                Light PointLight
                Vector3d position [3 3 5]
                Vector3d intensity [30 30 30]
                """);
        s.prepare();
        int row = 8;           // image y in [8, 9]: b in [0.1, 0.2], inside the outline's b-range of 0.204
        int found = 0;
        for (int x = 10; x < 20; x++) {
            Vector3d mean = new Vector3d();
            int misses = 0;
            for (int j = 0; j < 3; j++) {
                for (int i = 0; i < 3; i++) {
                    Vector3d c = s.trace(s.camera.getRayThrough(x + (i + 0.5) / 3, row + (j + 0.5) / 3, 20, 20));
                    misses += c.equals(s.backgroundColor) ? 1 : 0;
                    mean.add(c);
                }
            }
            if (misses == 0 || misses == 9) {
                continue;           // not on the outline
            }
            found++;
            mean.scale(1.0 / 9);
            assertColor(mean.x, mean.y, mean.z, s.renderPixel(x, row), "outline pixel " + x + "," + row);
        }
        assertTrue(found > 0, "row " + row + " should cross the sphere's outline");
    }

    // ---- PNG bytes ----

    /** Each channel is clamped to [0, 1] and stored as floor(255 v + 0.5), no gamma. */
    @Test
    void pngBytesAreClampedAndRounded(@TempDir Path dir) throws Exception {
        double[] values = {0.2, 0.5001, 1.0, -0.1, 1.7, 0.999, 0.0019, 0.002, 100.49 / 255, 100.51 / 255, 0, 0.25};
        // 255 v + 0.5: 51.5, 128.03, 255.5, clamped 0, clamped 255, 255.2, 0.98, 1.01, 100.99, 101.01, 0.5, 64.25
        int[] expected = {51, 128, 255, 0, 255, 255, 0, 1, 100, 101, 0, 64};
        Image img = new Image(4, 1);
        for (int p = 0; p < 4; p++) {
            img.set(p, 0, values[3 * p], values[3 * p + 1], values[3 * p + 2]);
        }
        Path file = dir.resolve("bytes.png");
        PngWriter.write(img, file);
        BufferedImage read = ImageIO.read(file.toFile());
        int[] actual = new int[12];
        for (int p = 0; p < 4; p++) {
            int rgb = read.getRGB(p, 0);
            actual[3 * p] = rgb >> 16 & 0xFF;
            actual[3 * p + 1] = rgb >> 8 & 0xFF;
            actual[3 * p + 2] = rgb & 0xFF;
        }
        assertArrayEquals(expected, actual);
    }

    // ---- camera convention ----

    /**
     * A 40 x 40 image at yFOV 90 from [0 0 5]: the ray through pixel (10, 10)'s centre has image-plane
     * coordinates a = -0.475 (left), b = 0.475 (up) and meets z = 0 at (-2.375, 2.375, 0). A sphere of
     * radius 0.05 there covers that pixel centre and no other (neighbours are 0.25 away), so only
     * pixel (10, 10), in the top-left quadrant, differs from the background: row 0 is the up side and
     * x grows along u = +x.
     */
    @Test
    void upLeftObjectAppearsInTopLeftPixel() throws Exception {
        List<int[]> hits = hitPixels(parse(tinySphereScene("[0 0 5]", "[0 1 0]", "[-2.375 2.375 0]")));
        assertEquals(1, hits.size(), "exactly one pixel should see the sphere");
        assertArrayEquals(new int[] {10, 10}, hits.get(0));
    }

    /**
     * Looking down -x from [5 0 0] with up [2 0 1]: w = +x, u = up x w = +y, v = w x u = +z (the part of
     * up along w does not matter). A point (0, Y, Z) maps to a = Y / 5, b = Z / 5, so (0, 2.375, 2.375)
     * is pixel (29, 10): top right.
     */
    @Test
    void rotatedCameraMapsUpToTopAndUToRight() throws Exception {
        List<int[]> hits = hitPixels(parse(tinySphereScene("[5 0 0]", "[2 0 1]", "[0 2.375 2.375]")));
        assertEquals(1, hits.size(), "exactly one pixel should see the sphere");
        assertArrayEquals(new int[] {29, 10}, hits.get(0));
    }

    static String tinySphereScene(String eye, String up, String centre) {
        return """
                Width 40
                Height 40
                BGColor [0 0 0]
                AmbientLight [1 1 1]

                Camera Camera
                Vector3d eye %s
                Vector3d target [0 0 0]
                Vector3d up %s
                double yFOV 90

                Material Diffuse m
                Vector3d ambientColor [1 1 1]

                Surface Sphere
                Vector3d center %s
                double radius 0.05
                ref material m
                """.formatted(eye, up, centre);
    }

    static List<int[]> hitPixels(Scene s) {
        Vector3d[][] img = s.renderAll();
        List<int[]> hits = new ArrayList<>();
        for (int x = 0; x < img.length; x++) {
            for (int y = 0; y < img[x].length; y++) {
                if (!img[x][y].equals(new Vector3d())) {
                    hits.add(new int[] {x, y});
                }
            }
        }
        assertNotEquals(0, img.length);
        return hits;
    }
}
