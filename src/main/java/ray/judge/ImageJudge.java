package ray.judge;

import java.awt.image.BufferedImage;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.Map;
import ray.render.Image;

/**
 * Judges a candidate image against a reference image of the same scene, rendered deterministically (for
 * stochastic renders see {@link StatJudge}). The policy ({@link Policy}, docs/grading.md):
 *
 * <ol>
 * <li><b>Edges</b> are found in the reference: pixels where it bends sharply (a second difference along a
 *     row, column or diagonal above {@code edgeContrast} steps in some channel; a smooth gradient, however
 *     steep, is no edge), widened by one pixel. An edge pixel is right when each
 *     channel lies within the range of the reference's neighbourhood and within {@code edgeShare} of that
 *     range of the reference pixel (both plus {@code pixelTolerance}): another anti-aliasing pattern passes,
 *     missing anti-aliasing (jaggies) or a moved silhouette does not.</li>
 * <li><b>Every other pixel</b> is wrong when a channel differs by more than {@code pixelTolerance} steps.</li>
 * <li><b>Systematic differences</b>: in tiles of {@code biasTile}^2 pixels, the mean signed difference of the
 *     off-edge pixels per channel, t-tested against zero with the tile's own spread (Sidak-corrected over all
 *     tiles and channels), is a bias when it exceeds {@code biasSteps} and is significant. Its pixels that
 *     differ in the bias's direction are wrong. This catches a broken material whose largest difference (2
 *     steps) hides below any per-pixel tolerance that lets harmless noise pass.</li>
 * <li><b>Credit</b> is the share of the picture's content that is right: 1 - wrong / content, where content
 *     counts the pixels that differ from the reference's most common colour (its background); a passing image
 *     gets 1. It <b>passes</b> when at most {@code maxWrongShare} of its pixels are wrong, no tile is biased,
 *     and its mean FLIP error is at most {@code maxFlipMean}.</li>
 * <li><b>Where</b>: each wrong pixel is put in one class (a biased tile's: other; a value within the
 *     reference's 3 x 3 range where the reference varies (an edge or a steep gradient): edges, i.e. sampling;
 *     a whitish excess where the brighter image is less saturated: highlights; light taken
 *     away, the excess of the lit pixel's colour, with the lit colour found nearby in the darker image:
 *     shadows; else other); a connected area of wrong pixels takes one class: an area all brighter or all
 *     darker is light added or taken away (highlight, shadow or other), never sampling; an area whose
 *     differences go both ways is sampling (edges). Half
 *     the content wrong is the whole image; a class holding half the wrong pixels names the image; else
 *     regions.</li>
 * </ol>
 */
public final class ImageJudge {

    /** A class must hold this share of the wrong pixels to name the difference. */
    static final double CLASS_SHARE = 0.5;
    /** This share of the content wrong is the whole image. */
    static final double WHOLE_SHARE = 0.5;
    /** Tiles with fewer off-edge pixels than this are not tested for bias. */
    static final int MIN_TILE_PIXELS = 8;
    /** An area of wrong pixels this large whose luminance differences mostly share a sign ... */
    static final int COHERENT_PIXELS = 4;
    /** ... (|sum| at least this share of sum of |d|) is light added or taken away, not sampling. */
    static final double COHERENCE = 0.7;
    /** How far (pixels) the shadow rule looks for the lit colour. */
    static final int SHADOW_RADIUS = 24;

    /** Chromaticities (r and g shares of r + g + b) this close are the same colour. */
    static final double CHROMA = 0.05;

    private static final int OTHER = 0, EDGE = 1, HIGHLIGHT = 2, SHADOW = 3;

    private ImageJudge() {
    }

    /** {@link #judge(Image, Image, Policy)} of two 8-bit images with the default policy. */
    public static Judgement judge(BufferedImage reference, BufferedImage candidate) {
        return judge(Images.fromBufferedImage(reference), Images.fromBufferedImage(candidate), Policy.DEFAULT);
    }

    /** {@link #judge(Image, Image, Policy)} with the default policy. */
    public static Judgement judge(Image reference, Image candidate) {
        return judge(reference, candidate, Policy.DEFAULT);
    }

