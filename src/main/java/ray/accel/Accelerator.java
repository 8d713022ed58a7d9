package ray.accel;

import ray.IntersectionRecord;
import ray.Ray;
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
}
