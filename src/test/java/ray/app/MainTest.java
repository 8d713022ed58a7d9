package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;

/** The command line, through {@code Main.run(out, err, args)}: files written, messages, exit status. */
class MainTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream outBytes = new ByteArrayOutputStream();
    private final ByteArrayOutputStream errBytes = new ByteArrayOutputStream();

    /** A 4 x 3 image of nothing but the background (0.5, 0.25, 1): bytes (128, 64, 255). */
    private static final String GOOD = "Width 4\nHeight 3\nBGColor [0.5 0.25 1]\n\nCamera Camera\n";

    /** Line 5 names a class that does not exist. */
    private static final String BAD = "Width 4\nHeight 3\n\nCamera Camera\nSurface Sphre\n";

    private int run(String... args) {
        return Main.run(new PrintStream(outBytes, true, StandardCharsets.UTF_8),
                new PrintStream(errBytes, true, StandardCharsets.UTF_8), args);
    }

    private String out() {
        return outBytes.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return errBytes.toString(StandardCharsets.UTF_8);
    }

    private Path write(String name, String text) throws Exception {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    private static void assertBackgroundPng(Path png) throws Exception {
        BufferedImage img = ImageIO.read(png.toFile());
        assertEquals(4, img.getWidth(), png.toString());
        assertEquals(3, img.getHeight(), png.toString());
        assertEquals(128 << 16 | 64 << 8 | 255, img.getRGB(3, 2) & 0xFFFFFF, png.toString());
    }

    private static void assertNoStackTrace(String text) {
        assertFalse(text.contains("\tat ") || text.contains("Exception") || text.contains("Error:"),
                "no stack trace or exception name in:\n" + text);
    }

    @Test
    void rendersSceneToPngBesideIt() throws Exception {
        Path scene = write("a.txt", GOOD);
        assertEquals(0, run(scene.toString()), err());
        assertBackgroundPng(dir.resolve("a.png"));
        assertEquals("", err());
        assertTrue(out().startsWith(scene + " -> " + dir.resolve("a.png")), out());
    }

    @Test
    void badSceneAmongGoodOnesFailsAloneWithOneLocatedLine() throws Exception {
        Path a = write("a.txt", GOOD), bad = write("bad.txt", BAD), c = write("c.txt", GOOD);
        assertEquals(1, run("-q", a.toString(), bad.toString(), c.toString()));
        assertBackgroundPng(dir.resolve("a.png"));
        assertBackgroundPng(dir.resolve("c.png"));
        assertFalse(Files.exists(dir.resolve("bad.png")));
        List<String> lines = err().lines().toList();
        assertEquals(1, lines.size(), "exactly one line on stderr:\n" + err());
        assertTrue(lines.get(0).startsWith(bad + ":5: "), lines.get(0));
        assertTrue(lines.get(0).contains("Sphre"), lines.get(0));
        assertNoStackTrace(err());
        assertEquals("", out(), "-q prints nothing but errors");
    }

    @Test
    void existingPngIsKeptWhenItsSceneIsBad() throws Exception {
        Path bad = write("bad.txt", BAD);
        byte[] old = MainBadInputTest.oldPng();
        Files.write(dir.resolve("bad.png"), old);
        assertEquals(1, run(bad.toString()));
        assertArrayEquals(old, Files.readAllBytes(dir.resolve("bad.png")));
    }

    @Test
    void missingSceneFileIsOneLine() throws Exception {
        Path missing = dir.resolve("missing.txt");
        assertEquals(1, run(missing.toString()));
        List<String> lines = err().lines().toList();
        assertEquals(1, lines.size(), err());
        assertTrue(lines.get(0).startsWith(missing.toString() + ":"), lines.get(0));
        assertNoStackTrace(err());
    }

    @Test
    void outputOptionWritesThere() throws Exception {
        Path scene = write("a.txt", GOOD);
        Path png = dir.resolve("elsewhere.png");
        assertEquals(0, run("-o", png.toString(), scene.toString()), err());
        assertBackgroundPng(png);
        assertFalse(Files.exists(dir.resolve("a.png")));
    }

    @Test
    void outputOptionWithTwoScenesIsUsageError() throws Exception {
        Path a = write("a.txt", GOOD), b = write("b.txt", GOOD);
        assertEquals(2, run("-o", dir.resolve("x.png").toString(), a.toString(), b.toString()));
        assertEquals(1, err().lines().count(), err());
        assertFalse(Files.exists(dir.resolve("x.png")));
        assertFalse(Files.exists(dir.resolve("a.png")));
    }

    @Test
    void helpExitsZeroAndPrintsUsage() {
        assertEquals(0, run("--help"));
        assertTrue(out().contains("Usage"), out());
        assertEquals("", err());
    }

    @Test
    void unknownOptionIsUsageError() {
        assertEquals(2, run("--no-such-option"));
        assertNoStackTrace(err());
    }

    @Test
    void noArgumentsWithoutDisplayIsOneLineUsageError() {
        Assumptions.assumeTrue(GraphicsEnvironment.isHeadless(), "the tests run headless (build.gradle sets it)");
        assertEquals(2, run());
        assertEquals(1, err().lines().count(), err());
        assertTrue(err().contains("raytracer"), err());
    }

    @Test
    void sceneWithoutTxtSuffixGetsPngAppended() throws Exception {
        Path scene = write("plain", GOOD);
        assertEquals(0, run("-q", scene.toString()), err());
        assertBackgroundPng(dir.resolve("plain.png"));
    }

    /** A material whose code throws (a student's bug), named from a scene file by its qualified name. */
    public static class Broken extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            throw new ArithmeticException("/ by zero");
        }
    }

    /** A scene whose own material code throws fails alone: the scenes after it are still rendered. */
    @Test
    void sceneWhoseCodeThrowsDoesNotStopTheOthers() throws Exception {
        Path broken = write("broken.txt", "Width 4\nHeight 3\n\nCamera Camera\n\nMaterial ray.app.MainTest$Broken m\n\n"
                + "Surface Sphere\nVector3d center [0 0 0]\nref material m\n");
        Path good = write("good.txt", GOOD);
        assertEquals(1, run("-q", broken.toString(), good.toString()));
        assertBackgroundPng(dir.resolve("good.png"));
        assertFalse(Files.exists(dir.resolve("broken.png")));
        List<String> lines = err().lines().toList();
        assertTrue(lines.get(0).startsWith(broken.toString() + ": "), err());
        assertTrue(lines.get(0).contains("ArithmeticException") && lines.get(0).contains("/ by zero"), err());
        assertTrue(lines.get(0).contains("Broken.shade"), "points at the throwing method: " + err());
        assertEquals(1, lines.size(), "one line, no stack trace:\n" + err());
    }
}
