package ray.viewer;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * A render against a reference image, pixel by pixel in the PNG's own unit, 8-bit steps: each pixel's
 * difference is the largest over its three channels of |render - reference| (0 to 255). It counts the
 * pixels off by more than one step (one step is rounding; more is a real difference) and paints a heat
 * map from black (equal) through red and orange to white at {@link #scaleTop()} steps, the largest
 * difference found (at least 2, so an image off by one step everywhere stays dark). Pure: no Swing.
 */
final class Compare {

    /** Colour stops of the heat map (a black-red-yellow-white ramp, readable in grey print too). */
    private static final int[] RAMP = {0x000000, 0x3b0f70, 0x8c2981, 0xde4968, 0xfe9f6d, 0xfcfdbf};

    final int width, height;
    private final int[] steps;
    private final int max;
    private final long overOne;

    private Compare(int width, int height, int[] steps, int max, long overOne) {
        this.width = width;
        this.height = height;
        this.steps = steps;
        this.max = max;
        this.overOne = overOne;
    }

    /**
     * Compares two images of the same size ({@link #sizeMismatch} first); their RGB values are the 8-bit
     * values shown at exposure 0 (the PNG's).
     */
    static Compare of(BufferedImage render, BufferedImage reference) {
        int w = render.getWidth(), h = render.getHeight();
        int[] a = render.getRGB(0, 0, w, h, null, 0, w), b = reference.getRGB(0, 0, w, h, null, 0, w);
        int[] d = new int[w * h];
        int max = 0;
        long over = 0;
        for (int i = 0; i < d.length; i++) {
            int x = a[i], y = b[i];
            int s = Math.max(Math.abs((x >> 16 & 255) - (y >> 16 & 255)),
                    Math.max(Math.abs((x >> 8 & 255) - (y >> 8 & 255)), Math.abs((x & 255) - (y & 255))));
            d[i] = s;
            max = Math.max(max, s);
            if (s > 1) {
                over++;
            }
        }
        return new Compare(w, h, d, max, over);
    }

    /** Why two images cannot be compared (their sizes differ), or null. */
    static String sizeMismatch(BufferedImage render, BufferedImage reference) {
        if (render.getWidth() == reference.getWidth() && render.getHeight() == reference.getHeight()) {
            return null;
        }
        return "the reference is " + reference.getWidth() + "x" + reference.getHeight() + ", the render "
                + render.getWidth() + "x" + render.getHeight() + ": not compared";
    }

    /**
     * The scene's own reference image, or null: {@code reference-images/<name>.png} beside the scene or
     * beside its folder (the repository's and the course kit's layout: {@code scenes/x.txt} and
     * {@code reference-images/x.png}).
     */
    static Path referenceFor(Path scene) {
        Path abs = scene.toAbsolutePath().normalize();
        String name = abs.getFileName().toString();
        String png = (name.toLowerCase(Locale.ROOT).endsWith(".txt") ? name.substring(0, name.length() - 4) : name) + ".png";
        Path dir = abs.getParent();
        for (Path d : new Path[] {dir, dir == null ? null : dir.getParent()}) {
            if (d != null && Files.isRegularFile(d.resolve("reference-images").resolve(png))) {
                return d.resolve("reference-images").resolve(png);
            }
        }
        return null;
    }

    /** The difference of pixel (x, y) in 8-bit steps. */
    int steps(int x, int y) {
        return steps[y * width + x];
    }

    /** The largest difference, in 8-bit steps. */
    int max() {
        return max;
    }

    /** Pixels off by more than one 8-bit step in some channel. */
    long overOneStep() {
        return overOne;
    }

    /** The number of steps shown white in the heat map. */
    int scaleTop() {
        return Math.max(2, max);
    }

    /** {@code 1,234 of 19,200 pixels (6.4%) off by more than 1 step; largest 37 steps}. */
    String summary() {
        long n = (long) width * height;
        if (overOne == 0) {
            return max == 0 ? "identical to the reference" : "within 1 step of the reference everywhere";
        }
        return String.format(Locale.ROOT, "%,d of %,d pixels (%.1f%%) off by more than 1 step; largest %d steps",
                overOne, n, 100.0 * overOne / n, max);
    }

    /** The heat map: 0 steps black, {@link #scaleTop()} steps white. */
    BufferedImage heatMap() {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int[] row = new int[width];
        double top = scaleTop();
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                row[x] = colour(steps[y * width + x] / top);
            }
            img.setRGB(0, y, width, 1, row, 0, width);
        }
        return img;
    }

    /** The ramp's colour at {@code t} in [0, 1] (clamped), interpolated between its stops. */
    static int colour(double t) {
        double u = Math.max(0, Math.min(1, t)) * (RAMP.length - 1);
        int i = Math.min(RAMP.length - 2, (int) u);
        double f = u - i;
        int a = RAMP[i], b = RAMP[i + 1], c = 0;
        for (int shift = 16; shift >= 0; shift -= 8) {
            int ca = a >> shift & 255, cb = b >> shift & 255;
            c |= (int) Math.round(ca + f * (cb - ca)) << shift;
        }
        return c;
    }
}
