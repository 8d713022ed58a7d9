package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;
import ray.accel.PrimitiveSet;

/**
 * A sphere. Its normal points outward; seen from inside, the record's normal is turned to face the
 * ray (so a lit interior is visible) and {@code frontFace} is false.
 *
 * <pre>
 * Surface Sphere
 * Vector3d center [0 0 0]   # default [0 0 0]
 * double radius 1           # default 1, must be positive
 * ref material red
 * </pre>
 *
 * The ray/sphere test uses the numerically improved quadratic of Haines et al., "Precision
 * Improvements for Ray/Sphere Intersection" (Ray Tracing Gems ch. 7): the discriminant from the
 * distance of the centre to the ray's line, and each root from the stable form, so small spheres far
 * away, huge spheres close up and grazing rays give clean hits or clean misses.
 */
public class Sphere extends Surface {

    /** Relative rounding-error bound of a computed hit point (a generous gamma(32)). */
    static final double ERROR = 32 * 0x1p-53;

    public Vector3d center = new Vector3d();
    public double radius = 1;

    @Override
    public void init() {
        if (!Double.isFinite(center.x) || !Double.isFinite(center.y) || !Double.isFinite(center.z)) {
            throw new IllegalArgumentException("sphere center must be finite, got " + center);
        }
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("sphere radius must be a positive number, got " + radius);
        }
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d o = ray.origin, d = ray.direction;
        double t = hit(center.x, center.y, center.z, radius, o.x, o.y, o.z, d.x, d.y, d.z, ray.tMin, ray.tMax);
        if (Double.isNaN(t)) {
            return false;
        }
        fill(center.x, center.y, center.z, radius, o.x, o.y, o.z, d.x, d.y, d.z, t, record);
        record.surface = this;
        return true;
    }

    /** The packed set for exactly this class (a subclass may override {@link #intersects}: it keeps its own). */
    @Override
    public PrimitiveSet.Type primitiveType() {
        return getClass() == Sphere.class ? SphereSet.TYPE : null;
    }

    @Override
    public boolean isClosed() {
        return true;
    }

    @Override
    public Aabb bounds() {
        return bounds(this, new Aabb());
    }

    /** {@code s}'s box, written into {@code box}. */
    static Aabb bounds(Sphere s, Aabb box) {
        Vector3d c = s.center;
        double r = s.radius;
        return box.set(c.x - r, c.y - r, c.z - r, c.x + r, c.y + r, c.z + r);
    }

    /** The nearest t in [tMin, tMax] where the ray meets the sphere, or NaN. */
    public static double hit(double cx, double cy, double cz, double r,
                             double ox, double oy, double oz, double dx, double dy, double dz,
                             double tMin, double tMax) {
        double fx = ox - cx, fy = oy - cy, fz = oz - cz;
        double a = dx * dx + dy * dy + dz * dz;
        if (!(a > 0) || a == Double.POSITIVE_INFINITY) {
            return Double.NaN;
        }
        double b = fx * dx + fy * dy + fz * dz;            // half the linear coefficient
        double ff = fx * fx + fy * fy + fz * fz;
        double c = ff - r * r;
        // a ray leaving from outside the sphere (c > 0) and heading away from its centre (b > 0): both
        // roots are negative (their product c / a > 0, their sum -2b / a < 0), and so are the computed
        // ones below (q < 0, so c / q < 0 and q / a < 0), so no t >= tMin >= 0 is a hit. Every shadow ray
        // leaving a sphere toward its light takes this exit before any square root. With tMin = 0 (a spawned
        // ray) a root rounded to -0.0 would pass; the magnitudes checked rule that out: a disc <= a r^2 <
        // a ff, so q is finite, and |q| <= 2 sqrt(a ff) <= a + ff (Cauchy-Schwarz), so |c / q| >= 2^-901 and
        // |q / a| >= b / a >= 2^-900
        if (b > 0 && c > 0 && tMin >= 0
                && (tMin > 0 || (a * ff <= 0x1p1000 && c >= 0x1p-900 * (a + ff) && b >= 0x1p-900 * a))) {
            return Double.NaN;
        }
        // a clear miss, decided without a division or a square root: the centre's squared distance from
        // the line is |f x d|^2 / a exactly; when it exceeds r^2 by far more than any rounding below
        // (a relative 1e-6 of r^2, plus 1e-6 of |f|^2 for the cancellation in the cross product),
        // the exact test below would find disc < 0 too
        double qx = fy * dz - fz * dy, qy = fz * dx - fx * dz, qz = fx * dy - fy * dx;
        if (qx * qx + qy * qy + qz * qz > a * (r * r * (1 + 1e-6) + 1e-6 * ff)) {
            return Double.NaN;
        }
        // discriminant / a = r^2 - |f - (f.d / a) d|^2: the centre's squared distance from the line
        double s = b / a;
        double lx = fx - s * dx, ly = fy - s * dy, lz = fz - s * dz;
        double dist = Math.sqrt(lx * lx + ly * ly + lz * lz);
        double disc = (r - dist) * (r + dist);           // no cancellation near the silhouette
        if (disc < 0) {
            return Double.NaN;
        }
        // stable roots: q = -(b + sign(b) sqrt(a disc)); t0 = c / q, t1 = q / a
        double q = -(b + Math.copySign(Math.sqrt(a * disc), b));
        double t0, t1;
        if (q == 0) {
            t0 = t1 = 0;
        } else {
            t0 = c / q;
            t1 = q / a;
        }
        // ordered by comparison, not Math.min/max, which C1 calls rather than inlines; a NaN root is a
        // miss, as Math.min/max's NaN would be
        double tNear, tFar;
        if (t0 <= t1) {
            tNear = t0;
            tFar = t1;
        } else if (t1 < t0) {
            tNear = t1;
            tFar = t0;
        } else {
            return Double.NaN;
        }
        if (tNear >= tMin && tNear <= tMax) {
            return tNear;
        }
        if (tFar >= tMin && tFar <= tMax) {
            return tFar;
        }
        return Double.NaN;
    }

    /** Fills a record for a hit at t: point re-projected onto the sphere, normal facing the ray, error bound. */
    public static void fill(double cx, double cy, double cz, double r,
                            double ox, double oy, double oz, double dx, double dy, double dz,
                            double t, IntersectionRecord rec) {
        double vx = ox + t * dx - cx, vy = oy + t * dy - cy, vz = oz + t * dz - cz;
        double len = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double nx, ny, nz;
        if (len > 0) {
            nx = vx / len; ny = vy / len; nz = vz / len;
        } else {                      // cannot happen for r > 0; keep the normal a unit vector anyway
            nx = 0; ny = 0; nz = 1;
        }
        rec.location.set(cx + r * nx, cy + r * ny, cz + r * nz);
        boolean front = nx * dx + ny * dy + nz * dz <= 0;
        rec.frontFace = front;
        if (front) {
            rec.normal.set(nx, ny, nz);
        } else {
            rec.normal.set(-nx, -ny, -nz);
        }
        rec.t = t;
        // the largest |coordinate| (plain comparisons: C1 calls Math.max; no NaN or -0 can occur here)
        double ax = Math.abs(cx), ay = Math.abs(cy), az = Math.abs(cz);
        double m = ax > ay ? (ax > az ? ax : az) : (ay > az ? ay : az);
        rec.error = ERROR * (m + r);
    }

    @Override
    public String toString() {
        return "Sphere[center " + center + ", radius " + radius + "]";
    }
}
