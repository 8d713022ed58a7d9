package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** PNG output: the 8-bit values the contract specifies, and atomic replacement of the target. */
class PngWriterTest {

    @TempDir
    Path dir;

    private static int[] channels(BufferedImage img, int x, int y) {
        int rgb = img.getRGB(x, y);
        return new int[] {rgb >> 16 & 255, rgb >> 8 & 255, rgb & 255};
    }

    private List<String> listing() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }

    private static Image uniform(int w, int h, double v) {
        Image img = new Image(w, h);
        java.util.Arrays.fill(img.rgb, v);
        return img;
    }

    /**
     * floor(255 v + 0.5) after clamping to [0, 1]: 0.5 -> 128 (127.5 + 0.5), 0.25 -> 64, 0.75 -> 191,
     * 1/255 -> 1, 0.5/255 -> 1 and 254.5/255 -> 255 (ties round up), 0.49/255 -> 0, 0.999 -> 255;
     * below 0, -infinity and NaN -> 0; above 1 and +infinity -> 255.
     */
    @Test
    void roundTripClampsAndRoundsAsSpecified() throws IOException {
        double[] in = {0, 1, 0.5, 0.25, 0.75, 1.0 / 255, 0.5 / 255, 0.49 / 255, -0.5, 2,
            Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, 254.5 / 255, 0.999};
        int[] expected = {0, 255, 128, 64, 191, 1, 1, 0, 0, 255, 0, 255, 0, 255, 255};
        Image img = new Image(in.length, 2);
        for (int x = 0; x < in.length; x++) {
            img.set(x, 0, in[x], 0, 1);        // the value in red, in row 0
            img.set(x, 1, 0.5, in[x], 0);      // and in green, in row 1
        }
        Path png = dir.resolve("round.png");
        PngWriter.write(img, png);
        BufferedImage back = ImageIO.read(png.toFile());
        assertEquals(in.length, back.getWidth());
        assertEquals(2, back.getHeight());
        for (int x = 0; x < in.length; x++) {
            assertArrayEquals(new int[] {expected[x], 0, 255}, channels(back, x, 0), "red of " + in[x]);
            assertArrayEquals(new int[] {128, expected[x], 0}, channels(back, x, 1), "green of " + in[x]);
        }
        assertEquals(List.of("round.png"), listing(), "no temporary file left behind");
    }

    @Test
    void rowZeroIsTheTopOfThePng() throws IOException {
        Image img = new Image(1, 3);
        img.set(0, 0, 1, 0, 0);
        img.set(0, 2, 0, 0, 1);
        Path png = dir.resolve("rows.png");
        PngWriter.write(img, png);
        BufferedImage back = ImageIO.read(png.toFile());
        assertArrayEquals(new int[] {255, 0, 0}, channels(back, 0, 0));
        assertArrayEquals(new int[] {0, 0, 255}, channels(back, 0, 2));
    }

    @Test
    void writingOverExistingFileReplacesIt() throws IOException {
        Path png = dir.resolve("a.png");
        PngWriter.write(uniform(3, 2, 1), png);
        PngWriter.write(uniform(5, 4, 0.5), png);
        BufferedImage back = ImageIO.read(png.toFile());
        assertEquals(5, back.getWidth());
        assertEquals(4, back.getHeight());
        assertArrayEquals(new int[] {128, 128, 128}, channels(back, 4, 3));
        assertEquals(List.of("a.png"), listing());
    }

    @Test
    void missingDirectoryFailsWithoutLeavingAnything() {
        Path png = dir.resolve("no-such-dir").resolve("a.png");
        assertThrows(IOException.class, () -> PngWriter.write(uniform(2, 2, 0.5), png));
        assertFalse(Files.exists(png.getParent()));
    }

    @Test
    void parentThatIsAFileFailsWithoutTouchingIt() throws IOException {
        Path file = dir.resolve("scene.txt");
        Files.writeString(file, "Width 1\n");
        assertThrows(IOException.class, () -> PngWriter.write(uniform(2, 2, 0.5), file.resolve("a.png")));
        assertEquals("Width 1\n", Files.readString(file));
        assertEquals(List.of("scene.txt"), listing());
    }

    /** The target is a non-empty directory: the rename fails after the PNG was written beside it. */
    @Test
    void failedRenameLeavesTargetAndNoTemporaryFile() throws IOException {
        Path target = dir.resolve("a.png");
        Files.createDirectory(target);
        Files.writeString(target.resolve("keep.txt"), "keep");
        assertThrows(IOException.class, () -> PngWriter.write(uniform(2, 2, 0.5), target));
        assertEquals("keep", Files.readString(target.resolve("keep.txt")));
        assertEquals(List.of("a.png"), listing(), "no temporary file left behind");
    }

    /** Encoding fails after the temporary file was created: the old PNG stays exactly as it was. */
    @Test
    void failedEncodingLeavesOldFileUntouched() throws IOException {
        Path png = dir.resolve("a.png");
        PngWriter.write(uniform(3, 3, 0.25), png);
        byte[] before = Files.readAllBytes(png);
        assertThrows(RuntimeException.class, () -> PngWriter.write(new Image(0, 0), png));  // no 0 x 0 PNG
        assertArrayEquals(before, Files.readAllBytes(png));
        assertEquals(List.of("a.png"), listing(), "no temporary file left behind");
    }
}
