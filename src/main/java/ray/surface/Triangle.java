package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;
import ray.accel.PrimitiveSet;

/**
 * A one-sided triangle: only rays arriving from the side of n = (v1 - v0) x (v2 - v0) hit it (and
 * only those are blocked by it as shadow rays). A ray lying in its plane misses; a zero-area triangle
 * is never hit.
 *
 * <pre>
 * Surface Triangle
 * Vector3d v0 [0 0 0]
 * Vector3d v1 [1 0 0]
 * Vector3d v2 [0 1 0]
 * ref material red
 * </pre>
 *
 * The test is the watertight algorithm of Woop, Benthin and Wald (JCGT 2013): the vertices are moved
 * into a frame where the ray runs along +z, and the 2D edge functions are computed from the same
 * vertex values for both triangles that share an edge, so a ray through a shared edge or vertex of a
 * closed mesh cannot slip between them.
 */
public class Triangle extends Surface {

    /** Relative rounding-error bound of a hit point computed from barycentrics (a generous gamma(32)). */
    static final double ERROR = 32 * 0x1p-53;

    public Vector3d v0 = new Vector3d();
    public Vector3d v1 = new Vector3d(1, 0, 0);
    public Vector3d v2 = new Vector3d(0, 1, 0);

    @Override
    public void init() {
        requireFinite(v0);   // one by one, not over a new array: a mesh has 100k triangles to check
        requireFinite(v1);
        requireFinite(v2);
    }

    private static void requireFinite(Vector3d v) {
        if (!Double.isFinite(v.x) || !Double.isFinite(v.y) || !Double.isFinite(v.z)) {
            throw new IllegalArgumentException("triangle vertices must be finite, got " + v);
        }
    }

    /** Zero area: the edges are parallel to double precision (or a vertex repeats). */
    @Override
    public boolean isDegenerate() {
        double ax = v1.x - v0.x, ay = v1.y - v0.y, az = v1.z - v0.z;
        double bx = v2.x - v0.x, by = v2.y - v0.y, bz = v2.z - v0.z;
        double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
        double n = Math.sqrt(nx * nx + ny * ny + nz * nz);
        double ea = Math.sqrt(ax * ax + ay * ay + az * az), eb = Math.sqrt(bx * bx + by * by + bz * bz);
        return !(n > 1e-14 * ea * eb);
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        if (isDegenerate()) {
            return false;
        }
        double[] v = {v0.x, v0.y, v0.z, v1.x, v1.y, v1.z, v2.x, v2.y, v2.z};
        double[] k = new double[KERNEL_SIZE];
        setupRay(ray, k, 0);
        double t = hit(v, 0, (int) k[0], (int) k[1], (int) k[2], k[SX], k[SY], k[SZ], k[OX], k[OY], k[OZ],
                ray.tMin, ray.tMax, k, B0);
        if (Double.isNaN(t)) {
            return false;
        }
        fill(v, 0, k, B0, t, record);
        record.surface = this;
        return true;
    }

    /** The packed set for exactly this class (a subclass may override {@link #intersects}: it keeps its own). */
    @Override
    public PrimitiveSet.Type primitiveType() {
        return getClass() == Triangle.class ? TriangleSet.TYPE : null;
    }

    @Override
    public Aabb bounds() {
        return bounds(this, new Aabb());
    }

    /** {@code t}'s box: {@code empty} (an empty box) grown to its three vertices. */
    static Aabb bounds(Triangle t, Aabb empty) {
        empty.include(t.v0.x, t.v0.y, t.v0.z);
        empty.include(t.v1.x, t.v1.y, t.v1.z);
        empty.include(t.v2.x, t.v2.y, t.v2.z);
        return empty;
    }

    // ---- the watertight kernel, the one the BVH uses too (TriangleSet; vertices packed 9 doubles each) ----

    /** Length of the per-ray array of {@link #setupRay}: the set-up, then room for the barycentrics. */
    public static final int KERNEL_SIZE = 12;
    /** Relative rounding bound of the edge functions (16 eps; see {@link #hit}). */
    public static final double PARALLEL = 16 * 0x1p-53;
    /** Offsets in {@link #setupRay}'s output: kx, ky, kz at 0..2, then these. */
    static final int SX = 3, SY = 4, SZ = 5, OX = 6, OY = 7, OZ = 8, B0 = 9;

