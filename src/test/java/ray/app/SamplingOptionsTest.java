package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.render.SampledRenderTestAccess;

/** {@code --sampler}, {@code --samples}, {@code --target-error} and the summary they print. */
class SamplingOptionsTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream outBytes = new ByteArrayOutputStream();
    private final ByteArrayOutputStream errBytes = new ByteArrayOutputStream();

    private int run(String... args) {
        outBytes.reset();
        errBytes.reset();
        return Main.run(new PrintStream(outBytes, true, StandardCharsets.UTF_8),
                new PrintStream(errBytes, true, StandardCharsets.UTF_8), args);
    }

    private String out() {
        return outBytes.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return errBytes.toString(StandardCharsets.UTF_8);
    }

    @Test
    void gridPrintsOnlyTheUsualLineAndAdaptiveAddsItsEstimate() throws Exception {
        Path scene = dir.resolve("s.txt");
        Files.writeString(scene, SampledRenderTestAccess.SCENE);
        assertEquals(0, run(scene.toString(), "-o", dir.resolve("grid.png").toString()));
        assertEquals(1, out().lines().count(), out());
        assertTrue(out().contains("4x4 AA"), out());
        assertEquals(0, run("--sampler", "adaptive", "--target-error", "0", scene.toString(), "-o", dir.resolve("zero.png").toString()));
        assertTrue(out().contains("adaptive: 16.0 samples per pixel, estimated error "), out());
        assertArrayEquals(Files.readAllBytes(dir.resolve("grid.png")), Files.readAllBytes(dir.resolve("zero.png")),
                "adaptive with a zero target writes the grid's PNG");
        assertEquals(0, run("--sampler", "sobol", "--samples", "2", scene.toString(), "-o", dir.resolve("sobol.png").toString()));
        assertTrue(out().contains("2x2 AA") && out().contains("sobol: 4.0 samples per pixel"), out());
        assertEquals(0, run("--max-depth", "0", "--plan", scene.toString()));
        assertTrue(out().contains("MaxDepth 0"), "--plan sees the override: " + out());
    }

    @Test
    void badValuesAreOneLineAndStatusTwo() throws Exception {
        Path scene = dir.resolve("s.txt");
        Files.writeString(scene, SampledRenderTestAccess.SCENE);
        assertEquals(2, run("--sampler", "halton", scene.toString()));
        assertEquals("raytracer: --sampler must be one of grid, jittered, sobol, adaptive, got 'halton'", err().strip());
        assertEquals(2, run("--samples", "0", scene.toString()));
        assertEquals("raytracer: --samples must be 1 to 64, got 0", err().strip());
        assertEquals(2, run("--target-error", "-1", scene.toString()));
        assertEquals("raytracer: --target-error must be 0 to 255 (8-bit steps), got -1.0", err().strip());
        assertEquals(2, run("--max-depth", "1001", scene.toString()));
        assertEquals("raytracer: --max-depth must be 0 to 1000, got 1001", err().strip());
        assertFalse(Files.exists(dir.resolve("s.png")), "nothing written");
    }
}
