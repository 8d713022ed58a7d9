package ray.accel;

/**
 * A primitive set's closest-hit kernel over many rays, four at a time in the lanes of a vector: what a
 * small scene's camera packets are traced with when the JVM has the Vector API ({@link Bvh}, "lanes").
 * Every primitive of the set is tested against every ray of the packet (no tree: a scene of a few
 * primitives), each lane doing the set's scalar kernel's operations in its order, so each ray's t (and
 * what its fill needs) is the scalar kernel's, bit for bit. For each ray the set's nearest hit (at equal
 * t the lowest index, which is the earliest leaf slot) is offered to the ray's query
 * ({@link RayQuery#offer} with its slot), so the answer is the tree's.
 *
 * <p>An implementation names the Vector API, so it is a class of its own, made only by
 * {@link PrimitiveSet#lanes()}, which the BVH calls only when the module is loaded (a JVM without it never
 * loads the class).
 */
public abstract class LaneKernel {

    /**
     * Tests every primitive of the set against rays {@code 0..rays.n - 1}, offering each ray's nearest
     * hit among them to {@code rays.queries[k]}, primitive {@code i} in leaf slot {@code slotOf[i]}.
     */
    public abstract void closestHits(LaneRays rays, int[] slotOf);
}
