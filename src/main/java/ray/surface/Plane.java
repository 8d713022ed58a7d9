package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;

/**
 * An infinite plane, seen from both sides. {@code frontFace} is true on the side {@code normal}
 * points to; from either side the record's normal faces the ray.
 *
 * <pre>
 * Surface Plane
 * Vector3d point [0 0 0]    # any point of the plane (default [0 0 0])
 * Vector3d normal [0 1 0]   # need not be unit length; not zero (default [0 1 0])
 * ref material floor
 * </pre>
 *
 * The ray/plane test is t = ((point - o) . n) / (d . n) (Haines, "Essential Ray Tracing Algorithms", in
 * Glassner, An Introduction to Ray Tracing, 1989); the hit
 * point is projected back onto the plane, so it lies on it to rounding whatever the ray's length.
 * A plane has no bounds: the BVH tests it against every ray.
 */
public class Plane extends Surface {

    /** Relative rounding-error bound of a projected hit point (a generous gamma(32)). */
    static final double ERROR = 32 * HitMath.EPS;

    public Vector3d point = new Vector3d();
    public Vector3d normal = new Vector3d(0, 1, 0);

    /** Unit normal, derived by {@link #init()}. */
    private double nx, ny = 1, nz;

    @Override
    public void init() {
        Checks.requireFinite(point, "plane point");
        Checks.requireDirection(normal, "plane normal");
        double len = normal.length();
        nx = normal.x / len;
        ny = normal.y / len;
        nz = normal.z / len;
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        double t = hit(point, nx, ny, nz, ray);
        if (!(t >= ray.tMin && t <= ray.tMax)) {
            return false;
        }
        fill(point, nx, ny, nz, ray, t, record);
        record.surface = this;
        return true;
    }

    /**
     * The t where the ray meets the plane through {@code p} with unit normal n (any t, range not
     * checked), or NaN when the ray runs parallel to it. Shared with {@link Disc}.
     */
    static double hit(Vector3d p, double nx, double ny, double nz, Ray ray) {
        Vector3d o = ray.origin, d = ray.direction;
        double dn = nx * d.x + ny * d.y + nz * d.z;
        if (dn == 0) {
            return Double.NaN;
        }
        double t = ((p.x - o.x) * nx + (p.y - o.y) * ny + (p.z - o.z) * nz) / dn;
        return Double.isFinite(t) ? t : Double.NaN;
    }

    /** Fills a record for the hit at t: point projected onto the plane, normal facing the ray, error bound. */
    static void fill(Vector3d p, double nx, double ny, double nz, Ray ray, double t, IntersectionRecord rec) {
        Vector3d o = ray.origin, d = ray.direction;
        double hx = o.x + t * d.x, hy = o.y + t * d.y, hz = o.z + t * d.z;
        double s = (hx - p.x) * nx + (hy - p.y) * ny + (hz - p.z) * nz;
        hx -= s * nx;
        hy -= s * ny;
        hz -= s * nz;
        rec.location.set(hx, hy, hz);
        HitMath.face(rec, nx, ny, nz, nx * d.x + ny * d.y + nz * d.z < 0);
        rec.t = t;
        double m = Math.max(Math.abs(hx), Math.max(Math.abs(hy), Math.abs(hz)));
        rec.error = Math.max(ERROR * (m + HitMath.maxAbs(p)), Double.MIN_NORMAL);   // > 0 at the origin too
    }

    @Override
    public String toString() {
        return "Plane[point " + point + ", normal " + normal + "]";
    }
}
