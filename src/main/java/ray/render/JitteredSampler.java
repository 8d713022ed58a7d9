package ray.render;

/**
 * Stratified ("jittered") sampling: sample {@code index} lies at a uniformly random point of grid cell
 * ({@code index % n_s}, {@code index / n_s}), so each of the n_s x n_s cells holds exactly one sample.
 * Every further pair of dimensions is stratified the same way over the pixel's samples, through its own
 * random assignment of samples to cells (pbrt's {@code StratifiedSampler} with padding), so an area
 * light sampled once per pixel sample also gets one point per cell. Randomness is a hash of (pixel,
 * index, dimension): the same render gives the same image.
 */
public final class JitteredSampler extends Sampler {

    private static final int SEED = 0x6a177e4d;

    private final int seed;

    public JitteredSampler(int n) {
        this(n, 0);
    }

    /** Another independent jittering for each {@code seed} (0 is the default's). */
    public JitteredSampler(int n, int seed) {
        super(n);
        this.seed = SEED ^ seed;
    }

    @Override
    public double get(int x, int y, int index, int dim) {
        int pair = dim >>> 1;
        int cell = pair == 0 ? index : permute(index, n * n, (int) hash(x, y, pair, seed));
        int stratum = (dim & 1) == 0 ? cell % n : cell / n;
        double jitter = unit(hash(x, y, index, dim ^ seed));
        return Math.min((stratum + jitter) / n, Math.nextDown(1.0));
    }

    @Override
    public String name() {
        return "jittered";
    }
}
