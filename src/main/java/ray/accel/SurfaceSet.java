package ray.accel;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.Surface;

/**
 * The generic set: surfaces tested through their own {@code intersects} (a user's classes, and any
 * type without a packed set). The record a surface fills is kept as its author wrote it
 * ({@link #finish}).
 */
final class SurfaceSet extends PrimitiveSet {

    static final Type TYPE = new Type() {
        @Override
        public PrimitiveSet pack(List<Surface> surfaces) {
            return new SurfaceSet(surfaces);
        }
    };


    SurfaceSet(List<Surface> surfaces) {
        super(surfaces);
    }

    @Override
    public void closestHit(int from, int to, int slot, RayQuery q) {
        for (int i = from; i < to; i++, slot++) {
            if (hit(surfaces[i], q)) {
                q.take(q.record.t, this, i, slot);
            }
        }
    }

    @Override
    public boolean anyHit(int from, int to, RayQuery q) {
        for (int i = from; i < to; i++) {
            if (intersects(surfaces[i], q.ray, q.scratchRecord, q)) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void fill(int i, RayQuery q, IntersectionRecord rec) {
        // filled by the surface's own intersects when it was hit
    }

    @Override
    public long memoryBytes() {
        return 4L * surfaces.length;
    }

    /**
     * The surface's own test over [tMin, best] into the query's record; on a hit the record is the one
     * the surface filled ({@link #finish}), on a miss it is left as it was. The ray's tMax is restored
     * even if the surface throws.
     */
    private static boolean hit(Surface s, RayQuery q) {
        Ray ray = q.ray;
        IntersectionRecord rec = q.record;
        double saved = ray.tMax, savedError = rec.error;
        boolean savedFront = rec.frontFace;
        Surface savedSurface = rec.surface;
        // what a surface written against the framework alone does not set: unknown error bound, front
        // face unless its normal says otherwise, and the surface itself
        rec.error = 0;
        rec.frontFace = true;
        rec.surface = null;
        ray.tMax = q.tMax;
        boolean hit = false;
        try {
            hit = intersects(s, ray, rec, q);
        } finally {
            ray.tMax = saved;
            if (!hit) {
                rec.error = savedError;
                rec.frontFace = savedFront;
                rec.surface = savedSurface;
            }
        }
        if (hit) {
            finish(ray, rec, s);
        }
        return hit;
    }

    /** Calls a surface's own intersects, the record keeping its own vectors ({@link Surface#intersectInto}). */
    private static boolean intersects(Surface s, Ray ray, IntersectionRecord rec, RayQuery q) {
        return Surface.intersectInto(s, ray, rec, q.scene);
    }

    /**
     * A user surface's record is kept as its author wrote it (t, point, frontFace, error bound, and the
     * surface it names, {@code s} when it names none). Only a normal pointing away from the ray (a
     * surface written against the framework alone, which returns the outward normal) is turned to face
     * the ray, and then the ray is on the back side.
     */
    private static void finish(Ray ray, IntersectionRecord rec, Surface s) {
        if (rec.surface == null) {
            rec.surface = s;
        }
        double dn = rec.normal.x * ray.direction.x + rec.normal.y * ray.direction.y + rec.normal.z * ray.direction.z;
        if (dn > 0) {
            rec.normal.negate();
            rec.frontFace = false;
        }
    }
}