    /**
     * Judges {@code candidate} against {@code reference}: images of display values in [0, 1] (a PNG's bytes /
     * 255, or a film's means; values outside are clamped, NaN is black as the PNG writer makes it).
     */
    public static Judgement judge(Image reference, Image candidate, Policy policy) {
        if (reference.width != candidate.width || reference.height != candidate.height) {
            Map<String, Double> m = new LinkedHashMap<>();
            m.put("score", 0.0);
            return new Judgement(0, false, Difference.SIZE, String.format("FAIL: the image is %dx%d, the reference %dx%d",
                    candidate.width, candidate.height, reference.width, reference.height), m, candidate.width,
                    candidate.height, new double[0], new boolean[0], false);
        }
        return new Run(reference, candidate, policy).judge();
    }

    /** One judgement's working state. */
    private static final class Run {
        final Image refImage, candImage;
        final Policy policy;
        final int w, h, n;
        final double[] r, c;        // channel values in steps (0 to 255)
        final double[] lo, hi;      // the reference's 3 x 3 range per channel
        final boolean[] edge;
        final boolean[] wrong;
        final boolean[] byBias;     // wrong only through a biased tile
        final double[] diff;        // largest channel |difference| in steps

        Run(Image reference, Image candidate, Policy policy) {
            this.refImage = reference;
            this.candImage = candidate;
            this.policy = policy;
            w = reference.width;
            h = reference.height;
            n = w * h;
            r = steps(reference);
            c = steps(candidate);
            lo = new double[3 * n];
            hi = new double[3 * n];
            edge = new boolean[n];
            wrong = new boolean[n];
            byBias = new boolean[n];
            diff = new double[n];
        }

        Judgement judge() {
            findEdges();
            int edgePixels = 0, edgeWrong = 0, offWrong = 0;
            double maxOff = 0, sumAbs = 0;
            int maxAt = 0;
            double tol = policy.pixelTolerance();
            for (int p = 0; p < n; p++) {
                double d = 0;
                for (int ch = 0; ch < 3; ch++) {
                    d = Math.max(d, Math.abs(c[3 * p + ch] - r[3 * p + ch]));
                }
                diff[p] = d;
                sumAbs += d;
                if (edge[p]) {
                    edgePixels++;
                    if (!edgeRight(p, tol)) {
                        wrong[p] = true;
                        edgeWrong++;
                    }
                } else {
                    if (d > maxOff) {
                        maxOff = d;
                        maxAt = p;
                    }
                    if (d > tol) {
                        wrong[p] = true;
                        offWrong++;
                    }
                }
            }
            int[] bias = findBias();
            int biasedTiles = bias[0], biasWrong = bias[1];
            int wrongCount = edgeWrong + offWrong + biasWrong;
            int content = contentPixels(r, tol);
            double[] flip = Flip.errorMap(refImage, candImage, policy.pixelsPerDegree());
            double flipMean = Flip.mean(flip);
            double wrongShare = (double) wrongCount / n;
            boolean passed = wrongShare <= policy.maxWrongShare() && biasedTiles == 0 && flipMean <= policy.maxFlipMean();
            double score = passed ? 1 : Math.max(0, 1 - (double) wrongCount / content);
            int[] classes = classify();
            Difference where = where(wrongCount, content, classes);
            if (passed && where != Difference.NONE && wrongCount == 0) {
                where = Difference.NONE;
            }

            Map<String, Double> m = new LinkedHashMap<>();
            m.put("score", score);
            m.put("wrong_share", wrongShare);
            m.put("wrong_pixels", (double) wrongCount);
            m.put("content_pixels", (double) content);
            m.put("edge_pixels", (double) edgePixels);
            m.put("edge_wrong_share", edgePixels == 0 ? 0 : (double) edgeWrong / edgePixels);
            m.put("off_edge_wrong_share", n - edgePixels == 0 ? 0 : (double) offWrong / (n - edgePixels));
            m.put("biased_tiles", (double) biasedTiles);
            m.put("bias_wrong_pixels", (double) biasWrong);
            m.put("max_off_edge_steps", maxOff);
            m.put("mean_abs_steps", sumAbs / n);
            m.put("flip_mean", flipMean);
            m.put("flip_max", max(flip));
            m.put("wrong_edges", (double) classes[EDGE]);
            m.put("wrong_highlights", (double) classes[HIGHLIGHT]);
            m.put("wrong_shadows", (double) classes[SHADOW]);
            m.put("wrong_other", (double) classes[OTHER]);

            StringBuilder msg = new StringBuilder(passed ? "PASS" : "FAIL");
            msg.append(String.format(": %d of %d pixels wrong (%.2f%%), %s", wrongCount, n, 100 * wrongShare,
                    where == Difference.NONE && wrongCount > 0 ? "within the allowance" : where.summary()));
            if (biasedTiles > 0) {
                msg.append(String.format("; %d region%s systematically off", biasedTiles, biasedTiles == 1 ? "" : "s"));
            }
            if (wrongCount > 0) {
                msg.append("; wrong pixels within ").append(boundingBox());
            }
            msg.append(String.format("; largest off-edge difference %.0f steps at (%d, %d); FLIP %.4f; credit %.0f%%",
                    maxOff, maxAt % w, maxAt / w, flipMean, 100 * score));
            if (!passed && flipMean > policy.maxFlipMean()) {
                msg.append(String.format(" (FLIP above %.3g)", policy.maxFlipMean()));
            }
            return new Judgement(score, passed, where, msg.toString(), m, w, h, diff, wrong, false);
        }

