package ray;

/**
 * A sampler as the core sees it: dimension {@code dim} of sample {@code index} of pixel (x, y), a number
 * in [0, 1) that depends on nothing else (pbrt-v4's {@code StartPixelSample(pixel, index, dim)}). The
 * renderer's samplers ({@code ray.render.Sampler}) are these; light and effect code draws from them
 * through the thread's {@link PixelSample}, so it needs nothing of the renderer.
 */
public abstract class SampleSource {

    /** Dimension {@code dim} of sample {@code index} of pixel (x, y): a number in [0, 1). */
    public abstract double get(int x, int y, int index, int dim);
}
