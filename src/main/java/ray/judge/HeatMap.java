package ray.judge;

import java.awt.image.BufferedImage;
import ray.render.Image;

/**
 * Difference pictures: a per-pixel value drawn with the magma colour map (black: none, through purple and
 * orange, to pale yellow: most) above a scale bar with its tick values, drawn with a small built-in digit
 * font so that no system font is needed. Images narrower than {@link #MIN_WIDTH} are enlarged by a whole
 * factor (each pixel a square block) so that the bar's labels fit.
 */
public final class HeatMap {

    /** Pictures are at least this wide (small images are enlarged by a whole factor). */
    public static final int MIN_WIDTH = 240;

    // magma (matplotlib, CC0: van der Walt and Smith) at 17 evenly spaced points; linear in between
    private static final double[][] MAGMA = {
        {0.001462, 0.000466, 0.013866}, {0.039608, 0.031090, 0.133515}, {0.113094, 0.065492, 0.276784},
        {0.211718, 0.061992, 0.418647}, {0.316654, 0.071690, 0.485380}, {0.414709, 0.110431, 0.504662},
        {0.512831, 0.148179, 0.507648}, {0.613617, 0.181811, 0.498536}, {0.716387, 0.214982, 0.475290},
        {0.816914, 0.255895, 0.436461}, {0.904281, 0.319610, 0.388137}, {0.960949, 0.418323, 0.359630},
        {0.986700, 0.535582, 0.382210}, {0.996096, 0.653659, 0.446213}, {0.996898, 0.769591, 0.534892},
        {0.992440, 0.884330, 0.640099}, {0.987053, 0.991438, 0.749504}};

