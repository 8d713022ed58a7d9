package ray.judge;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import ray.render.Film;
import ray.render.Image;

/**
 * The judge's inputs as {@link Image}s of display values in [0, 1]: an 8-bit PNG as the engine writes it
 * (a channel's byte / 255; the engine stores linear values clamped to [0, 1] without gamma, and a viewer
 * shows those bytes as sRGB), or a {@link Film}'s pixel means (the same numbers before the 8-bit rounding).
 */
public final class Images {

    private Images() {
    }

    /** Reads a PNG (or any format ImageIO knows) into display values; alpha is ignored. */
    public static Image read(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            BufferedImage img = ImageIO.read(in);
            if (img == null) {
                throw new IOException(file + ": not an image ImageIO can read");
            }
            return fromBufferedImage(img);
        }
    }

    /** The display values of an 8-bit image: each channel's byte / 255. */
    public static Image fromBufferedImage(BufferedImage img) {
        Image out = new Image(img.getWidth(), img.getHeight());
        int[] row = new int[img.getWidth()];
        for (int y = 0; y < img.getHeight(); y++) {
            img.getRGB(0, y, img.getWidth(), 1, row, 0, img.getWidth());
            for (int x = 0; x < row.length; x++) {
                int c = row[x];
                out.set(x, y, (c >> 16 & 255) / 255.0, (c >> 8 & 255) / 255.0, (c & 255) / 255.0);
            }
        }
        return out;
    }

    /** The film's pixel means (unrounded display values; the PNG would round them to 8 bits). */
    public static Image fromFilm(Film film) {
        Image out = new Image(film.width, film.height);
        film.writeTo(out);
        return out;
    }

    /** {@code image} rounded to 8 bits per channel as the PNG writer rounds it, back in [0, 1]. */
    public static Image quantised(Image image) {
        Image out = new Image(image.width, image.height);
        for (int i = 0; i < image.rgb.length; i++) {
            out.rgb[i] = Image.toByte(image.rgb[i]) / 255.0;
        }
        return out;
    }

    /** Writes a picture (heat map, side-by-side view) as a PNG. */
    public static void writePng(BufferedImage img, Path file) throws IOException {
        if (!ImageIO.write(img, "png", file.toFile())) {
            throw new IOException("no PNG writer available");
        }
    }
}
