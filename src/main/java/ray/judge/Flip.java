package ray.judge;

import ray.render.Image;

/**
 * LDR-FLIP, the perceptual difference evaluator of Andersson, Nilsson, Akenine-Möller, Oskarsson,
 * Åström and Fairchild ("FLIP: A Difference Evaluator for Alternating Images", HPG 2020; the
 * constants and the separable filters as in the 2021 tech report "Visualizing Errors in Rendered High
 * Dynamic Range Images" and NVIDIA's reference code), written from the paper. It gives each pixel an
 * error in [0, 1]: roughly how noticeable the difference is when one flips between the two images on a
 * screen at {@code ppd} pixels per degree of visual angle.
 *
 * <p>The pipeline: both images (sRGB-encoded display values in [0, 1]) to linear RGB and to the opponent
 * space YCxCz; each channel blurred by a contrast-sensitivity filter (a Gaussian for the achromatic and
 * red-green channels, a sum of two for blue-yellow), back to linear RGB clamped to the unit cube, to
 * L*a*b* with the Hunt adjustment; the HyAB distance raised to q_c and redistributed to [0, 1] (the colour
 * error). Separately, the achromatic channel's edges and points (first and second derivatives of a
 * Gaussian) of both images; their largest difference is the feature error. The pixel's FLIP value is
 * colour error ^ (1 - feature error). Borders repeat the edge pixel, as the reference code does.
 *
 * <p>Tested against values computed by NVIDIA's flip-evaluator 1.7 (tools/flip_reference.py).
 */
public final class Flip {

    /** The reference code's default observer: a 0.7 m wide 3840-pixel monitor seen from 0.7 m (67.02). */
    public static final double DEFAULT_PPD = 0.7 * (3840 / 0.7) * Math.PI / 180;

    // the paper's constants
    private static final double QC = 0.7, QF = 0.5, PC = 0.4, PT = 0.95, W = 0.082;
    // contrast sensitivity: a1 sqrt(pi / b1) exp(-pi^2 x^2 / b1) + a2 sqrt(pi / b2) exp(-pi^2 x^2 / b2) per channel
    private static final double[] A1 = {1, 1, 34.1}, B1 = {0.0047, 0.0053, 0.04};
    private static final double[] A2 = {0, 0, 13.5}, B2 = {1e-5, 1e-5, 0.025};
    // the D65 white point of the colour transforms
    private static final double[] WHITE = {0.950428545, 1.0, 1.088900371};
    // linear sRGB to XYZ (D65), the rational form the reference code uses
    private static final double[] M = {
        10135552.0 / 24577794, 8788810.0 / 24577794, 4435075.0 / 24577794,
        2613072.0 / 12288897, 8788810.0 / 12288897, 887015.0 / 12288897,
        1425312.0 / 73733382, 8788810.0 / 73733382, 70074185.0 / 73733382};

    private Flip() {
    }

    /** The error map at the default 67 pixels per degree; see {@link #errorMap(Image, Image, double)}. */
    public static double[] errorMap(Image reference, Image test) {
        return errorMap(reference, test, DEFAULT_PPD);
    }

    /**
     * The FLIP value of each pixel (row by row, {@code reference.width * reference.height}), for images of
     * display values (what the PNG holds, divided by 255; clamped to [0, 1] first) seen at {@code ppd}
     * pixels per degree.
     */
    public static double[] errorMap(Image reference, Image test, double ppd) {
        if (reference.width != test.width || reference.height != test.height) {
            throw new IllegalArgumentException("images differ in size: " + reference.width + "x" + reference.height
                    + " and " + test.width + "x" + test.height);
        }
        if (!(ppd > 0) || Double.isInfinite(ppd)) {
            throw new IllegalArgumentException("pixels per degree must be positive and finite, got " + ppd);
        }
        int w = reference.width, h = reference.height;
        double[][] ref = toYCxCz(reference), tst = toYCxCz(test);
        double[] colour = colourError(ref, tst, w, h, ppd);
        double[] feature = featureError(ref[0], tst[0], w, h, ppd);
        double[] out = new double[w * h];
        for (int p = 0; p < out.length; p++) {
            out[p] = Math.pow(colour[p], 1 - feature[p]);
        }
        return out;
    }

    /** The mean of an error map. */
    public static double mean(double[] map) {
        double s = 0;
        for (double v : map) {
            s += v;
        }
        return map.length == 0 ? 0 : s / map.length;
    }

    // ---- colour pipeline ----

