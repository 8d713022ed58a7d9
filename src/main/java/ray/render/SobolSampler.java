package ray.render;

/**
 * Low-discrepancy sampling: the first two dimensions of the Sobol sequence (a (0, 2)-sequence: every
 * prefix of 2^k points has one point in each of the 2^k equal-area boxes of every shape), Owen-scrambled
 * per pixel with the hash-based nested uniform scrambling of Burley, "Practical Hash-based Owen
 * Scrambling" (JCGT 2020). Each further pair of dimensions is another independently scrambled copy whose
 * sample order is shuffled per pixel, so pairs are not correlated with each other.
 *
 * <p>Why Sobol and not R2: any prefix of the sequence is well spread (the progressive passes and the
 * first samples of a pixel are good on their own), Owen scrambling keeps the stratification while making
 * the error random and unbiased (so it averages away across pixels instead of forming patterns), and the
 * error on edges falls faster than with jittered sampling. R2 is simpler but its prefixes are not
 * stratified in the same strict sense and a per-pixel random shift does not decorrelate it as well.
 */
public final class SobolSampler extends Sampler {

    private static final int SEED = 0x50b01;

    private final int seed;
    private final int count;

    public SobolSampler(int n) {
        this(n, 0);
    }

    /** Another independent scrambling for each {@code seed} (0 is the default's). */
    public SobolSampler(int n, int seed) {
        this(n, SEED ^ seed, n * n);
    }

    /**
     * An independent scrambling ({@code seed}) of the first {@code count} points (at most n x n; a power
     * of two keeps the prefix a (0, m, 2)-net), for estimates that need two independent sets of points.
     */
    SobolSampler(int n, int seed, int count) {
        super(n);
        if (count < 1 || count > n * n) {
            throw new IllegalArgumentException("count must be 1 to " + n * n + ", got " + count);
        }
        this.seed = seed;
        this.count = count;
    }

    /** How many of the n x n points this sampler hands out (all of them unless made for a probe). */
    int count() {
        return count;
    }

    @Override
    public double get(int x, int y, int index, int dim) {
        int pair = dim >>> 1;
        int i = pair == 0 ? index : permute(index, count, (int) hash(x, y, pair, seed));
        int scramble = (int) hash(x, y, dim, seed ^ 0x5eed);
        int v = (dim & 1) == 0 ? Integer.reverse(i) : sobolSecond(i);
        return Integer.toUnsignedLong(owenScramble(v, scramble)) * 0x1.0p-32;
    }

    /** Dimension 1 of the Sobol sequence (generator matrix: Pascal's triangle mod 2), as a 32-bit fraction. */
    static int sobolSecond(int index) {
        int result = 0;
        for (int v = 1 << 31; index != 0; index >>>= 1, v ^= v >>> 1) {
            if ((index & 1) != 0) {
                result ^= v;
            }
        }
        return result;
    }

    /** Nested uniform (Owen) scrambling of a 32-bit fraction: each bit flipped by a hash of the bits above it. */
    static int owenScramble(int v, int seed) {
        v = Integer.reverse(v);
        // Laine and Karras's permutation: each bit affects only the bits above it
        v += seed;
        v ^= v * 0x6c50b47c;
        v ^= v * 0xb82f1e52;
        v ^= v * 0xc7afe638;
        v ^= v * 0x8d22f6e6;
        return Integer.reverse(v);
    }

    @Override
    public String name() {
        return "sobol";
    }
}
