package ray.grade;

import java.awt.image.BufferedImage;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The tolerance policy: a pixel is wrong when a channel is more than {@link #TOLERANCE} 8-bit steps off
 * its reference, except on an edge of the reference (a pixel whose channels differ from a neighbour's by
 * more than {@link #EDGE_STEP} steps), where sampling differences are expected and only a gross error
 * (more than {@link #EDGE_TOLERANCE}) counts. The image passes when under {@link #PASS_SHARE} of its pixels
 * are wrong; partial credit is the share of pixels that are right, scaled so that a quarter of the
 * pixels wrong gives nothing.
 */
final class PixelJudge implements Judge {

    static final int TOLERANCE = 3;
    static final int EDGE_STEP = 24;
    static final int EDGE_TOLERANCE = 96;
    static final double PASS_SHARE = 0.002;
    static final double ZERO_SHARE = 0.25;

    /** Without a statistical test: the first renders, pixel by pixel. */
    @Override
    public Verdict judge(java.util.List<BufferedImage> references, java.util.List<BufferedImage> candidates) {
        return judge(references.get(0), candidates.get(0), true);
    }

    @Override
    public Verdict judge(BufferedImage ref, BufferedImage cand, boolean stochastic) {
        int w = ref.getWidth(), h = ref.getHeight();
        Map<String, Double> metrics = new LinkedHashMap<>();
        if (cand.getWidth() != w || cand.getHeight() != h) {
            return new Verdict(0, false, "the image is " + cand.getWidth() + "x" + cand.getHeight() + ", the reference "
                    + w + "x" + h + ": check Scene.renderAll's array size ([width][height])", "size", metrics, null);
        }
        int[] r = ref.getRGB(0, 0, w, h, null, 0, w), c = cand.getRGB(0, 0, w, h, null, 0, w);
        BufferedImage heat = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int bad = 0, badEdge = 0, edges = 0, darker = 0, brighter = 0, brightRef = 0, maxOff = 0;
        double sum = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = y * w + x;
                int d = diff(r[i], c[i]);
                sum += d;
                boolean edge = isEdge(r, w, h, x, y);
                edges += edge ? 1 : 0;
                if (!edge) {
                    maxOff = Math.max(maxOff, d);
                }
                boolean wrong = d > (edge ? EDGE_TOLERANCE : TOLERANCE);
                if (wrong) {
                    bad++;
                    badEdge += edge ? 1 : 0;
                    int lr = luma(r[i]), lc = luma(c[i]);
                    if (lc > lr) {
                        brighter++;
                    } else {
                        darker++;
                    }
                    if (lr > 200) {
                        brightRef++;
                    }
                }
                heat.setRGB(x, y, heat(d, wrong));
            }
        }
        int n = w * h;
        double share = (double) bad / n;
        metrics.put("wrong pixels %", 100 * share);
        metrics.put("edge pixels %", 100.0 * edges / n);
        metrics.put("max error off edges (8-bit steps)", (double) maxOff);
        metrics.put("mean error (8-bit steps)", sum / n);
        boolean pass = share < PASS_SHARE;
        double fraction = pass ? 1 : Math.max(0, 1 - share / ZERO_SHARE);
        String kind;
        if (pass) {
            kind = "none";
        } else if (share > 0.5) {
            kind = "whole image";
        } else if (badEdge > 0.6 * bad) {
            kind = "edges";
        } else if (brighter > 0.7 * bad) {
            kind = "too bright (missing shadows?)";
        } else if (brightRef > 0.5 * bad) {
            kind = "highlights";
        } else if (darker > 0.7 * bad) {
            kind = "too dark";
        } else {
            kind = "regions";
        }
        String message = pass ? String.format(java.util.Locale.ROOT, "matches the reference (%.2f%% of pixels off, largest "
                + "error away from edges %d steps)", 100 * share, maxOff)
                : String.format(java.util.Locale.ROOT, "%.1f%% of the pixels differ from the reference (more than %d of 255 "
                + "steps away from edges); the differences: %s", 100 * share, TOLERANCE, kind);
        return new Verdict(fraction, pass, message, kind, metrics, heat);
    }

    private static int diff(int a, int b) {
        return Math.max(Math.abs((a >> 16 & 255) - (b >> 16 & 255)),
                Math.max(Math.abs((a >> 8 & 255) - (b >> 8 & 255)), Math.abs((a & 255) - (b & 255))));
    }

    private static int luma(int a) {
        return (2 * (a >> 16 & 255) + 5 * (a >> 8 & 255) + (a & 255)) / 8;
    }

    private static boolean isEdge(int[] r, int w, int h, int x, int y) {
        int c = r[y * w + x];
        return (x > 0 && diff(c, r[y * w + x - 1]) > EDGE_STEP) || (x + 1 < w && diff(c, r[y * w + x + 1]) > EDGE_STEP)
                || (y > 0 && diff(c, r[(y - 1) * w + x]) > EDGE_STEP) || (y + 1 < h && diff(c, r[(y + 1) * w + x]) > EDGE_STEP);
    }

    /** Black where equal, dim blue for small differences, yellow to red for wrong pixels. */
    private static int heat(int d, boolean wrong) {
        if (d == 0) {
            return 0;
        }
        if (!wrong) {
            return 0x000040 + Math.min(d, 8) * 16;
        }
        int t = Math.min(255, 64 + d * 2);
        return 255 << 16 | (255 - t) << 8;
    }
}