        /**
         * Edge pixels: where the reference bends sharply (a second difference along a row, a column or a
         * diagonal above {@code edgeContrast} in some channel: a smooth gradient, however steep, has none),
         * widened by one pixel; and every pixel's 3 x 3 range per channel (lo, hi).
         */
        void findEdges() {
            boolean[] core = new boolean[n];
            int[][] dirs = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int p = y * w + x;
                    boolean isEdge = false;
                    for (int ch = 0; ch < 3; ch++) {
                        double mn = Double.MAX_VALUE, mx = -Double.MAX_VALUE;
                        for (int j = Math.max(0, y - 1); j <= Math.min(h - 1, y + 1); j++) {
                            for (int i = Math.max(0, x - 1); i <= Math.min(w - 1, x + 1); i++) {
                                double v = r[3 * (j * w + i) + ch];
                                mn = Math.min(mn, v);
                                mx = Math.max(mx, v);
                            }
                        }
                        lo[3 * p + ch] = mn;
                        hi[3 * p + ch] = mx;
                        for (int[] d : dirs) {
                            int xa = x - d[0], ya = y - d[1], xb = x + d[0], yb = y + d[1];
                            if (xa < 0 || xb < 0 || xa >= w || xb >= w || ya < 0 || yb < 0 || ya >= h || yb >= h) {
                                continue;
                            }
                            double bend = r[3 * (ya * w + xa) + ch] - 2 * r[3 * p + ch] + r[3 * (yb * w + xb) + ch];
                            isEdge |= Math.abs(bend) > policy.edgeContrast();
                        }
                    }
                    core[p] = isEdge;
                }
            }
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    boolean e = false;
                    for (int j = Math.max(0, y - 1); j <= Math.min(h - 1, y + 1) && !e; j++) {
                        for (int i = Math.max(0, x - 1); i <= Math.min(w - 1, x + 1) && !e; i++) {
                            e = core[j * w + i];
                        }
                    }
                    edge[y * w + x] = e;
                }
            }
        }

        boolean edgeRight(int p, double tol) {
            for (int ch = 0; ch < 3; ch++) {
                int i = 3 * p + ch;
                double v = c[i], range = hi[i] - lo[i];
                if (v < lo[i] - tol || v > hi[i] + tol || Math.abs(v - r[i]) > tol + policy.edgeShare() * range) {
                    return false;
                }
            }
            return true;
        }

        /** Tiles whose off-edge mean difference is a significant bias: marks their pixels; {tiles, newly wrong pixels}. */
        int[] findBias() {
            int t = policy.biasTile();
            int tx = (w + t - 1) / t, ty = (h + t - 1) / t;
            double[][] mean = new double[tx * ty][3], p = new double[tx * ty][3];
            int tested = 0;
            for (int b = 0; b < tx * ty; b++) {
                int x0 = b % tx * t, y0 = b / tx * t, count = 0;
                double[] s = new double[3], s2 = new double[3];
                for (int y = y0; y < Math.min(h, y0 + t); y++) {
                    for (int x = x0; x < Math.min(w, x0 + t); x++) {
                        int q = y * w + x;
                        if (edge[q]) {
                            continue;
                        }
                        count++;
                        for (int ch = 0; ch < 3; ch++) {
                            double d = c[3 * q + ch] - r[3 * q + ch];
                            s[ch] += d;
                            s2[ch] += d * d;
                        }
                    }
                }
                for (int ch = 0; ch < 3; ch++) {
                    if (count < MIN_TILE_PIXELS) {
                        mean[b][ch] = 0;
                        p[b][ch] = 1;
                        continue;
                    }
                    double m = s[ch] / count, var = Math.max(0, (s2[ch] - count * m * m) / (count - 1));
                    mean[b][ch] = m;
                    p[b][ch] = StatTest.pValue(new StatTest.Estimate(m, var / count, count - 1), 0);
                    tested++;
                }
            }
            if (tested == 0 || policy.biasSteps() == Double.MAX_VALUE) {
                return new int[] {0, 0};
            }
            double level = StatTest.sidak(policy.biasAlpha(), tested);
            int tiles = 0, marked = 0;
            for (int b = 0; b < tx * ty; b++) {
                boolean biased = false;
                int x0 = b % tx * t, y0 = b / tx * t;
                for (int ch = 0; ch < 3; ch++) {
                    if (Math.abs(mean[b][ch]) > policy.biasSteps() && p[b][ch] < level) {
                        biased = true;
                        double sign = Math.signum(mean[b][ch]);
                        for (int y = y0; y < Math.min(h, y0 + t); y++) {
                            for (int x = x0; x < Math.min(w, x0 + t); x++) {
                                int q = y * w + x;
                                if (!edge[q] && !wrong[q] && sign * (c[3 * q + ch] - r[3 * q + ch]) >= 0.5) {
                                    wrong[q] = true;
                                    byBias[q] = true;
                                    marked++;
                                }
                            }
                        }
                    }
                }
                if (biased) {
                    tiles++;
                }
            }
            return new int[] {tiles, marked};
        }

        /**
         * How many wrong pixels fall in each class (OTHER, EDGE, HIGHLIGHT, SHADOW). A connected area of wrong
         * pixels (8-neighbours) takes one class for all its pixels. An area that is coherently brighter or
         * darker (four pixels or more, |sum of luminance differences| >= 0.7 sum of their sizes) is light added
         * or taken away: the most common of highlight, shadow and other, judged without the sampling rule (a
         * broader highlight stays within the reference's local range, yet is no sampling difference). An area
         * whose differences go both ways (jaggies along an edge, a far checkerboard breaking up into a
         * pattern, a silhouette moved) is EDGE; so is an area of fewer than four pixels whose pixels mostly are.
         */
        int[] classify() {
            int[] k = new int[4];
            boolean[] seen = new boolean[n];
            int[] queue = new int[n];
            for (int start = 0; start < n; start++) {
                if (!wrong[start] || seen[start]) {
                    continue;
                }
                int head = 0, tail = 0;
                queue[tail++] = start;
                seen[start] = true;
                int[] all = new int[4], apart = new int[4];
                double signed = 0, total = 0;
                while (head < tail) {
                    int p = queue[head++];
                    all[classOf(p, true)]++;
                    apart[classOf(p, false)]++;
                    double d = luminance(c, p) - luminance(r, p);
                    signed += d;
                    total += Math.abs(d);
                    int x = p % w, y = p / w;
                    for (int j = Math.max(0, y - 1); j <= Math.min(h - 1, y + 1); j++) {
                        for (int i = Math.max(0, x - 1); i <= Math.min(w - 1, x + 1); i++) {
                            int q = j * w + i;
                            if (wrong[q] && !seen[q]) {
                                seen[q] = true;
                                queue[tail++] = q;
                            }
                        }
                    }
                }
                // an area that is all brighter or all darker is light added or taken away; one whose differences
                // go both ways (along an edge, in a pattern that aliases) is sampling
                boolean coherent = tail >= COHERENT_PIXELS && Math.abs(signed) >= COHERENCE * total;
                int best = EDGE;
                if (coherent) {
                    best = OTHER;
                    for (int c2 = HIGHLIGHT; c2 <= SHADOW; c2++) {
                        if (apart[c2] > apart[best]) {
                            best = c2;
                        }
                    }
                } else if (tail < COHERENT_PIXELS) {
                    for (int c2 = 0; c2 < 4; c2++) {
                        if (all[c2] > all[best]) {
                            best = c2;
                        }
                    }
                }
                k[best] += tail;
            }
            return k;
        }

        /**
         * One wrong pixel's class (see {@link ImageJudge}); {@code sampling}: a value within the reference's
         * local range where the reference varies is EDGE (else only highlight, shadow or other).
         */
        int classOf(int p, boolean sampling) {
            if (byBias[p]) {
                return OTHER;       // a region's systematic difference, however it looks pixel by pixel
            }
            double tol = policy.pixelTolerance();
            // a value within the reference's local range where the reference varies (an edge, a steep gradient):
            // anti-aliasing, sampling inside the pixel, or a silhouette's place
            if (sampling) {
                boolean inRange = true;
                double range = 0;
                for (int ch = 0; ch < 3; ch++) {
                    int i = 3 * p + ch;
                    inRange &= c[i] >= lo[i] - tol && c[i] <= hi[i] + tol;
                    range = Math.max(range, hi[i] - lo[i]);
                }
                if (inRange && (edge[p] || range > 2 * tol)) {
                    return EDGE;
                }
            }
            boolean candBrighter = luminance(c, p) >= luminance(r, p);
            double[] bright = candBrighter ? c : r, dark = candBrighter ? r : c;
            double[] e = new double[3];
            double eMax = 0, eMin = Double.MAX_VALUE;
            for (int ch = 0; ch < 3; ch++) {
                e[ch] = bright[3 * p + ch] - dark[3 * p + ch];
                eMax = Math.max(eMax, e[ch]);
                if (bright[3 * p + ch] < 254) {
                    eMin = Math.min(eMin, e[ch]);      // a channel clipped at white cannot show its excess
                }
            }
            double lb = luminance(bright, p), ld = luminance(dark, p);
            // highlight: a whitish excess, the brighter pixel less saturated than the darker (or both grey and bright)
            if (eMax > tol && (eMin == Double.MAX_VALUE || eMin >= 0.5 * eMax)
                    && (saturation(bright, p) < saturation(dark, p) - 0.03 || saturation(dark, p) < 0.05 && lb > 200)) {
                return HIGHLIGHT;
            }
            // shadow: light taken away: the excess has the brighter pixel's colour (a lit surface less its
            // ambient), and the brighter colour is found nearby in the darker image (the same surface, lit)
            if (lb >= 1.15 * ld + 4 && sameChroma(e, 0, bright, p) && foundNearby(dark, bright, p)) {
                return SHADOW;
            }
            return OTHER;
        }

        boolean foundNearby(double[] img, double[] colourOf, int p) {
            int x = p % w, y = p / w;
            double lb = luminance(colourOf, p);
            for (int j = Math.max(0, y - SHADOW_RADIUS); j <= Math.min(h - 1, y + SHADOW_RADIUS); j += 2) {
                for (int i = Math.max(0, x - SHADOW_RADIUS); i <= Math.min(w - 1, x + SHADOW_RADIUS); i += 2) {
                    int q = j * w + i;
                    if (q != p && !wrong[q] && Math.abs(luminance(img, q) - lb) <= 0.15 * lb + 4
                            && sameChroma(img, q, colourOf, p)) {
                        return true;
                    }
                }
            }
            return false;
        }

        Difference where(int wrongCount, int content, int[] classes) {
            if (wrongCount == 0) {
                return Difference.NONE;
            }
            if (wrongCount >= WHOLE_SHARE * content) {
                return Difference.WHOLE_IMAGE;
            }
            int best = OTHER;
            for (int k = EDGE; k <= SHADOW; k++) {
                if (classes[k] > classes[best]) {
                    best = k;
                }
            }
            if (best != OTHER && classes[best] >= CLASS_SHARE * wrongCount) {
                return best == EDGE ? Difference.EDGES : best == HIGHLIGHT ? Difference.HIGHLIGHTS : Difference.SHADOWS;
            }
            return Difference.REGION;
        }

        String boundingBox() {
            int x0 = w, y0 = h, x1 = -1, y1 = -1;
            for (int p = 0; p < n; p++) {
                if (wrong[p]) {
                    x0 = Math.min(x0, p % w);
                    x1 = Math.max(x1, p % w);
                    y0 = Math.min(y0, p / w);
                    y1 = Math.max(y1, p / w);
                }
            }
            return String.format("x %d-%d, y %d-%d", x0, x1, y0, y1);
        }
    }

    /**
     * The picture's content: pixels that differ from the image's most common 8-bit colour (its background) by
     * more than {@code tol} steps in some channel; at least 1. {@code r}: channel values in steps.
     */
    static int contentPixels(double[] r, double tol) {
        int n = r.length / 3;
        Map<Integer, Integer> counts = new HashMap<>();
        int mode = 0, best = -1;
        for (int p = 0; p < n; p++) {
            int key = (int) Math.round(r[3 * p]) << 16 | (int) Math.round(r[3 * p + 1]) << 8 | (int) Math.round(r[3 * p + 2]);
            int k = counts.merge(key, 1, Integer::sum);
            if (k > best) {
                best = k;
                mode = key;
            }
        }
        double[] bg = {mode >> 16 & 255, mode >> 8 & 255, mode & 255};
        int content = 0;
        for (int p = 0; p < n; p++) {
            for (int ch = 0; ch < 3; ch++) {
                if (Math.abs(r[3 * p + ch] - bg[ch]) > tol) {
                    content++;
                    break;
                }
            }
        }
        return Math.max(1, content);
    }

    static double[] steps(Image img) {
        double[] out = new double[img.rgb.length];
        for (int i = 0; i < out.length; i++) {
            out[i] = 255 * Flip.clamp(img.rgb[i]);
        }
        return out;
    }

    static double luminance(double[] v, int p) {
        return 0.2126 * v[3 * p] + 0.7152 * v[3 * p + 1] + 0.0722 * v[3 * p + 2];
    }

    static double saturation(double[] v, int p) {
        double mx = maxChannel(v, p), mn = Math.min(v[3 * p], Math.min(v[3 * p + 1], v[3 * p + 2]));
        return mx <= 0 ? 0 : (mx - mn) / mx;
    }

    static double maxChannel(double[] v, int p) {
        return Math.max(v[3 * p], Math.max(v[3 * p + 1], v[3 * p + 2]));
    }

    /** The same chromaticity (r and g shares of r + g + b within {@link #CHROMA}); two near-black colours count as the same. */
    static boolean sameChroma(double[] a, int p, double[] b, int q) {
        double sa = a[3 * p] + a[3 * p + 1] + a[3 * p + 2], sb = b[3 * q] + b[3 * q + 1] + b[3 * q + 2];
        if (sa < 6 || sb < 6) {
            return sa < 6 && sb < 6;
        }
        return Math.abs(a[3 * p] / sa - b[3 * q] / sb) <= CHROMA && Math.abs(a[3 * p + 1] / sa - b[3 * q + 1] / sb) <= CHROMA;
    }

    private static double max(double[] v) {
        double m = 0;
        for (double x : v) {
            m = Math.max(m, x);
        }
        return m;
    }
}
