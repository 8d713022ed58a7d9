package ray.render;

import java.awt.image.BufferedImage;
import javax.vecmath.Vector3d;

/** A width x height image of linear RGB doubles, row 0 at the top. */
public final class Image implements java.io.Serializable {

    private static final long serialVersionUID = 1L;

    public final int width;
    public final int height;
    /** r, g, b of pixel (x, y) at {@code 3 * (y * width + x)}. */
    public final double[] rgb;

    public Image(int width, int height) {
        this.width = width;
        this.height = height;
        this.rgb = new double[3 * width * height];
    }

    public void set(int x, int y, double r, double g, double b) {
        int i = 3 * (y * width + x);
        rgb[i] = r;
        rgb[i + 1] = g;
        rgb[i + 2] = b;
    }

    public Vector3d get(int x, int y) {
        int i = 3 * (y * width + x);
        return new Vector3d(rgb[i], rgb[i + 1], rgb[i + 2]);
    }

    /** The framework's layout: {@code [x][y]}. */
    public Vector3d[][] toVectors() {
        Vector3d[][] out = new Vector3d[width][height];
        for (int x = 0; x < width; x++) {
            for (int y = 0; y < height; y++) {
                out[x][y] = get(x, y);
            }
        }
        return out;
    }

    /** One channel value as the PNG stores it: clamped to [0, 1], then floor(255 v + 0.5). */
    public static int toByte(double v) {
        if (!(v > 0)) {
            return 0;                 // also NaN
        }
        if (v >= 1) {
            return 255;
        }
        return (int) (255 * v + 0.5);   // floor: positive here, and (int) truncates (C1 calls StrictMath for Math.floor)
    }

    /** The 8-bit sRGB-less image the PNG holds (no gamma, as the scene format specifies). */
    public BufferedImage toBufferedImage() {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int[] row = new int[width];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int i = 3 * (y * width + x);
                row[x] = toByte(rgb[i]) << 16 | toByte(rgb[i + 1]) << 8 | toByte(rgb[i + 2]);
            }
            img.setRGB(0, y, width, 1, row, 0, width);
        }
        return img;
    }
}
