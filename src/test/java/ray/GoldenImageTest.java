package ray;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import ray.parse.Parser;
import ray.render.Image;

/**
 * Renders every {@code scenes/*.txt} and compares it with {@code reference-images/<scene>.png},
 * allowing one 8-bit step per channel. On a mismatch the rendered image and an amplified difference
 * go to {@code build/golden/}. The references are only ever written by
 * {@code gradle regenerateReferences}, never by this test.
 */
@Tag("slow") // end-to-end; left out by gradle mutation -PmutationFast
class GoldenImageTest {

    static final Path SCENES = Paths.get("scenes");
    static final Path REFERENCES = Paths.get("reference-images");
    static final Path OUTPUT = Paths.get("build", "golden");
    /** Largest accepted difference of one channel, in 8-bit steps. */
    static final int TOLERANCE = 1;
    /** Scale of the difference image: a one-step difference shows as 32. */
    static final int DIFF_GAIN = 32;

    static List<String> scenes() throws IOException {
        List<String> names;
        try (Stream<Path> s = Files.list(SCENES)) {
            names = s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".txt")).sorted()
                    .map(n -> n.substring(0, n.length() - 4)).collect(Collectors.toList());
        }
        assertFalse(names.isEmpty(), "no scenes in " + SCENES.toAbsolutePath() + ": nothing would be checked");
        return names;
    }

    /** Each scene renders to its reference image within one 8-bit step per channel. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void sceneMatchesReferenceImage(String name) throws Exception {
        Path reference = REFERENCES.resolve(name + ".png");
        assertTrue(Files.isRegularFile(reference), "scenes/" + name + ".txt has no reference image " + reference
                + " (make one with gradle regenerateReferences and look at it before committing)");
        BufferedImage expected = ImageIO.read(reference.toFile());
        Image rendered = new ray.render.Renderer(Parser.parse(SCENES.resolve(name + ".txt"))).render();
        BufferedImage actual = rendered.toBufferedImage();

        if (expected.getWidth() != actual.getWidth() || expected.getHeight() != actual.getHeight()) {
            Path out = writeOutputs(name, actual, null);
            fail(name + ": rendered " + actual.getWidth() + "x" + actual.getHeight() + " but the reference is "
                    + expected.getWidth() + "x" + expected.getHeight() + "; rendered image in " + out);
        }
        Comparison c = compare(expected, actual, TOLERANCE);
        if (c.differing() > 0) {
            Path out = writeOutputs(name, actual, c.diff());
            fail(String.format("%s: %d of %d pixels differ by more than %d step(s) in some channel, largest"
                            + " difference %d (first at pixel %d,%d); see %s-actual.png and %s-diff.png in %s",
                    name, c.differing(), actual.getWidth() * actual.getHeight(), TOLERANCE, c.largest(),
                    c.firstX(), c.firstY(), name, name, out));
        }
    }

    /** No reference image is left without a scene (a renamed or deleted scene leaves one behind). */
    @Test
    void everyReferenceImageHasAScene() throws IOException {
        List<String> scenes = scenes();
        List<String> orphans = new ArrayList<>();
        try (Stream<Path> s = Files.list(REFERENCES)) {
            s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".png")).sorted()
                    .map(n -> n.substring(0, n.length() - 4)).filter(n -> !scenes.contains(n)).forEach(orphans::add);
        }
        assertEquals(List.of(), orphans, "reference images without a scene in " + SCENES);
    }

    /** The comparison itself: a one-step difference passes, two steps fail and are counted and located. */
    @Test
    void comparisonAcceptsOneStepAndFlagsTwo() {
        BufferedImage a = new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB);
        BufferedImage b = new BufferedImage(4, 3, BufferedImage.TYPE_INT_RGB);
        a.setRGB(1, 1, 0x102030);
        b.setRGB(1, 1, 0x112131);                 // +1 in every channel
        assertEquals(0, compare(a, b, 1).differing());
        b.setRGB(3, 2, 0x000200);                 // green off by 2
        b.setRGB(0, 2, 0x00000A);                 // blue off by 10
        Comparison c = compare(a, b, 1);
        assertEquals(2, c.differing());
        assertEquals(10, c.largest());
        assertEquals(0, c.firstX());
        assertEquals(2, c.firstY());
        assertEquals(Math.min(255, 10 * DIFF_GAIN), c.diff().getRGB(0, 2) & 0xFF, "diff image amplifies |a - b|");
        assertEquals(0, c.diff().getRGB(2, 0) & 0xFFFFFF, "equal pixels are black in the diff image");
    }

    record Comparison(int differing, int largest, int firstX, int firstY, BufferedImage diff) {
    }

    /** Counts pixels with a channel off by more than {@code tolerance}; builds |a - b| times the gain. */
    static Comparison compare(BufferedImage expected, BufferedImage actual, int tolerance) {
        int w = expected.getWidth(), h = expected.getHeight();
        BufferedImage diff = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int differing = 0, largest = 0, firstX = -1, firstY = -1;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int e = expected.getRGB(x, y), a = actual.getRGB(x, y);
                int worst = 0, rgb = 0;
                for (int shift = 16; shift >= 0; shift -= 8) {
                    int d = Math.abs(((e >> shift) & 0xFF) - ((a >> shift) & 0xFF));
                    worst = Math.max(worst, d);
                    rgb |= Math.min(255, d * DIFF_GAIN) << shift;
                }
                diff.setRGB(x, y, rgb);
                largest = Math.max(largest, worst);
                if (worst > tolerance) {
                    if (differing++ == 0) {
                        firstX = x;
                        firstY = y;
                    }
                }
            }
        }
        return new Comparison(differing, largest, firstX, firstY, diff);
    }

    private static Path writeOutputs(String name, BufferedImage actual, BufferedImage diff) throws IOException {
        Files.createDirectories(OUTPUT);
        ImageIO.write(actual, "png", OUTPUT.resolve(name + "-actual.png").toFile());
        if (diff != null) {
            ImageIO.write(diff, "png", OUTPUT.resolve(name + "-diff.png").toFile());
        }
        return OUTPUT.toAbsolutePath();
    }
}