    /**
     * Per-ray set-up into {@code k[at..at+8]}: kz the dominant axis of the direction, kx and ky the
     * others (swapped when d[kz] is negative, to keep the winding), the shear constants sx, sy, sz, and
     * the origin in that axis order.
     */
    public static void setupRay(Ray ray, double[] k, int at) {
        double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        int kx = kz == 2 ? 0 : kz + 1;
        int ky = kx == 2 ? 0 : kx + 1;
        double dkz = component(kz, dx, dy, dz);
        if (dkz < 0) {
            int tmp = kx;
            kx = ky;
            ky = tmp;
        }
        k[at] = kx;
        k[at + 1] = ky;
        k[at + 2] = kz;
        k[at + SX] = component(kx, dx, dy, dz) / dkz;
        k[at + SY] = component(ky, dx, dy, dz) / dkz;
        k[at + SZ] = 1.0 / dkz;
        Vector3d o = ray.origin;
        k[at + OX] = component(kx, o.x, o.y, o.z);
        k[at + OY] = component(ky, o.x, o.y, o.z);
        k[at + OZ] = component(kz, o.x, o.y, o.z);
    }

    private static double component(int axis, double x, double y, double z) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }

    /**
     * The t in [tMin, tMax] where the ray set up by {@link #setupRay} (kx..okz) hits the front of the
     * triangle stored at {@code v[off..off+8]}, or NaN. On a hit the barycentric weights of v0, v1, v2
     * are written to {@code bary[at..at+2]}.
     */
    public static double hit(double[] v, int off, int kx, int ky, int kz, double sx, double sy, double sz,
                             double okx, double oky, double okz, double tMin, double tMax, double[] bary, int at) {
        // vertices relative to the origin, in the ray's axis order
        double ax = v[off + kx] - okx, ay = v[off + ky] - oky, az = v[off + kz] - okz;
        double bx = v[off + 3 + kx] - okx, by = v[off + 3 + ky] - oky, bz = v[off + 3 + kz] - okz;
        double cx = v[off + 6 + kx] - okx, cy = v[off + 6 + ky] - oky, cz = v[off + 6 + kz] - okz;
        return hit(ax, ay, az, bx, by, bz, cx, cy, cz, sx, sy, sz, tMin, tMax, bary, at);
    }

    /**
     * {@link #hit(double[], int, int, int, int, double, double, double, double, double, double, double,
     * double, double[], int)} on vertices stored as floats (a mesh's own coordinates): each is widened to
     * the same double and the same kernel runs, so t and the barycentrics are bit-identical to the double
     * version's on the widened vertices.
     */
    public static double hit(float[] v, int off, int kx, int ky, int kz, double sx, double sy, double sz,
                             double okx, double oky, double okz, double tMin, double tMax, double[] bary, int at) {
        // vertices relative to the origin, in the ray's axis order
        double ax = v[off + kx] - okx, ay = v[off + ky] - oky, az = v[off + kz] - okz;
        double bx = v[off + 3 + kx] - okx, by = v[off + 3 + ky] - oky, bz = v[off + 3 + kz] - okz;
        double cx = v[off + 6 + kx] - okx, cy = v[off + 6 + ky] - oky, cz = v[off + 6 + kz] - okz;
        return hit(ax, ay, az, bx, by, bz, cx, cy, cz, sx, sy, sz, tMin, tMax, bary, at);
    }

    /**
     * The kernel of both {@code hit}s above: the triangle's corners a, b, c already relative to the ray's
     * origin and in its axis order (kx, ky, kz). Named {@code hit} so the launcher's C1 inlines it
     * ({@code CompileCommand=inline,ray.*::hit}); one kernel whatever the vertices are stored as.
     */
    private static double hit(double ax, double ay, double az, double bx, double by, double bz, double cx, double cy,
                              double cz, double sx, double sy, double sz, double tMin, double tMax, double[] bary, int at) {
        // shear so the ray runs along +z, and the edge functions; the front side gives all three >= 0. Each
        // is tested as soon as it is known, a's shear only after the first: most triangles a ray is tested
        // against fail one, and C1 (a short render's compiler) runs the lines in this order, where C2
        // would have moved the later ones past the first test itself. The same numbers in every case
        double pbx = sx * bz, pby = sy * bz, pcx = sx * cz, pcy = sy * cz;
        double qbx = bx - pbx, qby = by - pby, qcx = cx - pcx, qcy = cy - pcy;
        double u = qcx * qby - qcy * qbx;
        if (u < 0) {
            return Double.NaN;
        }
        double pax = sx * az, pay = sy * az;
        double qax = ax - pax, qay = ay - pay;
        double w0 = qax * qcy - qay * qcx;
        if (w0 < 0) {
            return Double.NaN;
        }
        double w1 = qbx * qay - qby * qax;
        if (w1 < 0) {
            return Double.NaN;
        }
        double det = u + w0 + w1;
        if (!(det > 0)) {
            return Double.NaN;      // ray in the triangle's plane, or seen from behind on an edge
        }
        double tScaled = sz * (u * az + w0 * bz + w1 * cz);
        if (tScaled < tMin * det || tScaled > tMax * det) {
            return Double.NaN;
        }
        // det (twice the sheared triangle's area) within its rounding error of 0: the ray lies in the
        // triangle's plane up to rounding, and t = tScaled / det would be noise. Each sheared coordinate
        // is off by at most 4 eps (|a| + |s a_z|); 16 eps covers each edge function's products.
        double mAx = Math.abs(ax) + Math.abs(pax), mAy = Math.abs(ay) + Math.abs(pay);
        double mBx = Math.abs(bx) + Math.abs(pbx), mBy = Math.abs(by) + Math.abs(pby);
        double mCx = Math.abs(cx) + Math.abs(pcx), mCy = Math.abs(cy) + Math.abs(pcy);
        if (det <= PARALLEL * (mCx * mBy + mCy * mBx + mAx * mCy + mAy * mCx + mBx * mAy + mBy * mAx)) {
            return Double.NaN;
        }
        double inv = 1 / det;
        bary[at] = u * inv;
        bary[at + 1] = w0 * inv;
        bary[at + 2] = w1 * inv;
        return tScaled * inv;
    }

    /**
     * Fills a record for a hit at t found by {@link #hit} (barycentrics at {@code bary[at..at+2]}): point
     * from the barycentrics, unit normal, error bound.
     */
    public static void fill(double[] v, int off, double[] bary, int at, double t, IntersectionRecord rec) {
        fillPoint(v, off, bary, at, t, rec);
        fillNormal(v, off, rec);
    }

    /** What {@link #fill} writes that differs from hit to hit: the point from the barycentrics, t, the side. */
    static void fillPoint(double[] v, int off, double[] bary, int at, double t, IntersectionRecord rec) {
        double b0 = bary[at], b1 = bary[at + 1], b2 = bary[at + 2];
        double x0 = v[off], y0 = v[off + 1], z0 = v[off + 2];
        double x1 = v[off + 3], y1 = v[off + 4], z1 = v[off + 5];
        double x2 = v[off + 6], y2 = v[off + 7], z2 = v[off + 8];
        rec.location.set(b0 * x0 + b1 * x1 + b2 * x2, b0 * y0 + b1 * y1 + b2 * y2, b0 * z0 + b1 * z1 + b2 * z2);
        rec.frontFace = true;
        rec.t = t;
    }

    /**
     * What {@link #fill} writes that is the triangle's own, the same for every hit on it: the unit normal
     * and the error bound (a square root, three divisions and nine comparisons: {@link TriangleSet} keeps
     * them from a thread's last hit).
     */
    static void fillNormal(double[] v, int off, IntersectionRecord rec) {
        double x0 = v[off], y0 = v[off + 1], z0 = v[off + 2];
        double ex = v[off + 3] - x0, ey = v[off + 4] - y0, ez = v[off + 5] - z0;
        double fx = v[off + 6] - x0, fy = v[off + 7] - y0, fz = v[off + 8] - z0;
        double nx = ey * fz - ez * fy, ny = ez * fx - ex * fz, nz = ex * fy - ey * fx;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        rec.normal.set(nx / len, ny / len, nz / len);
        double m = 0;
        for (int i = 0; i < 9; i++) {
            double c = Math.abs(v[off + i]);
            if (c > m) {        // Math.max without the call C1 makes (no NaN or -0 can occur here)
                m = c;
            }
        }
        rec.error = ERROR * m;
    }

    @Override
    public String toString() {
        return "Triangle[" + v0 + ", " + v1 + ", " + v2 + "]";
    }
}