    // 3 x 5 digits and '.', row by row, bit 2 = left column
    private static final int[][] DIGITS = {
        {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
        {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
    private static final int[] DOT = {0, 0, 0, 0, 2};

    private HeatMap() {
    }

    /** The magma colour of {@code t} in [0, 1] as 0xRRGGBB. */
    public static int magma(double t) {
        double x = Math.max(0, Math.min(1, Double.isNaN(t) ? 0 : t)) * (MAGMA.length - 1);
        int i = Math.min((int) x, MAGMA.length - 2);
        double f = x - i;
        int rgb = 0;
        for (int c = 0; c < 3; c++) {
            double v = MAGMA[i][c] + f * (MAGMA[i + 1][c] - MAGMA[i][c]);
            rgb = rgb << 8 | (int) Math.round(255 * v);
        }
        return rgb;
    }

    /**
     * Differences in 8-bit steps (0 to 255, row by row) on a logarithmic scale, log2(1 + d) / 8, with ticks at
     * 0, 1, 2, 4, ..., 128 and 255 steps: one step is already visible, a whole-range difference is the top.
     */
    public static BufferedImage ofSteps(double[] steps, int width, int height) {
        double[] t = new double[steps.length];
        for (int i = 0; i < t.length; i++) {
            t[i] = stepPosition(steps[i]);
        }
        double[] ticks = {0, 1, 2, 4, 8, 16, 32, 64, 128, 255};
        double[] at = new double[ticks.length];
        for (int i = 0; i < ticks.length; i++) {
            at[i] = stepPosition(ticks[i]);
        }
        return draw(t, width, height, ticks, at);
    }

    /** FLIP values (0 to 1) on a linear scale with ticks every 0.2, as FLIP's own tool shows them. */
    public static BufferedImage ofFlip(double[] flip, int width, int height) {
        double[] ticks = {0, 0.2, 0.4, 0.6, 0.8, 1};
        return draw(flip, width, height, ticks, ticks);
    }

    static double stepPosition(double steps) {
        return Math.log1p(Math.max(0, Math.min(255, steps))) / Math.log(2) / 8;
    }

    /** Reference | candidate | picture, enlarged alike, on one strip with 4-pixel gaps (the picture's bar hangs below). */
    public static BufferedImage sideBySide(Image reference, Image candidate, BufferedImage picture) {
        BufferedImage a = reference.toBufferedImage(), b = candidate.toBufferedImage();
        int k = picture.getWidth() / Math.max(1, reference.width);
        int w = k * reference.width, gap = 4;
        BufferedImage out = new BufferedImage(3 * w + 2 * gap, Math.max(picture.getHeight(), k * reference.height),
                BufferedImage.TYPE_INT_RGB);
        fill(out, 0xffffff);
        blit(out, a, 0, k);
        blit(out, b, w + gap, k);
        for (int y = 0; y < picture.getHeight(); y++) {
            for (int x = 0; x < picture.getWidth() && 2 * (w + gap) + x < out.getWidth(); x++) {
                out.setRGB(2 * (w + gap) + x, y, picture.getRGB(x, y));
            }
        }
        return out;
    }

    private static BufferedImage draw(double[] t, int width, int height, double[] ticks, double[] at) {
        int k = Math.max(1, (MIN_WIDTH + width - 1) / Math.max(1, width));
        int w = k * width, barTop = k * height + 4, barH = 12, labelTop = barTop + barH + 3;
        BufferedImage out = new BufferedImage(w, labelTop + 12, BufferedImage.TYPE_INT_RGB);
        fill(out, 0xffffff);
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int c = magma(t[y * width + x]);
                for (int j = 0; j < k; j++) {
                    for (int i = 0; i < k; i++) {
                        out.setRGB(k * x + i, k * y + j, c);
                    }
                }
            }
        }
        int margin = 8, len = w - 2 * margin;
        for (int x = 0; x < len; x++) {
            int c = magma(x / (double) (len - 1));
            for (int y = 0; y < barH; y++) {
                out.setRGB(margin + x, barTop + y, c);
            }
        }
        int lastRight = -100;
        for (int i = 0; i < ticks.length; i++) {
            int x = margin + (int) Math.round(at[i] * (len - 1));
            for (int y = barTop + barH; y < barTop + barH + 3; y++) {
                out.setRGB(x, y, 0);
            }
            String label = label(ticks[i]);
            int lw = label.length() * 8 - 2, left = Math.max(0, Math.min(w - lw, x - lw / 2));
            if (left > lastRight + 3) {      // skip labels that would overlap the previous one
                text(out, label, left, labelTop);
                lastRight = left + lw;
            }
        }
        return out;
    }

    private static String label(double v) {
        return v == Math.rint(v) ? Long.toString((long) v) : Double.toString(v).replaceAll("0+$", "");
    }

    /** Draws digits and dots, each glyph 3 x 5 cells of 2 x 2 pixels, 8 pixels apart. */
    private static void text(BufferedImage img, String s, int x0, int y0) {
        for (int i = 0; i < s.length(); i++) {
            char ch = s.charAt(i);
            int[] g = ch == '.' ? DOT : ch >= '0' && ch <= '9' ? DIGITS[ch - '0'] : null;
            if (g == null) {
                continue;
            }
            for (int row = 0; row < 5; row++) {
                for (int col = 0; col < 3; col++) {
                    if ((g[row] >> (2 - col) & 1) != 0) {
                        for (int dy = 0; dy < 2; dy++) {
                            for (int dx = 0; dx < 2; dx++) {
                                int x = x0 + 8 * i + 2 * col + dx, y = y0 + 2 * row + dy;
                                if (x < img.getWidth() && y < img.getHeight()) {
                                    img.setRGB(x, y, 0);
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    private static void fill(BufferedImage img, int rgb) {
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                img.setRGB(x, y, rgb);
            }
        }
    }

    private static void blit(BufferedImage dst, BufferedImage src, int x0, int k) {
        for (int y = 0; y < src.getHeight() * k; y++) {
            for (int x = 0; x < src.getWidth() * k; x++) {
                dst.setRGB(x0 + x, y, src.getRGB(x / k, y / k));
            }
        }
    }
}
