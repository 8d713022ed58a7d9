package ray.render;

import java.util.List;
import ray.SampleSource;
import ray.settings.RenderOption;

/**
 * Where the samples of a pixel go, and every other random decision a sample makes: a pure function
 * {@link #get(int, int, int, int)} of the pixel, the sample's index within the pixel and a dimension
 * (pbrt-v4's {@code StartPixelSample(pixel, index, dim)}). Nothing is stateful, so an image never depends
 * on threads or tile order. Dimensions 0 and 1 are the position inside the pixel (x right, y down);
 * dimensions 2, 3, ... serve other decisions (an area light's point, ...), in pairs (2, 3), (4, 5), ...
 * for 2D ones. Code on the hot path draws them through {@link PixelSample}.
 *
 * <p>A sampler gives {@link #samplesPerPixel()} = n_s x n_s samples to a pixel. Built-in samplers
 * ({@link #create}): {@code grid} (the scene format's regular grid, the default), {@code jittered}
 * (one random point in each grid cell), {@code sobol} (Owen-scrambled Sobol points) and {@code adaptive}
 * (the grid's points, taken only until the pixel's estimated error is small enough).
 */
public abstract class Sampler extends SampleSource {

    /** The built-in samplers' names, as {@code --sampler} and the scene's {@code Sampler} global take them ({@link RenderOption#SAMPLER}). */
    public static final List<String> NAMES = RenderOption.SAMPLER.choices;

    /** n_s: the pixel holds n_s x n_s samples. */
    protected final int n;

    protected Sampler(int n) {
        if (n < 1) {
            throw new IllegalArgumentException("samples per pixel side must be at least 1, got " + n);
        }
        this.n = n;
    }

    /** The sampler called {@code name} (one of {@link #NAMES}) with n_s x n_s samples per pixel. */
    public static Sampler create(String name, int ns) {
        return create(name, ns, 0);
    }

    /**
     * {@link #create(String, int)} with another random {@code seed} for the randomised samplers
     * ({@code jittered}, {@code sobol}: seed 0 is their default; independent seeds give independent
     * images, as the accuracy study's two references need); {@code grid} and {@code adaptive} have no
     * randomness and ignore it.
     */
    public static Sampler create(String name, int ns, int seed) {
        return switch (name) {
            case "grid" -> new GridSampler(ns);
            case "jittered" -> new JitteredSampler(ns, seed);
            case "sobol" -> new SobolSampler(ns, seed);
            case "adaptive" -> new AdaptiveSampler(ns);
            default -> throw new IllegalArgumentException(RenderOption.SAMPLER.problem("sampler", name));
        };
    }

    /** n_s x n_s: the most samples a pixel gets. */
    public final int samplesPerPixel() {
        return n * n;
    }

    /** n_s, the side of the pixel's sample grid. */
    public final int side() {
        return n;
    }

    /**
     * Dimension {@code dim} of sample {@code index} (0 to {@link #samplesPerPixel()} - 1) of pixel (x, y):
     * a number in [0, 1) that depends on nothing else.
     */
    @Override
    public abstract double get(int x, int y, int index, int dim);

    /** The name {@link #create} knows this sampler by. */
    public abstract String name();

    @Override
    public String toString() {
        return name() + " " + n + "x" + n;
    }

    // ---- hashing shared by the randomised samplers ----

    /** A well-mixed 64-bit hash of four ints (splitmix64's finaliser over a combined key). */
    static long hash(int a, int b, int c, int d) {
        long h = mix(0x9E3779B97F4A7C15L ^ a);
        h = mix(h ^ (b & 0xFFFFFFFFL) * 0xBF58476D1CE4E5B9L);
        h = mix(h ^ (c & 0xFFFFFFFFL) * 0x94D049BB133111EBL);
        return mix(h ^ (d & 0xFFFFFFFFL) * 0x9E3779B97F4A7C15L);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    /** The top 53 bits of {@code h} as a double in [0, 1). */
    static double unit(long h) {
        return (h >>> 11) * 0x1.0p-53;
    }

    /**
     * A pseudo-random permutation of [0, l) chosen by {@code p}, evaluated at {@code i} (Kensler 2013,
     * "Correlated Multi-Jittered Sampling", with cycle walking): a bijection for every l >= 1.
     */
    static int permute(int i, int l, int p) {
        if (l == 1) {
            return 0;
        }
        int w = l - 1;
        w |= w >>> 1;
        w |= w >>> 2;
        w |= w >>> 4;
        w |= w >>> 8;
        w |= w >>> 16;
        do {
            i ^= p;
            i *= 0xe170893d;
            i ^= p >>> 16;
            i ^= (i & w) >>> 4;
            i ^= p >>> 8;
            i *= 0x0929eb3f;
            i ^= p >>> 23;
            i ^= (i & w) >>> 1;
            i *= 1 | p >>> 27;
            i *= 0x6935fa69;
            i ^= (i & w) >>> 11;
            i *= 0x74dcb303;
            i ^= (i & w) >>> 2;
            i *= 0x9e501cc3;
            i ^= (i & w) >>> 2;
            i *= 0xc860a3df;
            i &= w;
            i ^= i >>> 5;
        } while (Integer.compareUnsigned(i, l) >= 0);
        return Integer.remainderUnsigned(i + p, l);
    }
}
