package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The command line on bad scene files: one line on stderr per bad file, exit status 1, and an
 * existing PNG beside the scene left byte for byte as it was (no partial or clobbered image).
 */
class MainBadInputTest {

    static final String GOOD = "Width 4\nHeight 3\nBGColor [1 0 0]\n\nCamera Camera\n";

    record Run(int status, String out, String err) {
        List<String> errLines() {
            return err.lines().collect(Collectors.toList());
        }
    }

    static Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    /** An earlier image: the PNG signature, then bytes of its own (an existing file that is no PNG is never replaced). */
    static byte[] oldPng() {
        byte[] b = new byte[300];
        for (int i = 0; i < b.length; i++) {
            b[i] = (byte) (i * 7);
        }
        System.arraycopy(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}, 0, b, 0, 8);
        return b;
    }

    static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }

    @Test
    void badSceneLeavesTheExistingPngUntouched(@TempDir Path dir) throws IOException {
        Path scene = dir.resolve("bad.txt"), png = dir.resolve("bad.png");
        Files.writeString(scene, GOOD + "\nSurface Sphere\ndouble radius -1\n");
        Files.write(png, oldPng());
        Run r = run("-q", scene.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(scene + ":7: Surface Sphere: sphere radius must be a positive number, got -1.0"), r.errLines());
        assertEquals("", r.out());
        assertArrayEquals(oldPng(), Files.readAllBytes(png));
        assertEquals(List.of("bad.png", "bad.txt"), names(dir), "no temporary files left behind");
    }

    @Test
    void sceneTooLargeForMemoryIsRefusedBeforeRendering(@TempDir Path dir) throws IOException {
        Path scene = dir.resolve("huge.txt"), png = dir.resolve("huge.png");
        Files.writeString(scene, "Width 65536\nHeight 65536\n\nCamera Camera\n");
        Files.write(png, oldPng());
        Run r = run(scene.toString());
        assertEquals(1, r.status());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.err().startsWith(scene + ":1: ") && r.err().contains("whatever the heap") && !r.err().contains("-Xmx"), r.err());
        assertArrayEquals(oldPng(), Files.readAllBytes(png));
    }

    @Test
    void missingSceneIsOneLineAndWritesNothing(@TempDir Path dir) throws IOException {
        Path scene = dir.resolve("nope.txt");
        Run r = run(scene.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(scene + ": cannot read the scene: no such file"), r.errLines());
        assertEquals(List.of(), names(dir));
    }

    @Test
    void directoryAsSceneIsOneLine(@TempDir Path dir) {
        Run r = run(dir.toString());
        assertEquals(1, r.status());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.err().startsWith(dir + ": cannot read the scene"), r.err());
    }

    @Test
    void binarySceneIsOneLine(@TempDir Path dir) throws IOException {
        Path scene = dir.resolve("image.txt");
        byte[] binary = new byte[300];
        for (int i = 0; i < binary.length; i++) {
            binary[i] = (byte) (i * 7);      // a NUL on the first line
        }
        Files.write(scene, binary);
        Run r = run(scene.toString());
        assertEquals(1, r.status());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.err().startsWith(scene + ":1: "), r.err());
        assertFalse(Files.exists(dir.resolve("image.png")));
    }

    /** Each file on the command line is rendered or reported on its own; the status says whether any failed. */
    @Test
    void goodAndBadScenesOnOneCommandLine(@TempDir Path dir) throws IOException {
        Path good = dir.resolve("good.txt"), bad = dir.resolve("bad.txt"), good2 = dir.resolve("good2.txt");
        Files.writeString(good, GOOD);
        Files.writeString(bad, "Width 4\n");
        Files.writeString(good2, GOOD);
        Run r = run("-q", good.toString(), bad.toString(), good2.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(bad + ":1: no Height (expected 'Height <pixels>', e.g. 'Height 480')"), r.errLines());
        assertTrue(Files.size(dir.resolve("good.png")) > 0);
        assertTrue(Files.size(dir.resolve("good2.png")) > 0);
        assertFalse(Files.exists(dir.resolve("bad.png")));
    }

    /** A user's own class failing during the render is reported on one line too, and leaves the old PNG. */
    @Test
    void failingUserMaterialIsOneLine(@TempDir Path dir) throws IOException {
        Path scene = dir.resolve("mine.txt"), png = dir.resolve("mine.png");
        Files.writeString(scene, GOOD + "\nMaterial ThrowingMaterial m\n\nSurface Sphere\nVector3d center [0 0 0]\nref material m\n");
        Files.write(png, oldPng());
        Run r = run("-q", scene.toString());
        assertEquals(1, r.status());
        assertEquals(1, r.errLines().size(), r.errLines().toString());
        assertTrue(r.errLines().get(0).startsWith(scene + ": rendering failed: UnsupportedOperationException (student code not finished) at ThrowingMaterial.shade("),
                r.errLines().toString());
        assertArrayEquals(oldPng(), Files.readAllBytes(png));
    }

    @Test
    void allGoodExitsZero(@TempDir Path dir) throws IOException {
        Path good = dir.resolve("good.txt");
        Files.writeString(good, GOOD);
        Run r = run("-q", good.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
    }
}
