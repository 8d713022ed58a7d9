package ray.render;

/**
 * The grid's points (same positions, same index numbering, 0.5 in every further dimension), taken in an
 * order that spreads any first few over the pixel, so a pixel can stop early: the renderer takes
 * {@link #firstBatch()} samples (4) for every pixel, then doubles a pixel's count while its estimated
 * standard error is at or above the target, up to all n_s x n_s (at least 16 near a possible edge). With every sample taken the pixel is the grid's pixel,
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
        return Math.min(n * n, 4);
    }

    /**
     * Grid cells ordered so that the prefixes the renderer uses (4, 8, 16, ...) are spread over the pixel
     * and point-symmetric about its centre (so a linear change of colour across the pixel averages out
     * exactly): first the rotated-grid pattern (3/8, 1/8), (5/8, 7/8), (7/8, 3/8), (1/8, 5/8) (distinct
     * rows and columns, the classic best four samples for near-horizontal and near-vertical edges), then
     * greedily the cell farthest from those taken (ties to the lower index) followed by its mirror image;
     * the centre cell of an odd grid comes last.
     */
    static int[] farthestPointOrder(int n) {
        int all = n * n;
        int[] order = new int[all];
        double[] nearest = new double[all];
        boolean[] taken = new boolean[all];
        java.util.Arrays.fill(nearest, Double.POSITIVE_INFINITY);
        int a = (int) Math.floor(n / 8.0), b = (int) Math.floor(3 * n / 8.0);
        int[][] seeds = {{b, a}, {n - 1 - b, n - 1 - a}, {n - 1 - a, b}, {a, n - 1 - b}};
        int k = 0;
        for (int[] seed : seeds) {
            int c = seed[1] * n + seed[0];
            if (!taken[c]) {
                order[k++] = c;
                take(n, c, taken, nearest);
            }
        }
        int centre = n % 2 == 1 ? all / 2 : -1;
        while (k < all) {
            int next = -1;
            for (int c = 0; c < all; c++) {
                if (!taken[c] && c != centre && (next < 0 || nearest[c] > nearest[next])) {
                    next = c;
                }
            }
            if (next < 0) {
                next = centre;
            }
            order[k++] = next;
            take(n, next, taken, nearest);
            int mirror = all - 1 - next;
            if (!taken[mirror]) {
                order[k++] = mirror;
                take(n, mirror, taken, nearest);
            }
        }
        return order;
    }

    /** Marks cell {@code pick} taken and lowers the other cells' squared distance to the nearest taken one. */
    private static void take(int n, int pick, boolean[] taken, double[] nearest) {
        taken[pick] = true;
        for (int c = 0; c < n * n; c++) {
            double dx = c % n - pick % n, dy = c / n - pick / n;
            nearest[c] = Math.min(nearest[c], dx * dx + dy * dy);
        }
    }

    @Override
    public String name() {
        return "adaptive";
    }
}
