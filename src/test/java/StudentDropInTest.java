import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.Scene;
import ray.app.Main;
import ray.parse.Parser;
import ray.render.Image;
import ray.render.Renderer;

/**
 * The project's key promise: a student's own Surface, Material and Light, written in the default
 * package against the 2003 framework API only (StudentPlane, Checker, ConstantLight, FlatMirror, Metal, Tinted
 * beside this file), are found by simple name from a scene file and rendered like built-in ones.
 */
class StudentDropInTest {

    private static final double EPS = 1e-9;

    /** Looking straight down at the floor y = 0 from (0, 5, 0): image x is world +x, image up is world -z. */
    private static final String TOP_VIEW = """
            Camera Camera
            Vector3d eye [0 5 0]
            Vector3d target [0 0 0]
            Vector3d up [0 0 -1]
            double yFOV 90

            """;

    private static Scene parse(String text) throws Exception {
        List<String> warnings = new ArrayList<>();
        Scene s = Parser.parse(text, "student.txt", warnings);
        assertEquals(List.of(), warnings);
        return s;
    }

    /** World x (and z) of the floor point seen through column i (row j) of an n-pixel image, yFOV 90. */
    private static double floorCoordinate(int i, int n) {
        return 5 * (2 * (i + 0.5) / n - 1);
    }

    private static void assertPixel(double r, double g, double b, Image img, int x, int y, String what) {
        Vector3d c = img.get(x, y);
        assertEquals(r, c.x, EPS, what + " pixel (" + x + ", " + y + ") red");
        assertEquals(g, c.y, EPS, what + " pixel (" + x + ", " + y + ") green");
        assertEquals(b, c.z, EPS, what + " pixel (" + x + ", " + y + ") blue");
    }

    static final String CHECKER_SCENE = """
            Width 4
            Height 4
            BGColor [0 0 1]

            """ + TOP_VIEW + """
            Material Checker board
            Vector3d color1 [1 1 1]
            Vector3d color2 [0.2 0.4 0.6]
            double size 1

            Surface StudentPlane
            Vector3d point [0 0 0]
            Vector3d normal [0 1 0]
            ref material board

            Light PointLight
            Vector3d position [0 4 0]
            Vector3d intensity [16 16 16]

            Light ConstantLight
            Vector3d intensity [0.25 0.5 0.75]
            """;

    /**
     * Pixel (i, j) sees the floor at x = -3.75, -1.25, 1.25, 3.75 (and z likewise down the rows), whose
     * floors are -4, -2, 1, 3: the square is color1 where i and j are on the same side of the centre.
     * Checker sums getIntensity: 16 / (x^2 + z^2 + 16) from the point light plus the constant light.
     */
    static double[] checkerExpected(int i, int j) {
        double x = floorCoordinate(i, 4), z = floorCoordinate(j, 4);
        boolean first = (i < 2) == (j < 2);
        double[] c = first ? new double[] {1, 1, 1} : new double[] {0.2, 0.4, 0.6};
        double p = 16 / (x * x + z * z + 16);
        return new double[] {c[0] * (p + 0.25), c[1] * (p + 0.5), c[2] * (p + 0.75)};
    }

    @Test
    void studentClassesAreFoundBySimpleNameInTheDefaultPackage() throws Exception {
        Scene s = parse(CHECKER_SCENE);
        assertSame(StudentPlane.class, s.surfaces.get(0).getClass());
        assertSame(Checker.class, s.materials.get(0).getClass());
        assertSame(ConstantLight.class, s.lights.get(1).getClass());
        assertEquals(new Vector3d(0.2, 0.4, 0.6), ((Checker) s.materials.get(0)).color2);
    }

