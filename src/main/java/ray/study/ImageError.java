package ray.study;

import ray.render.Image;

/**
 * How far an image is from a reference, measured on the clamped linear image in units of the [0, 1]
 * range (the values the PNG quantises): root-mean-square error over all channels, PSNR, the largest
 * channel error, and the share of pixels with some channel more than one 8-bit step (1/255) off.
 */
public final class ImageError {

    /** One 8-bit step in units of the [0, 1] range. */
    public static final double STEP = 1.0 / 255;

    public final double rmse;
    /** 20 log10(1 / rmse); infinite for identical images. */
    public final double psnrDb;
    public final double maxError;
    public final double shareOffByMoreThanOneStep;

    private ImageError(double rmse, double maxError, double share) {
        this.rmse = rmse;
        this.psnrDb = psnr(rmse);
        this.maxError = maxError;
        this.shareOffByMoreThanOneStep = share;
    }

    /** The error of {@code image} against {@code reference}; both clamped to [0, 1] first. */
    public static ImageError of(Image image, Image reference) {
        if (image.width != reference.width || image.height != reference.height) {
            throw new IllegalArgumentException("image is " + image.width + "x" + image.height
                    + ", reference " + reference.width + "x" + reference.height);
        }
        double[] a = image.rgb, b = reference.rgb;
        double sum = 0, max = 0;
        long off = 0;
        for (int p = 0; p < a.length; p += 3) {
            boolean pixelOff = false;
            for (int c = p; c < p + 3; c++) {
                double d = Math.abs(clamp(a[c]) - clamp(b[c]));
                sum += d * d;
                max = Math.max(max, d);
                pixelOff |= d > STEP;
            }
            if (pixelOff) {
                off++;
            }
        }
        int pixels = a.length / 3;
        return new ImageError(pixels == 0 ? 0 : Math.sqrt(sum / a.length), max, pixels == 0 ? 0 : (double) off / pixels);
    }

    /** PSNR in dB of a root-mean-square error in units of the [0, 1] range. */
    public static double psnr(double rmse) {
        return rmse == 0 ? Double.POSITIVE_INFINITY : -20 * Math.log10(rmse);
    }

    /** [0, 1] clamp; NaN becomes 0, as the PNG writer treats it. */
    static double clamp(double v) {
        return v > 0 ? (v < 1 ? v : 1) : 0;
    }

    /** Per-pixel error (root mean square over the three channels), for finding the worst region. */
    public static double[] perPixel(Image image, Image reference) {
        double[] out = new double[image.width * image.height];
        for (int i = 0; i < out.length; i++) {
            double s = 0;
            for (int c = 0; c < 3; c++) {
                double d = clamp(image.rgb[3 * i + c]) - clamp(reference.rgb[3 * i + c]);
                s += d * d;
            }
            out[i] = Math.sqrt(s / 3);
        }
        return out;
    }

    @Override
    public String toString() {
        return String.format("rmse %.3g, psnr %.1f dB, max %.3g, %.1f%% of pixels off by more than one step",
                rmse, psnrDb, maxError, 100 * shareOffByMoreThanOneStep);
    }
}
