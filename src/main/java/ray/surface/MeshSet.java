package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.accel.Aabb;
import ray.accel.PrimitiveSet;
import ray.accel.RayQuery;

/**
 * Mesh triangles packed for the BVH: 9 floats of vertices each (the mesh's own float coordinates, which
 * the kernel widens to the same doubles {@link TriangleSet} holds for a {@link Triangle}), the
 * triangle's number in its mesh, and the mesh (one reference for the set when all its triangles come
 * from one mesh, as they usually do). Tested with {@link Triangle}'s watertight kernel; a two-sided mesh's
 * triangle missed from the front is tested from the back with the same kernel on the ray's x and y
 * axes swapped, which negates each edge function exactly: the same t and barycentrics, and no crack
 * between a mesh's front and back hits. Hits are completed by {@link Mesh#finishHit} (smooth normal,
 * back side, surface).
 */
final class MeshSet extends PrimitiveSet {

    static final Type ONE_SIDED = new MeshType(false), TWO_SIDED = new MeshType(true);

    private static final class MeshType implements Type {
        private final boolean twoSided;

        MeshType(boolean twoSided) {
            this.twoSided = twoSided;
        }

        @Override
        public PrimitiveSet pack(List<Surface> surfaces) {
            return new MeshSet(surfaces, twoSided);
        }

        @Override
        public Aabb bounds(Surface s, Aabb scratch) {   // MeshTriangle.bounds() without a new box
            return ((MeshTriangle) s).bounds(scratch.reset());
        }
    }

    private final boolean twoSided;
    private final float[] v;
    /** Each triangle's mesh; null when they all have the same one, {@link #only} (4 bytes a triangle less). */
    private final Mesh[] mesh;
    private final Mesh only;
    private final int[] index;

    private MeshSet(List<Surface> list, boolean twoSided) {
        this.twoSided = twoSided;
        int n = list.size();
        v = new float[9 * n];
        index = new int[n];
        Mesh first = n == 0 ? null : ((MeshTriangle) list.get(0)).mesh;
        boolean one = true;
        for (int i = 0; i < n; i++) {
            MeshTriangle t = (MeshTriangle) list.get(i);
            one &= t.mesh == first;
            index[i] = t.index;
            for (int k = 0; k < 9; k++) {
                v[9 * i + k] = (float) t.mesh.coordinate(t.index, k / 3, k % 3);   // a float widened: exact
            }
        }
        if (one) {
            mesh = null;
            only = first;
        } else {
            mesh = new Mesh[n];
            for (int i = 0; i < n; i++) {
                mesh[i] = ((MeshTriangle) list.get(i)).mesh;
            }
            only = null;
        }
    }

    /** Writes triangle {@code t} of {@code m} as 9 doubles at {@code out[off..]}. */
    static void pack(Mesh m, int t, double[] out, int off) {
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < 3; c++) {
                out[off + 3 * k + c] = m.coordinate(t, k, c);
            }
        }
    }

    /**
     * The front test, then (two-sided) the back test, for a ray set up at {@code k[0..]}; the barycentrics
     * go to {@code k[B0..B0+2]} and 1 (back) or 0 (front) to {@code k[B0+3]}.
     */
    static double hit(double[] v, int off, double[] k, double tMin, double tMax, boolean twoSided) {
        int kx = (int) k[0], ky = (int) k[1], kz = (int) k[2];
        int b = Triangle.B0;
        double t = Triangle.hit(v, off, kx, ky, kz, k[Triangle.SX], k[Triangle.SY], k[Triangle.SZ],
                k[Triangle.OX], k[Triangle.OY], k[Triangle.OZ], tMin, tMax, k, b);
        k[b + 3] = 0;
        if (t != t && twoSided) {
            t = Triangle.hit(v, off, ky, kx, kz, k[Triangle.SY], k[Triangle.SX], k[Triangle.SZ],
                    k[Triangle.OY], k[Triangle.OX], k[Triangle.OZ], tMin, tMax, k, b);
            k[b + 3] = 1;
        }
        return t;
    }

    @Override
    public int size() {
        return index.length;
    }

    @Override
    public Surface surface(int i) {
        return mesh == null ? only : mesh[i];
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
        double[] k = q.scratch;
        float[] tv = v;
        int at = setUp(q), b = at + Triangle.B0;
        int kx = (int) k[at], ky = (int) k[at + 1], kz = (int) k[at + 2];
        double sx = k[at + Triangle.SX], sy = k[at + Triangle.SY], sz = k[at + Triangle.SZ];
        double okx = k[at + Triangle.OX], oky = k[at + Triangle.OY], okz = k[at + Triangle.OZ];
        double tMin = q.tMin;
        boolean both = twoSided;
        for (int i = from; i < to; i++, slot++) {
            double t = Triangle.hit(tv, 9 * i, kx, ky, kz, sx, sy, sz, okx, oky, okz, tMin, q.candidateBound(), k, b);
            double back = 0;
            if (t != t && both) {
                t = Triangle.hit(tv, 9 * i, ky, kx, kz, sy, sx, sz, oky, okx, okz, tMin, q.candidateBound(), k, b);
                back = 1;
            }
            if (t == t && q.offer(t, this, i, slot)) {
                double[] h = q.hitData;
                h[0] = k[b];
                h[1] = k[b + 1];
                h[2] = k[b + 2];
                h[3] = back;
            }
        }
    }

    @Override
    public boolean anyHit(int from, int to, RayQuery q) {
        double[] k = q.scratch;
        float[] tv = v;
        int at = setUp(q), b = at + Triangle.B0;
        int kx = (int) k[at], ky = (int) k[at + 1], kz = (int) k[at + 2];
        double sx = k[at + Triangle.SX], sy = k[at + Triangle.SY], sz = k[at + Triangle.SZ];
        double okx = k[at + Triangle.OX], oky = k[at + Triangle.OY], okz = k[at + Triangle.OZ];
        double tMin = q.tMin, tMax = q.tMax;
        boolean both = twoSided;
        for (int i = from; i < to; i++) {
            double t = Triangle.hit(tv, 9 * i, kx, ky, kz, sx, sy, sz, okx, oky, okz, tMin, tMax, k, b);
            if (t != t && both) {
                t = Triangle.hit(tv, 9 * i, ky, kx, kz, sy, sx, sz, oky, okx, okz, tMin, tMax, k, b);
            }
            if (t == t) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void fill(int i, RayQuery q, IntersectionRecord rec) {
        double[] h = q.hitData;   // barycentrics and side at 0..3, the corners widened to doubles at 4..12
        for (int c = 0; c < 9; c++) {
            h[4 + c] = v[9 * i + c];
        }
        Triangle.fill(h, 4, h, 0, q.tMax, rec);
        (mesh == null ? only : mesh[i]).finishHit(index[i], h[0], h[1], h[2], h[3] != 0, rec);
    }

    @Override
    public long memoryBytes() {
        return 4L * v.length + (mesh == null ? 0 : 4L * mesh.length) + 4L * index.length;
    }
}