    @Test
    void studentPlaneCheckerAndLightRenderAsSpecified() throws Exception {
        Image img = new Renderer(parse(CHECKER_SCENE)).threads(2).render();
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                double[] e = checkerExpected(i, j);
                assertPixel(e[0], e[1], e[2], img, i, j, "checker");
            }
        }
    }

    /**
     * Built-in Diffuse on the student's Plane, a built-in Sphere in front of it, both lit by a point
     * light and the student's ConstantLight (which arrives along the normal: n.l = 1). The sphere
     * covers the four centre pixels of the 8 x 8 image; the floor elsewhere is out of its shadow.
     * Hits on the sphere reuse the record the Plane pointed at its own normal field: the field must
     * survive.
     */
    @Test
    void builtInMaterialOnStudentPlaneBesideBuiltInSphere() throws Exception {
        Scene s = parse("""
                Width 8
                Height 8
                AmbientLight [1 1 1]

                """ + TOP_VIEW + """
                Material Diffuse floor
                Vector3d ambientColor [0 0 0.1]
                Vector3d diffuseColor [0.8 0.8 0.8]

                Material Diffuse ball
                Vector3d ambientColor [0.5 0 0]
                Vector3d diffuseColor [0 0 0]

                Surface StudentPlane ground
                Vector3d point [0 0 0]
                Vector3d normal [0 1 0]
                ref material floor

                Surface Sphere
                Vector3d center [0 1 0]
                double radius 1
                ref material ball

                Light PointLight
                Vector3d position [0 4 0]
                Vector3d intensity [16 16 16]

                Light ConstantLight
                Vector3d intensity [0.25 0.25 0.25]
                """);
        StudentPlane ground = (StudentPlane) s.surfaces.get(0);
        for (int threads : new int[] {1, 2}) {
            Image img = new Renderer(s).threads(threads).render();
            for (int j = 0; j < 8; j++) {
                for (int i = 0; i < 8; i++) {
                    if ((i == 3 || i == 4) && (j == 3 || j == 4)) {
                        assertPixel(0.5, 0, 0, img, i, j, "sphere, " + threads + " threads");
                        continue;
                    }
                    double x = floorCoordinate(i, 8), z = floorCoordinate(j, 8);
                    double r = Math.sqrt(x * x + z * z + 16);
                    double v = 0.8 * 16 / (r * r) * (4 / r) + 0.8 * 0.25;
                    assertPixel(v, v, v + 0.1, img, i, j, "floor, " + threads + " threads");
                }
            }
            assertEquals(new Vector3d(0, 1, 0), ground.normal, "the student's own normal field");
        }
    }

    /** Materials for the mirror scenes: each reflects half and adds red 1, built-in or student-written. */
    private static final String MIRROR_MATERIALS = """
            AmbientLight [1 1 1]

            Material FlatMirror student
            Vector3d color [1 0 0]
            double reflectance 0.5

            Material Diffuse red
            Vector3d ambientColor [1 0 0]
            Vector3d diffuseColor [0 0 0]

            Material GlazedMaterial glazed
            ref base red
            double mirrorCoefficient 0.5

            Material Tinted wrapped
            ref inner glazed

            """;

    /** Two facing planes at z = 1 and z = -1 with the named materials, the camera between them. */
    static String mirrors(String maxDepthLine, String front, String back) {
        return "Width 3\nHeight 3\n" + maxDepthLine + "\n" + MIRROR_MATERIALS + """
                Camera Camera
                Vector3d eye [0 0 0]
                Vector3d target [0 0 1]

                Surface StudentPlane
                Vector3d point [0 0 1]
                Vector3d normal [0 0 -1]
                ref material %s

                Surface StudentPlane
                Vector3d point [0 0 -1]
                Vector3d normal [0 0 1]
                ref material %s
                """.formatted(front, back);
    }

    /**
     * Two facing student mirrors recursing through scene.trace(new Ray(...)) would never stop by
     * themselves. MaxDepth d follows d bounces, as for GlazedMaterial: red 1 + 1/2 + ... + 1/2^d. The
     * count must not depend on who wrote the mirror: student, built-in, mixed, or a student material
     * calling a built-in one.
     */
    @Test
    void facingMirrorsStopAtMaxDepthWhoeverWroteThem() throws Exception {
        String[][] pairs = {{"student", "student"}, {"glazed", "glazed"}, {"glazed", "student"},
            {"student", "glazed"}, {"wrapped", "wrapped"}, {"wrapped", "student"}};
        for (String[] pair : pairs) {
            for (int d : new int[] {0, 1, 2, 5, 30}) {
                String what = pair[0] + " facing " + pair[1] + ", MaxDepth " + d;
                Image img = new Renderer(parse(mirrors("MaxDepth " + d, pair[0], pair[1]))).threads(2).render();
                for (int j = 0; j < 3; j++) {
                    for (int i = 0; i < 3; i++) {
                        assertPixel(2 - Math.pow(0.5, d), 0, 0, img, i, j, what);
                    }
                }
            }
        }
        Image img = new Renderer(parse(mirrors("", "student", "student"))).threads(1).render();
        assertPixel(2 - Math.pow(0.5, 10), 0, 0, img, 1, 1, "default MaxDepth 10");
    }

    /** The largest MaxDepth the parser accepts still terminates, on the render threads' stacks too. */
    @Test
    void facingStudentMirrorsAtLargestMaxDepthTerminate() throws Exception {
        Image img = new Renderer(parse(mirrors("MaxDepth 1000", "student", "wrapped"))).threads(2).render();
        assertPixel(2, 0, 0, img, 1, 1, "MaxDepth 1000");
    }

    /**
     * A built-in mirror reflects a student Metal, which traces its own reflection and then reads
     * record.location and record.normal to light itself. The nested trace must not reuse the record
     * the student is holding. Metal sits at (0, 0, -2) facing +z; the light at (0, 1, -1) is at
     * r^2 = 2 with n.l = 1/sqrt(2): L = 1 * (1/2) * (1/sqrt(2)).
     */
    @Test
    void studentMaterialSeenInBuiltInMirrorKeepsItsRecord() throws Exception {
        Scene s = parse("""
                Width 1
                Height 1

                Camera Camera
                Vector3d eye [0 0 0]
                Vector3d target [0 0 1]

                Material GlazedMaterial glass
                double mirrorCoefficient 1

                Material Metal metal
                Vector3d diffuseColor [1 1 1]
                double reflectance 0

                Surface StudentPlane
                Vector3d point [0 0 2]
                Vector3d normal [0 0 -1]
                ref material glass

                Surface StudentPlane
                Vector3d point [0 0 -2]
                Vector3d normal [0 0 1]
                ref material metal

                Light PointLight
                Vector3d position [0 1 -1]
                Vector3d intensity [1 1 1]
                """);
        double v = 0.5 / Math.sqrt(2);
        assertPixel(v, v, v, new Renderer(s).threads(1).render(), 0, 0, "metal in the mirror");
    }

    /** The whole command line on a student scene: the PNG holds floor(255 v + 0.5) of each value. */
    @Test
    void commandLineRendersStudentScene(@TempDir Path dir) throws Exception {
        Path scene = dir.resolve("student.txt");
        Files.writeString(scene, CHECKER_SCENE);
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), "-q", scene.toString());
        assertEquals(0, status, err.toString(StandardCharsets.UTF_8));
        assertEquals("", err.toString(StandardCharsets.UTF_8));
        BufferedImage png = ImageIO.read(dir.resolve("student.png").toFile());
        for (int j = 0; j < 4; j++) {
            for (int i = 0; i < 4; i++) {
                double[] e = checkerExpected(i, j);
                int rgb = png.getRGB(i, j);
                String where = "PNG pixel (" + i + ", " + j + ")";
                assertEquals(toByte(e[0]), rgb >> 16 & 255, where + " red");
                assertEquals(toByte(e[1]), rgb >> 8 & 255, where + " green");
                assertEquals(toByte(e[2]), rgb & 255, where + " blue");
            }
        }
        assertTrue(toByte(checkerExpected(0, 0)[2]) == 255, "the scene exercises clamping too");
    }

    private static int toByte(double v) {
        return (int) Math.floor(255 * Math.min(1, Math.max(0, v)) + 0.5);
    }
}
