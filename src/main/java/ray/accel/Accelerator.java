package ray.accel;

import ray.IntersectionRecord;
import ray.Ray;
import ray.RayPacket;
import ray.TraceContext;

/** Answers the two ray queries a renderer needs, over all of a scene's surfaces. */
public interface Accelerator {

    /**
     * The closest hit with t in the ray's span: fills {@code rec} (point, unit normal facing the ray,
     * t, surface, frontFace, error bound) and returns true; on a miss returns false.
     */
    boolean closestHit(Ray ray, IntersectionRecord rec, TraceContext ctx);

    /** True when any surface is hit with t in the ray's span (shadow rays; may stop at the first hit). */
    boolean anyHit(Ray ray, TraceContext ctx);

    /**
     * {@link #anyHit(Ray, TraceContext)} for a caller that casts many similar shadow rays: rays toward
     * one light from neighbouring points, say, told apart by {@code cacheSlot} (0 to {@link #CACHE_SLOTS} - 1;
     * another value: no cache). The answer is the same; an accelerator may remember, per thread and
     * slot, the primitive that answered last and test it first (an occluder cache).
     */
    default boolean anyHit(Ray ray, TraceContext ctx, int cacheSlot) {
        return anyHit(ray, ctx);
    }

    /**
     * {@link #closestHit} for each ray of the packet, into its record and hit flag: the same answers,
     * ray for ray. An accelerator may trace rays that leave one point together.
     */
    default void closestHits(RayPacket p, TraceContext ctx) {
        for (int k = 0; k < p.size; k++) {
            p.hit[k] = closestHit(p.rays[k], p.records[k], ctx);
        }
    }

    /**
     * True when {@link #closestHits} of rays leaving one point costs less than their single queries
     * (a renderer then casts its camera rays in packets); false by default.
     */
    default boolean packetsPay() {
        return false;
    }

    /** Slots of the occluder cache {@link #anyHit(Ray, TraceContext, int)} may keep. */
    int CACHE_SLOTS = 16;
}
