package ray.accel;

/**
 * A packet's rays laid out for {@link LaneKernel}s: per ray its origin, direction, span and
 * {@link RayQuery#candidateBound}, and its query, in arrays whose length is a multiple of
 * {@link #WIDTH}; a packet that does not fill its last vector repeats its last ray in the spare lanes
 * (their answers are never offered). One per thread, kept in its {@link RayQuery}; grown, never shrunk.
 */
public final class LaneRays {

    /** Rays per vector: 256-bit lanes of doubles. */
    public static final int WIDTH = 4;

    /** Rays in the packet (the arrays hold at least this many, rounded up to {@link #WIDTH}). */
    public int n;
    public double[] ox = new double[0], oy = ox, oz = ox, dx = ox, dy = ox, dz = ox, tMin = ox, tMax = ox, bound = ox;
    /** Ray k's query, started: the kernels offer its hits there. */
    public RayQuery[] queries;
    /**
     * A kernel's scratch for one vector's answers, per lane (the thread's: a kernel is shared by the
     * render threads and keeps no state of its own): nearest t, index of the primitive (-1: none), and
     * what the set's fill needs (a triangle's barycentrics).
     */
    public final double[] bestT = new double[WIDTH], bestIndex = new double[WIDTH],
            hit0 = new double[WIDTH], hit1 = new double[WIDTH], hit2 = new double[WIDTH];

    /** Lays out the started queries {@code q[0..n-1]}. */
    void load(RayQuery[] q, int n) {
        int padded = (n + WIDTH - 1) / WIDTH * WIDTH;
        if (ox.length < padded) {
            ox = new double[padded];
            oy = new double[padded];
            oz = new double[padded];
            dx = new double[padded];
            dy = new double[padded];
            dz = new double[padded];
            tMin = new double[padded];
            tMax = new double[padded];
            bound = new double[padded];
        }
        this.n = n;
        this.queries = q;
        for (int k = 0; k < padded; k++) {
            RayQuery r = q[Math.min(k, n - 1)];
            ox[k] = r.ox;
            oy[k] = r.oy;
            oz[k] = r.oz;
            dx[k] = r.dx;
            dy[k] = r.dy;
            dz[k] = r.dz;
            tMin[k] = r.tMin;
            tMax[k] = r.tMax;
            bound[k] = r.candidateBound();
        }
    }
}
