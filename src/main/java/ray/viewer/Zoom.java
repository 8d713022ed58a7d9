package ray.viewer;

/**
 * The image's scale on screen: either "fit" (as large as fits the view; at first never above 1:1,
 * after "Zoom to fit" up to {@value #MAX}) or a
 * fixed step on a ladder of powers of two and their halves, 1:1 among them. Pure arithmetic.
 */
final class Zoom {

    static final double MIN = 1.0 / 16, MAX = 16;
    private static final double[] STEPS = ladder();

    private boolean fit = true;
    /** Fitting enlarges up to this: 1 at first (a small image is shown 1:1), {@link #MAX} after "Zoom to fit". */
    private double fitMax = 1;
    private double scale = 1;

    private static double[] ladder() {
        double[] s = new double[17];
        for (int i = 0; i < s.length; i++) {
            s[i] = Math.pow(2, (i - 8) / 2.0);     // 1/16 ... 1/sqrt2, 1, sqrt2, 2 ... 16
        }
        s[8] = 1;                                   // exactly 1:1
        return s;
    }

    boolean fit() {
        return fit;
    }

    void fitToView() {
        fit = true;
        fitMax = MAX;
    }

    void actualSize() {
        fit = false;
        scale = 1;
    }

    /** The scale at which an {@code iw x ih} image is drawn in a {@code vw x vh} view. */
    double scale(int iw, int ih, int vw, int vh) {
        if (!fit) {
            return scale;
        }
        if (iw <= 0 || ih <= 0 || vw <= 0 || vh <= 0) {
            return 1;
        }
        return Math.max(MIN, Math.min(fitMax, Math.min((double) vw / iw, (double) vh / ih)));
    }

    /** One step larger than {@code current} (the scale shown now, fitted or not). */
    void in(double current) {
        fit = false;
        scale = MAX;
        for (double s : STEPS) {
            if (s > current * 1.0001) {
                scale = s;
                return;
            }
        }
    }

    /** One step smaller than {@code current}. */
    void out(double current) {
        fit = false;
        scale = MIN;
        for (int i = STEPS.length - 1; i >= 0; i--) {
            if (STEPS[i] < current / 1.0001) {
                scale = STEPS[i];
                return;
            }
        }
    }
}
