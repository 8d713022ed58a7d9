package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.util.Random;
import java.util.zip.Inflater;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;

/** The hand-written PNG encoder must give a standard PNG whose pixels are exactly Image.toByte of the image. */
class PngEncoderTest {

    private static Image randomImage(int w, int h, long seed) {
        Random r = new Random(seed);
        Image img = new Image(w, h);
        for (int i = 0; i < img.rgb.length; i++) {
            // smooth gradients (so every filter type gets chosen somewhere), noise, and out-of-range values
            int p = i / 3, x = p % w, y = p / w;
            img.rgb[i] = switch (r.nextInt(6)) {
                case 0 -> r.nextDouble();
                case 1 -> -0.5;
                case 2 -> 1.7;
                case 3 -> Double.NaN;
                default -> (x + 2.0 * y) / (w + 2.0 * h);
            };
        }
        return img;
    }

    private static void assertDecodesTo(Image img) throws Exception {
        byte[] png = PngEncoder.encode(img);
        BufferedImage back = ImageIO.read(new ByteArrayInputStream(png));
        assertEquals(img.width, back.getWidth());
        assertEquals(img.height, back.getHeight());
        for (int y = 0; y < img.height; y++) {
            for (int x = 0; x < img.width; x++) {
                int i = 3 * (y * img.width + x);
                int expected = Image.toByte(img.rgb[i]) << 16 | Image.toByte(img.rgb[i + 1]) << 8 | Image.toByte(img.rgb[i + 2]);
                assertEquals(expected, back.getRGB(x, y) & 0xFFFFFF, "pixel " + x + "," + y);
            }
        }
    }

    @Test
    void oneBandImageDecodesToTheSamePixels() throws Exception {
        assertDecodesTo(randomImage(37, 5, 1));
    }

    /** Several bands deflated separately must still form one valid zlib stream. */
    @Test
    void manyBandImageDecodesToTheSamePixels() throws Exception {
        assertDecodesTo(randomImage(301, 3 * PngEncoder.BAND_ROWS + 17, 2));
    }

    @Test
    void onePixelImage() throws Exception {
        assertDecodesTo(randomImage(1, 1, 3));
    }

    /** The zlib stream is complete and checked: the Adler-32 at its end matches (Inflater verifies it). */
    @Test
    void idatIsOneCompleteZlibStream() throws Exception {
        Image img = randomImage(64, 2 * PngEncoder.BAND_ROWS + 1, 4);
        byte[] png = PngEncoder.encode(img);
        int pos = 8;
        java.io.ByteArrayOutputStream idat = new java.io.ByteArrayOutputStream();   // the IDATs' data joined
        while (pos < png.length) {
            int len = (png[pos] & 0xFF) << 24 | (png[pos + 1] & 0xFF) << 16 | (png[pos + 2] & 0xFF) << 8 | png[pos + 3] & 0xFF;
            String type = new String(png, pos + 4, 4, java.nio.charset.StandardCharsets.US_ASCII);
            if (type.equals("IDAT")) {
                idat.write(png, pos + 8, len);
            }
            pos += 12 + len;
        }
        assertEquals(png.length, pos);
        Inflater inf = new Inflater();
        inf.setInput(idat.toByteArray());
        byte[] raw = new byte[img.height * (3 * img.width + 1) + 1];
        int n = inf.inflate(raw);
        assertEquals(true, inf.finished());
        assertEquals(img.height * (3 * img.width + 1), n);
        byte[] expected = PngEncoder.filterRows(img);
        byte[] got = new byte[n];
        System.arraycopy(raw, 0, got, 0, n);
        assertArrayEquals(expected, got);
    }

    /** zlib's combination rule agrees with one Adler-32 over the joined data (seeded lengths, including 0 and > 65521). */
    @Test
    void adlerCombineEqualsTheAdlerOfTheJoinedData() {
        java.util.Random r = new java.util.Random(11);
        for (int trial = 0; trial < 200; trial++) {
            byte[] a = new byte[trial == 0 ? 0 : r.nextInt(200_000)], b = new byte[trial == 1 ? 0 : r.nextInt(200_000)];
            r.nextBytes(a);
            r.nextBytes(b);
            java.util.zip.Adler32 x = new java.util.zip.Adler32(), y = new java.util.zip.Adler32(), all = new java.util.zip.Adler32();
            x.update(a);
            y.update(b);
            all.update(a);
            all.update(b);
            assertEquals(all.getValue(), PngEncoder.adlerCombine(x.getValue(), y.getValue(), b.length), "seed 11, trial " + trial);
        }
    }

    /**
     * The image limit and the encoder's buffers agree: at the largest pixel count the parser admits,
     * in every shape the side limit allows, no buffer the encoder allocates exceeds what a Java array
     * holds (computed, not allocated). The old single scanline buffer, h * (3w + 1) bytes, did not fit.
     */
    @Test
    void everyBufferFitsAnArrayAtTheImageLimit() {
        long max = ray.parse.Limits.MAX_ARRAY_PIXELS, arrayMax = Integer.MAX_VALUE - 8;
        long side = ray.parse.Limits.MAX_SIDE;
        long worstW = 0, worstH = 0;      // the admitted shape with the most scanline bytes, h * (3w + 1)
        for (long h = 1; h <= side; h++) {
            long w = Math.min(side, max / h);
            if (h * (3 * w + 1) > worstH * (3 * worstW + 1)) {
                worstW = w;
                worstH = h;
            }
        }
        long[][] shapes = {{side, max / side}, {max / side, side}, {(long) Math.sqrt(max), (long) Math.sqrt(max)}, {side, 1}, {1, side},
            {worstW, worstH}};
        for (long[] s : shapes) {
            long w = s[0], h = s[1];
            org.junit.jupiter.api.Assertions.assertTrue(w * h <= max && w <= side && h <= side, w + " x " + h + " is admitted");
            org.junit.jupiter.api.Assertions.assertTrue(3 * w * h <= arrayMax, "RGB doubles of " + w + " x " + h);
            org.junit.jupiter.api.Assertions.assertTrue(PngEncoder.largestBuffer(w, h) <= arrayMax, "encoder buffer of " + w + " x " + h);
        }
        org.junit.jupiter.api.Assertions.assertTrue(worstH * (3 * worstW + 1) > Integer.MAX_VALUE,
                "a whole-image scanline buffer would not fit: " + worstW + " x " + worstH + " needs " + worstH * (3 * worstW + 1));
    }
}
