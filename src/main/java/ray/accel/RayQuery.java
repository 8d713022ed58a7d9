package ray.accel;

import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;

/**
 * One ray query in progress, and one thread's scratch for it: the BVH fills the ray's fields, the
 * primitive sets ({@link PrimitiveSet}) test their primitives against them and offer hits. Owned by
 * the accelerator, one per thread (kept in {@link ray.TraceContext#acceleratorScratch}); never shared.
 */
public final class RayQuery {

    /** The ray being traced (origin, direction) and the span still searched: [tMin, tMax]. */
    public double ox, oy, oz, dx, dy, dz, tMin, tMax;
    /** The ray itself and the scene, for surfaces tested through their own {@code intersects}. */
    public Ray ray;
    public final Scene scene;
    /**
     * The caller's record (closest-hit queries; a user surface fills it at once). Any-hit queries leave
     * it alone: a user surface tested for any hit fills {@link #scratchRecord}.
     */
    public IntersectionRecord record;
    public final IntersectionRecord scratchRecord = new IntersectionRecord();
    /**
     * Per primitive set, {@link PrimitiveSet#SCRATCH} doubles of per-ray set-up at
     * {@code scratch[set.id() * SCRATCH]}, valid while bit {@code set.id()} of {@link #setUp} is on
     * (cleared at the start of every query), and the winning hit's data at {@link #hitData}.
     */
    public double[] scratch;
    public int setUp;
    /** What the closest hit's {@link PrimitiveSet#fill} needs besides t (barycentrics, say). */
    public final double[] hitData = new double[PrimitiveSet.SCRATCH];

    PrimitiveSet hitSet;
    int hitIndex, hitSlot;

    /**
     * The occluder cache: per slot of {@link Accelerator#anyHit(Ray, ray.TraceContext, int)}, the set
     * (-1: none yet) and index of the primitive that last answered an any-hit query, and the range
     * [from, to) of its leaf run.
     */
    final int[] occluderSet = new int[Accelerator.CACHE_SLOTS], occluderIndex = new int[Accelerator.CACHE_SLOTS],
            occluderFrom = new int[Accelerator.CACHE_SLOTS], occluderTo = new int[Accelerator.CACHE_SLOTS];

    /** Traversal stack of node references, and (closest hit) their entry distances. */
    final int[] stack = new int[Wide4.STACK];
    final double[] stackT = new double[Wide4.STACK];
    /** A wide node's four entry distances, then the entered ones sorted, and their lanes ({@link Wide4}). */
    final double[] wideT = new double[8];
    final int[] wideRef = new int[4];
    /** A leaf's box gathered from its wide node for a packet's rays ({@link Wide4#closestHits}). */
    final float[] wideBox = new float[6];
    /**
     * A packet's traversal ({@link Bvh#closestHits}): per pending subtree its box's offset in the node
     * array; per ray of the packet its own query and its inverse direction. Made on the first packet.
     */
    int[] stackBox;
    RayQuery[] lanes = new RayQuery[0];
    double[] laneIx, laneIy, laneIz;
    final Bvh owner;
    /** Inner nodes visited and primitives tested (counted only with -Dray.bvh.count=true). */
    long nodeVisits, primitiveTests;

    RayQuery(Bvh owner, Scene scene, int sets) {
        this.owner = owner;
        this.scene = scene;
        this.scratch = new double[Math.max(1, sets) * PrimitiveSet.SCRATCH];
        java.util.Arrays.fill(occluderSet, -1);
    }

    /** The per-ray queries of a packet of {@code n} rays (made on first use; kept for the thread). */
    RayQuery[] lanes(int n) {
        if (lanes.length < n) {
            RayQuery[] l = java.util.Arrays.copyOf(lanes, n);
            for (int i = lanes.length; i < n; i++) {
                l[i] = new RayQuery(owner, scene, scratch.length / PrimitiveSet.SCRATCH);
            }
            lanes = l;
            laneIx = new double[n];
            laneIy = new double[n];
            laneIz = new double[n];
            if (stackBox == null) {
                stackBox = new int[stack.length];
            }
        }
        return lanes;
    }

    /** Starts a closest-hit query of {@code r}, to be filled into {@code rec}. */
    void start(Ray r, IntersectionRecord rec) {
        startAny(r);
        record = rec;
        hitSet = null;
        hitSlot = Integer.MAX_VALUE;
    }

    /** Starts an any-hit query of {@code r} (no record: nothing is filled in, no hit is kept). */
    void startAny(Ray r) {
        ray = r;
        ox = r.origin.x; oy = r.origin.y; oz = r.origin.z;
        dx = r.direction.x; dy = r.direction.y; dz = r.direction.z;
        tMin = r.tMin;
        tMax = r.tMax;
        setUp = 0;
    }

    /** {@link #candidateBound}'s widening: covers the rounding of a kernel's scaled test (4 eps) with room. */
    private static final double CANDIDATE_SLACK = 1 + 0x1p-48;

    /**
     * The bound a closest-hit kernel tests a candidate's t against: {@link #tMax} widened by 2^-48 of it.
     * The triangle kernel rejects a t above its bound before its division (tScaled > tMax det, rounded),
     * which can turn away a primitive whose t, once divided, equals tMax exactly; the tie {@link #offer}
     * decides by slot would then be decided by which primitive was tested first, and so by the traversal's
     * order. Widened, every t up to tMax reaches offer, which compares exactly and rejects the rest.
     */
    public double candidateBound() {
        return tMax * CANDIDATE_SLACK;
    }

    /**
     * A closest-hit candidate at t (already known to be in [tMin, {@link #candidateBound}]) from primitive
     * {@code index} of {@code set}, in leaf slot {@code slot}: taken when nearer than the best so far, or as
     * near and in an earlier slot (so ties do not depend on the order of tests). Returns whether it was taken; then
     * {@link #tMax} is t and the set should leave what its fill needs in {@link #hitData}.
     */
    public boolean offer(double t, PrimitiveSet set, int index, int slot) {
        if (t < tMax || (t == tMax && slot < hitSlot)) {
            take(t, set, index, slot);
            return true;
        }
        return false;
    }

    /** Takes a hit unconditionally (a user surface that has filled the record already). */
    void take(double t, PrimitiveSet set, int index, int slot) {
        tMax = t;
        hitSet = set;
        hitIndex = index;
        hitSlot = slot;
    }
}
