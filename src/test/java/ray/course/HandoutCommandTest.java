package ray.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code java RayTracer scene.txt} as a student runs it, in a child JVM: the reference solution writes the PNG
 * beside the scene, equal to the reference image; the stubbed handout says which method returned nothing, for
 * which pixel, exits 1 and writes no PNG; a scene mistake is the parser's one line.
 */
@Tag("slow")
class HandoutCommandTest {

    @TempDir
    Path dir;

    record Run(int status, String out, String err) {
    }

    private Run java(Path classes, String... args) throws IOException, InterruptedException {
        List<String> cmd = new java.util.ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=true", "-cp", classes.toAbsolutePath() + File.pathSeparator + Course.jars(), "RayTracer"));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectOutput(dir.resolve("out.txt").toFile())
                .redirectError(dir.resolve("err.txt").toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "RayTracer finished");
        return new Run(p.exitValue(), Files.readString(dir.resolve("out.txt"), StandardCharsets.UTF_8),
                Files.readString(dir.resolve("err.txt"), StandardCharsets.UTF_8));
    }

    @Test
    void theSolutionRendersAScenesPngBesideIt() throws Exception {
        Files.copy(Path.of("scenes/material-blinnphong.txt"), dir.resolve("s.txt"));
        Run r = java(Course.SOLUTION_CLASSES, "s.txt");
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        java.awt.image.BufferedImage got = javax.imageio.ImageIO.read(dir.resolve("s.png").toFile());
        java.awt.image.BufferedImage ref = javax.imageio.ImageIO.read(new File("reference-images/material-blinnphong.png"));
        for (int y = 0; y < ref.getHeight(); y++) {
            for (int x = 0; x < ref.getWidth(); x++) {
                assertEquals(ref.getRGB(x, y), got.getRGB(x, y), "pixel " + x + ", " + y);
            }
        }
    }

    @Test
    void theStubbedHandoutNamesTheMethodAndPixelAndWritesNoPng() throws Exception {
        Path classes = Files.createDirectories(dir.resolve("classes"));
        assertEquals("", Course.compile(classes, Course.HANDOUT.resolve("src/main/java")));
        Files.copy(Path.of("scenes/material-diffuse.txt"), dir.resolve("s.txt"));
        Files.writeString(dir.resolve("bad.txt"), "Width 8\nHeight 6\n\nCamera Camera\nVector3d eye [0 0 5 6]\n");
        Run r = java(classes, "s.txt", "bad.txt");
        assertEquals(1, r.status());
        assertEquals("s.txt: Camera.getRayThrough returned null for pixel (0, 0) (expected a new Ray)\n"
                + "bad.txt:5: malformed vector '[0 0 5 6]' for eye: found 4 numbers (expected [x y z], three numbers in brackets)\n", r.err());
        assertFalse(Files.exists(dir.resolve("s.png")));
        assertFalse(Files.exists(dir.resolve("bad.png")));
    }
}