    private static double[] colourError(double[][] ref, double[][] tst, int w, int h, double ppd) {
        int r = (int) Math.ceil(3 * Math.sqrt(max(B1, B2) / (2 * Math.PI * Math.PI)) * ppd);
        double[] ky = csfKernel(r, ppd, A1[0], B1[0], false), kx = csfKernel(r, ppd, A1[1], B1[1], false);
        // blue-yellow: a sum of two Gaussians, each separable, their 2D weights summing to 1 together
        double[] kz1 = csfKernel(r, ppd, A1[2], B1[2], true), kz2 = csfKernel(r, ppd, A2[2], B2[2], true);
        double s1 = sum(kz1), s2 = sum(kz2), norm = 1 / Math.sqrt(s1 * s1 + s2 * s2);
        scale(kz1, norm);
        scale(kz2, norm);
        double[][] fr = {blur(ref[0], w, h, ky, ky), blur(ref[1], w, h, kx, kx),
            add(blur(ref[2], w, h, kz1, kz1), blur(ref[2], w, h, kz2, kz2))};
        double[][] ft = {blur(tst[0], w, h, ky, ky), blur(tst[1], w, h, kx, kx),
            add(blur(tst[2], w, h, kz1, kz1), blur(tst[2], w, h, kz2, kz2))};
        double cmax = Math.pow(hyab(huntLab(0, 1, 0), huntLab(0, 0, 1)), QC), pccmax = PC * cmax;
        double[] out = new double[w * h];
        double[] rgb = new double[3];
        for (int p = 0; p < out.length; p++) {
            ycxczToClampedLinear(fr[0][p], fr[1][p], fr[2][p], rgb);
            double[] a = huntLab(rgb[0], rgb[1], rgb[2]);
            ycxczToClampedLinear(ft[0][p], ft[1][p], ft[2][p], rgb);
            double[] b = huntLab(rgb[0], rgb[1], rgb[2]);
            double e = Math.pow(hyab(a, b), QC);
            out[p] = e < pccmax ? e * PT / pccmax : PT + (e - pccmax) / (cmax - pccmax) * (1 - PT);
        }
        return out;
    }

    /** One axis of a contrast-sensitivity filter, weights summing to 1 (or, {@code sqrtForm}, unnormalised sqrt of the 2D weight). */
    private static double[] csfKernel(int r, double ppd, double a, double b, boolean sqrtForm) {
        double[] k = new double[2 * r + 1];
        double pi2 = Math.PI * Math.PI;
        for (int i = -r; i <= r; i++) {
            double x = i / ppd;
            double g = Math.exp(-pi2 * x * x / b);
            k[i + r] = sqrtForm ? Math.sqrt(a * Math.sqrt(Math.PI / b)) * g : a * Math.sqrt(Math.PI / b) * g;
        }
        if (!sqrtForm) {
            scale(k, 1 / sum(k));
        }
        return k;
    }

    private static double hyab(double[] a, double[] b) {
        double da = a[1] - b[1], db = a[2] - b[2];
        return Math.abs(a[0] - b[0]) + Math.sqrt(da * da + db * db);
    }

    /** Linear RGB to CIE L*a*b* (D65) with the Hunt adjustment: a and b scaled by L / 100. */
    private static double[] huntLab(double r, double g, double b) {
        double x = (M[0] * r + M[1] * g + M[2] * b) / WHITE[0];
        double y = M[3] * r + M[4] * g + M[5] * b;
        double z = (M[6] * r + M[7] * g + M[8] * b) / WHITE[2];
        double fx = labF(x), fy = labF(y), fz = labF(z);
        double l = 116 * fy - 16;
        return new double[] {l, 0.01 * l * 500 * (fx - fy), 0.01 * l * 200 * (fy - fz)};
    }

    private static double labF(double t) {
        double d = 6.0 / 29;
        return t > d * d * d ? Math.cbrt(t) : t / (3 * d * d) + 4.0 / 29;
    }

    private static void ycxczToClampedLinear(double yy, double cx, double cz, double[] out) {
        double y = (yy + 16) / 116, x = (y + cx / 500) * WHITE[0], z = (y - cz / 200) * WHITE[2];
        out[0] = clamp(3.241003275 * x - 1.537398934 * y - 0.498615861 * z);
        out[1] = clamp(-0.969224334 * x + 1.875930071 * y + 0.041554224 * z);
        out[2] = clamp(0.055639423 * x - 0.204011202 * y + 1.057148933 * z);
    }

    // ---- feature pipeline ----

