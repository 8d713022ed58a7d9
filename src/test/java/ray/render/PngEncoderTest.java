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
        int pos = 8, idatStart = -1, idatLen = 0;
        while (pos < png.length) {
            int len = (png[pos] & 0xFF) << 24 | (png[pos + 1] & 0xFF) << 16 | (png[pos + 2] & 0xFF) << 8 | png[pos + 3] & 0xFF;
            String type = new String(png, pos + 4, 4, java.nio.charset.StandardCharsets.US_ASCII);
            if (type.equals("IDAT")) {
                idatStart = pos + 8;
                idatLen = len;
            }
            pos += 12 + len;
        }
        assertEquals(png.length, pos);
        Inflater inf = new Inflater();
        inf.setInput(png, idatStart, idatLen);
        byte[] raw = new byte[img.height * (3 * img.width + 1) + 1];
        int n = inf.inflate(raw);
        assertEquals(true, inf.finished());
        assertEquals(img.height * (3 * img.width + 1), n);
        byte[] expected = PngEncoder.filterRows(img);
        byte[] got = new byte[n];
        System.arraycopy(raw, 0, got, 0, n);
        assertArrayEquals(expected, got);
    }
}
