package ray;

/**
 * Rays counted by {@link RayKind}. Each render thread owns one (no sharing, no atomics on the hot
 * path); the renderer adds them up when the threads finish. Only {@link Scene}'s casting methods
 * count ({@link #count(RayKind)}); everything else reads.
 */
public final class RayStats implements java.io.Serializable {

    private static final long serialVersionUID = 1L;
    private final long[] rays = new long[RayKind.all().length];
    /** Samples whose value was NaN or infinite and were replaced by black (should stay 0). */
    public long invalidSamples;

    /** Rays of {@code kind} counted so far. */
    public long get(RayKind kind) {
        return rays[kind.ordinal()];
    }

    /** One more ray of {@code kind}: called by the casting methods of {@link Scene} only. */
    void count(RayKind kind) {
        rays[kind.ordinal()]++;
    }

    /** {@code n} more rays of {@code kind} (a packet's): called by the casting methods of {@link Scene} only. */
    void count(RayKind kind, int n) {
        rays[kind.ordinal()] += n;
    }

    public void add(RayStats o) {
        for (int i = 0; i < rays.length; i++) {
            rays[i] += o.rays[i];
        }
        invalidSamples += o.invalidSamples;
    }

    public long total() {
        long t = 0;
        for (long n : rays) {
            t += n;
        }
        return t;
    }

    /**
     * {@code "1,200 camera, 0 shadow, 0 mirror rays"}: camera, shadow and mirror always, the other kinds
     * only when some were cast (so the line of a scene without them reads as it always did).
     */
    @Override
    public String toString() {
        StringBuilder b = new StringBuilder();
        for (RayKind k : RayKind.all()) {
            long n = get(k);
            if (k.ordinal() <= RayKind.MIRROR.ordinal() || n != 0) {
                b.append(b.length() == 0 ? "" : ", ").append(grouped(n)).append(' ').append(k.key());
            }
        }
        return b.append(" rays").toString();
    }

    /** {@code n} with commas between groups of three digits, as {@code %,d} in an English locale. */
    static String grouped(long n) {
        String s = Long.toString(Math.abs(n));
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            if (i > 0 && (s.length() - i) % 3 == 0) {
                b.append(',');
            }
            b.append(s.charAt(i));
        }
        return (n < 0 ? "-" : "") + b;
    }
}
