package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.accel.Aabb;
import ray.accel.PrimitiveSet;
import ray.accel.RayQuery;

/**
 * Built-in triangles packed for the BVH: 9 doubles of vertices each, tested with {@link Triangle}'s
 * watertight kernel; the ray's set-up ({@link Triangle#setupRay}) is made once per ray, when the first
 * triangle is tested.
 */
final class TriangleSet extends PrimitiveSet {

    static final Type TYPE = new Type() {
        @Override
        public PrimitiveSet pack(List<Surface> surfaces) {
            return new TriangleSet(surfaces);
        }

        @Override
        public Aabb bounds(Surface s, Aabb scratch) {   // Triangle.bounds() without a new box
            return Triangle.bounds((Triangle) s, scratch.reset());
        }
    };

    private final double[] v;
    /**
     * Where in this set's query scratch the normals of the last filled triangles are kept ({@link #fill}):
     * after the ray set-up, {@value #FILLED_SLOTS} slots of 5 doubles, triangle i in slot i mod 8.
     */
    private static final int FILLED = Triangle.KERNEL_SIZE, FILLED_SLOTS = 8;

    private TriangleSet(List<Surface> list) {
        super(list);
        v = new double[9 * surfaces.length];
        for (int i = 0; i < surfaces.length; i++) {
            Triangle t = (Triangle) surfaces[i];
            int o = 9 * i;
            v[o] = t.v0.x; v[o + 1] = t.v0.y; v[o + 2] = t.v0.z;
            v[o + 3] = t.v1.x; v[o + 4] = t.v1.y; v[o + 5] = t.v1.z;
            v[o + 6] = t.v2.x; v[o + 7] = t.v2.y; v[o + 8] = t.v2.z;
        }
    }

    /** Offset of this set's ray set-up in the query's scratch, made on the ray's first test. */
    private int setUp(RayQuery q) {
        int at = id() * SCRATCH;
        if (firstUse(q)) {
            Triangle.setupRay(q.ray, q.scratch, at);
        }
        return at;
    }

    @Override
    public void closestHit(int from, int to, int slot, RayQuery q) {
        double[] k = q.scratch, tv = v;
        int at = setUp(q), b = at + Triangle.B0;
        int kx = (int) k[at], ky = (int) k[at + 1], kz = (int) k[at + 2];
        double sx = k[at + Triangle.SX], sy = k[at + Triangle.SY], sz = k[at + Triangle.SZ];
        double okx = k[at + Triangle.OX], oky = k[at + Triangle.OY], okz = k[at + Triangle.OZ];
        double tMin = q.tMin;
        for (int i = from; i < to; i++, slot++) {
            double t = Triangle.hit(tv, 9 * i, kx, ky, kz, sx, sy, sz, okx, oky, okz, tMin, q.candidateBound(), k, b);
            if (t == t && q.offer(t, this, i, slot)) {
                double[] h = q.hitData;
                h[0] = k[b];
                h[1] = k[b + 1];
                h[2] = k[b + 2];
            }
        }
    }

    @Override
    public boolean anyHit(int from, int to, RayQuery q) {
        double[] k = q.scratch, tv = v;
        int at = setUp(q), b = at + Triangle.B0;
        int kx = (int) k[at], ky = (int) k[at + 1], kz = (int) k[at + 2];
        double sx = k[at + Triangle.SX], sy = k[at + Triangle.SY], sz = k[at + Triangle.SZ];
        double okx = k[at + Triangle.OX], oky = k[at + Triangle.OY], okz = k[at + Triangle.OZ];
        double tMin = q.tMin, tMax = q.tMax;
        for (int i = from; i < to; i++) {
            double t = Triangle.hit(tv, 9 * i, kx, ky, kz, sx, sy, sz, okx, oky, okz, tMin, tMax, k, b);
            if (t == t) {
                return true;
            }
        }
        return false;
    }

    /**
     * {@link Triangle#fill}. The normal and error bound are the triangle's own, so the thread's last ones
     * are kept in its query scratch (a slot per triangle index mod 8: index + 1, or 0 for none; normal;
     * error bound) and copied when the same triangle is hit again, as neighbouring camera rays and a
     * mirror path's bounces mostly do: the same numbers without their square root and divisions.
     */
    @Override
    public void fill(int i, RayQuery q, IntersectionRecord rec) {
        int o = 9 * i;
        Triangle.fillPoint(v, o, q.hitData, 0, q.tMax, rec);
        double[] k = q.scratch;
        int c = id() * SCRATCH + FILLED + 5 * (i & (FILLED_SLOTS - 1));
        if (k[c] == i + 1) {
            rec.normal.set(k[c + 1], k[c + 2], k[c + 3]);
            rec.error = k[c + 4];
        } else {
            Triangle.fillNormal(v, o, rec);
            k[c] = i + 1;
            k[c + 1] = rec.normal.x;
            k[c + 2] = rec.normal.y;
            k[c + 3] = rec.normal.z;
            k[c + 4] = rec.error;
        }
        rec.surface = surfaces[i];
    }

    @Override
    public long memoryBytes() {
        return 8L * v.length + 4L * surfaces.length;
    }
}
