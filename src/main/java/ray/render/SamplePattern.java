package ray.render;

/**
 * Where in a pixel the samples go. The scene format's pattern is {@link #GRID}; other patterns
 * (jittered, random, low-discrepancy) plug in here for accuracy-versus-time studies.
 */
public interface SamplePattern {

    /** The regular n x n grid of sub-pixel centres the scene format specifies. */
    SamplePattern GRID = new SamplePattern() {
        @Override
        public void offsets(int pixelX, int pixelY, int n, double[] out) {
            int k = 0;
            for (int j = 0; j < n; j++) {
                for (int i = 0; i < n; i++) {
                    out[k++] = (i + 0.5) / n;
                    out[k++] = (j + 0.5) / n;
                }
            }
        }

        @Override
        public String toString() {
            return "grid";
        }
    };

    /**
     * Writes the n x n sample offsets of pixel (pixelX, pixelY) into {@code out} as (dx, dy) pairs in
     * [0, 1)^2, row by row. Must depend only on its arguments, so images do not depend on threading.
     */
    void offsets(int pixelX, int pixelY, int n, double[] out);
}
