package ray.render;

/**
 * The grid's points (same positions, same index numbering, 0.5 in every further dimension), taken in an
 * order that spreads any first few over the pixel, so a pixel can stop early: the renderer takes
 * {@link #firstBatch()} samples, then doubles the count while the pixel's estimated standard error is
 * at or above the target, up to all n_s x n_s. With every sample taken the pixel is the grid's pixel,
 * bit for bit (the renderer sums the taken samples in grid order).
 */
public final class AdaptiveSampler extends Sampler {

    private final int[] order;

    public AdaptiveSampler(int n) {
        super(n);
        order = farthestPointOrder(n);
    }

    @Override
    public double get(int x, int y, int index, int dim) {
        return GridSampler.gridValue(n, index, dim);
    }

    /** The grid index of the k-th sample taken. */
    public int order(int k) {
        return order[k];
    }

    /** Samples every pixel gets before its error is first estimated. */
    public int firstBatch() {
        int all = n * n;
        return Math.min(all, Math.max(4, all / 16));
    }

    /**
     * Grid cells ordered greedily: first the cell nearest the centre, then each time the cell farthest
     * from those already taken (ties to the lower index). Any prefix is spread over the pixel.
     */
    static int[] farthestPointOrder(int n) {
        int all = n * n;
        int[] order = new int[all];
        double[] nearest = new double[all];
        boolean[] taken = new boolean[all];
        int pick = 0;
        double best = Double.POSITIVE_INFINITY;
        for (int c = 0; c < all; c++) {
            double dx = c % n + 0.5 - n / 2.0, dy = c / n + 0.5 - n / 2.0, d = dx * dx + dy * dy;
            if (d < best) {
                best = d;
                pick = c;
            }
        }
        java.util.Arrays.fill(nearest, Double.POSITIVE_INFINITY);
        for (int k = 0; k < all; k++) {
            order[k] = pick;
            taken[pick] = true;
            int next = -1;
            double far = -1;
            for (int c = 0; c < all; c++) {
                if (taken[c]) {
                    continue;
                }
                double dx = c % n - pick % n, dy = c / n - pick / n;
                nearest[c] = Math.min(nearest[c], dx * dx + dy * dy);
                if (nearest[c] > far) {
                    far = nearest[c];
                    next = c;
                }
            }
            pick = next;
        }
        return order;
    }

    @Override
    public String name() {
        return "adaptive";
    }
}
