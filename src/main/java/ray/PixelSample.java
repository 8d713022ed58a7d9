package ray;

/**
 * The sample being traced on one render thread: its pixel, its index and the next free dimension of
 * its sampler ({@link SampleSource}; pbrt-v4's {@code StartPixelSample} / {@code Get1D} / {@code Get2D}). Lives in
 * {@code TraceContext.sample}, so light and effect code draws its numbers without allocating:
 *
 * <pre>
 * PixelSample s = ctx.sample;
 * s.next2D();                      // an aligned pair of dimensions
 * double a = s.u, b = s.v;         // in [0, 1)
 * </pre>
 *
 * Dimensions are handed out in call order starting at 2 (0 and 1 are the position in the pixel), so a
 * given pixel sample always receives the same numbers. Outside a render it is sample 0 of pixel (0, 0)
 * of a 1 x 1 grid: every draw is 0.5.
 */
public final class PixelSample {

    /** Outside a render: the centre of everything (sample 0 of a 1 x 1 grid). */
    private static final SampleSource NONE = new SampleSource() {
        @Override
        public double get(int x, int y, int index, int dim) {
            return 0.5;
        }
    };

    private SampleSource sampler = NONE;
    private int x, y, index;
    private int dim = 2;
    /** The pair the last {@link #next2D()} drew. */
    public double u, v;

    /** Starts sample {@code index} of pixel (x, y): the next dimension handed out is 2. */
    public void start(SampleSource s, int px, int py, int sampleIndex) {
        sampler = s;
        x = px;
        y = py;
        index = sampleIndex;
        dim = 2;
    }

    /** The next dimension's value. */
    public double next1D() {
        return sampler.get(x, y, index, dim++);
    }

    /** Draws the next aligned pair of dimensions (skipping one if needed) into {@link #u} and {@link #v}. */
    public void next2D() {
        dim += dim & 1;
        u = sampler.get(x, y, index, dim);
        v = sampler.get(x, y, index, dim + 1);
        dim += 2;
    }

    public int x() {
        return x;
    }

    public int y() {
        return y;
    }

    public int index() {
        return index;
    }

    /** The next dimension {@link #next1D()} would use. */
    public int dimension() {
        return dim;
    }
}
