package ray.accel;

import java.util.List;
import ray.IntersectionRecord;
import ray.surface.Surface;

/**
 * The primitives of one type inside the BVH, packed the way that type's kernel wants them, in leaf
 * order: primitive {@code i} of a set is the set's {@code i}-th surface in the list it was
 * {@link Type#pack packed} from. The BVH holds no primitive's math: at a leaf it hands each run of
 * same-set slots to the set, which tests them with its kernel (the same kernel the surface's own
 * {@code intersects} calls).
 *
 * <p>A new primitive type needs no set at all: a {@link Surface} with {@code bounds()} and
 * {@code intersects} goes into the BVH as it is (the generic set calls {@code intersects}). To give it
 * a packed fast path, return a {@link Type} from {@link Surface#primitiveType()} (for the exact class
 * only, so a subclass that overrides {@code intersects} keeps its own test).
 */
public abstract class PrimitiveSet {

    /**
     * Doubles a set may keep in {@link RayQuery#scratch} (per-ray set-up, and what it keeps from ray to
     * ray in the thread: TriangleSet its last triangles' normals), and of {@link RayQuery#hitData}.
     */
    public static final int SCRATCH = 52;

    /** Makes a set from surfaces of one type, in leaf order. One shared instance per type. */
    public interface Type {
        PrimitiveSet pack(List<Surface> surfaces);

        /**
         * {@code s.bounds()}, which a type may write into {@code scratch} instead of allocating a box per
         * primitive (the BVH build reads it before asking again). Only for surfaces of this type, which
         * is only ever returned for the exact class whose bounds it knows.
         */
        default Aabb bounds(Surface s, Aabb scratch) {
            return s.bounds();
        }
    }

    private int id, bit;
    /** The scene surface each primitive stands for, in the set's order. */
    protected final Surface[] surfaces;

    /** A set of {@code surfaces}, in the order given (leaf order). */
    protected PrimitiveSet(List<Surface> surfaces) {
        this.surfaces = surfaces.toArray(new Surface[0]);
    }

    /** For a set that keeps its surfaces itself (then override {@link #size} and {@link #surface}). */
    protected PrimitiveSet() {
        this.surfaces = new Surface[0];
    }

    /** This set's number in its BVH: its scratch is at {@code id * SCRATCH}, its set-up bit {@code 1 << id}. */
    public final int id() {
        return id;
    }

    final void id(int id) {
        this.id = id;
        this.bit = id < 31 ? 1 << id : 0;   // past 30 sets: no flag, the set-up is made on every use
    }

    /**
     * True the first time this set is used during the current query (then it makes its per-ray set-up
     * in its part of {@link RayQuery#scratch}); false after that.
     */
    protected final boolean firstUse(RayQuery q) {
        int s = q.setUp;
        if ((s & bit) != 0) {
            return false;
        }
        q.setUp = s | bit;
        return true;
    }

    /** Number of primitives. */
    public int size() {
        return surfaces.length;
    }

    /** The scene surface primitive {@code i} stands for ({@code record.surface} of its hits). */
    public Surface surface(int i) {
        return surfaces[i];
    }

    /**
     * Tests primitives {@code [from, to)} (in leaf slots {@code slot, slot + 1, ...}) against the query's
     * ray over [tMin, tMax], offering each hit ({@link RayQuery#offer}).
     */
    public abstract void closestHit(int from, int to, int slot, RayQuery q);

    /** True when any of primitives {@code [from, to)} is hit over [tMin, tMax] (a shadow query). */
    public abstract boolean anyHit(int from, int to, RayQuery q);

    /** Fills {@code rec} for the closest hit, primitive {@code i} at {@code q.tMax}, from {@link RayQuery#hitData}. */
    public abstract void fill(int i, RayQuery q, IntersectionRecord rec);

    /** Bytes of packed data (for {@link Bvh#memoryBytes()}). */
    public abstract long memoryBytes();
}