    private static double[] featureError(double[] yRef, double[] yTst, int w, int h, double ppd) {
        double sd = 0.5 * W * ppd;
        int r = (int) Math.ceil(3 * sd);
        double[] g = new double[2 * r + 1], dg = new double[2 * r + 1], ddg = new double[2 * r + 1];
        double gs = 0, dPos = 0, dNeg = 0, ddPos = 0, ddNeg = 0;
        for (int i = -r; i <= r; i++) {
            double v = Math.exp(-(double) i * i / (2 * sd * sd));
            g[i + r] = v;
            dg[i + r] = -i * v;
            ddg[i + r] = ((double) i * i / (sd * sd) - 1) * v;
            gs += v;
            if (dg[i + r] > 0) {
                dPos += dg[i + r];
            } else {
                dNeg -= dg[i + r];
            }
            if (ddg[i + r] > 0) {
                ddPos += ddg[i + r];
            } else {
                ddNeg -= ddg[i + r];
            }
        }
        // the Gaussian sums to 1; the derivatives' positive weights to 1 and negative ones to -1
        for (int i = 0; i < g.length; i++) {
            g[i] /= gs;
            dg[i] /= dg[i] > 0 ? dPos : dNeg;
            ddg[i] /= ddg[i] > 0 ? ddPos : ddNeg;
        }
        double[] a = normalisedY(yRef), b = normalisedY(yTst);
        double[] edgeA = magnitude(blur(a, w, h, dg, g), blur(a, w, h, g, dg));
        double[] edgeB = magnitude(blur(b, w, h, dg, g), blur(b, w, h, g, dg));
        double[] pointA = magnitude(blur(a, w, h, ddg, g), blur(a, w, h, g, ddg));
        double[] pointB = magnitude(blur(b, w, h, ddg, g), blur(b, w, h, g, ddg));
        double[] out = new double[w * h];
        for (int p = 0; p < out.length; p++) {
            double d = Math.max(Math.abs(edgeA[p] - edgeB[p]), Math.abs(pointA[p] - pointB[p]));
            out[p] = Math.pow(d / Math.sqrt(2), QF);
        }
        return out;
    }

    /** YCxCz's Y brought to [0, 1]. */
    private static double[] normalisedY(double[] y) {
        double[] out = new double[y.length];
        for (int i = 0; i < y.length; i++) {
            out[i] = (y[i] + 16) / 116;
        }
        return out;
    }

    private static double[] magnitude(double[] x, double[] y) {
        double[] out = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            out[i] = Math.sqrt(x[i] * x[i] + y[i] * y[i]);
        }
        return out;
    }

    // ---- shared ----

    /** sRGB display values to YCxCz planes {Y, Cx, Cz} (D65). */
    private static double[][] toYCxCz(Image img) {
        int n = img.width * img.height;
        double[][] out = new double[3][n];
        for (int p = 0; p < n; p++) {
            double r = linear(img.rgb[3 * p]), g = linear(img.rgb[3 * p + 1]), b = linear(img.rgb[3 * p + 2]);
            double x = (M[0] * r + M[1] * g + M[2] * b) / WHITE[0];
            double y = M[3] * r + M[4] * g + M[5] * b;
            double z = (M[6] * r + M[7] * g + M[8] * b) / WHITE[2];
            out[0][p] = 116 * y - 16;
            out[1][p] = 500 * (x - y);
            out[2][p] = 200 * (y - z);
        }
        return out;
    }

    /** An sRGB-encoded value (clamped to [0, 1]; NaN as 0) to linear. */
    static double linear(double s) {
        double c = clamp(s);
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /**
     * The separable convolution of plane {@code v} (w x h) with {@code kx} along rows then {@code ky} along
     * columns (odd lengths, centred), repeating the border pixels.
     */
    static double[] blur(double[] v, int w, int h, double[] kx, double[] ky) {
        double[] tmp = new double[w * h], out = new double[w * h];
        int rx = kx.length / 2, ry = ky.length / 2;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double s = 0;
                for (int i = -rx; i <= rx; i++) {
                    s += kx[i + rx] * v[y * w + Math.min(Math.max(x + i, 0), w - 1)];
                }
                tmp[y * w + x] = s;
            }
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double s = 0;
                for (int j = -ry; j <= ry; j++) {
                    s += ky[j + ry] * tmp[Math.min(Math.max(y + j, 0), h - 1) * w + x];
                }
                out[y * w + x] = s;
            }
        }
        return out;
    }

    private static double[] add(double[] a, double[] b) {
        for (int i = 0; i < a.length; i++) {
            a[i] += b[i];
        }
        return a;
    }

    private static double sum(double[] k) {
        double s = 0;
        for (double v : k) {
            s += v;
        }
        return s;
    }

    private static void scale(double[] k, double f) {
        for (int i = 0; i < k.length; i++) {
            k[i] *= f;
        }
    }

    private static double max(double[] a, double[] b) {
        double m = 0;
        for (int i = 0; i < a.length; i++) {
            m = Math.max(m, Math.max(a[i], b[i]));
        }
        return m;
    }

    static double clamp(double v) {
        return v > 0 ? Math.min(v, 1) : 0;
    }
}
