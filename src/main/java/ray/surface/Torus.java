package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/**
 * A ring torus: the points at distance {@code minorRadius} from the circle of radius
 * {@code majorRadius} around {@code center} in the plane normal to {@code axis}. Closed: its normals
 * point away from the tube's middle; seen from inside the tube, the record's normal is turned to face
 * the ray and {@code frontFace} is false.
 *
 * <pre>
 * Surface Torus
 * Vector3d center [0 0 0]     # default [0 0 0]
 * Vector3d axis [0 1 0]       # normal of the torus's plane; not zero (default [0 1 0])
 * double majorRadius 1        # centre to the middle of the tube (default 1)
 * double minorRadius 0.25     # radius of the tube (default 0.25); 0 < minorRadius < majorRadius
 * ref material red
 * </pre>
 *
 * A ray meets the torus where the quartic (|p|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + y^2) = 0 (Hanrahan,
 * "Ray Tracing Algebraic Surfaces", SIGGRAPH 1983; Cychosz, "Intersecting a Ray with an Elliptical Torus",
 * Graphics Gems II, 1991). Closed-form quartic formulas lose most digits at grazing angles and far from
 * the torus, so they are not used:
 * <ol>
 * <li>In the torus's frame, the ray's origin is moved to its closest approach to the centre and its
 * direction made unit length, so the quartic's coefficients are of the torus's size whatever the
 * distance; a line missing the bounding sphere (radius R + r) is a miss.</li>
 * <li>The quartic's real roots lie in [-h, h], h the half chord of the bounding sphere. They are
 * isolated by its critical points, found in turn between the roots of its second derivative (a
 * quadratic): between two critical points the quartic is monotonic, so it changes sign at most
 * once.</li>
 * <li>Each sign change is located with safeguarded Newton iteration on the distance to the tube,
 * sqrt((rho - R)^2 + z^2) - r, which has the quartic's zeros (for r &lt; R) but is Lipschitz and well
 * conditioned near the surface; bisection is the fallback, so it always converges.</li>
 * <li>The hit point is projected onto the tube.</li>
 * </ol>
 * The crossings do not depend on the ray's [tMin, tMax]: the first one inside it is returned, entering
 * ({@code frontFace}) or leaving the solid.
 */
public class Torus extends Surface {

    /** Relative rounding-error bound of a hit point moved back to world coordinates (generous). */
    static final double ERROR = 64 * HitMath.EPS;
    private static final int MAX_ITERATIONS = 100;

    public Vector3d center = new Vector3d();
    public Vector3d axis = new Vector3d(0, 1, 0);
    public double majorRadius = 1;
    public double minorRadius = 0.25;

    private Frame frame = new Frame(0, 1, 0);

    @Override
    public void init() {
        Checks.requireFinite(center, "torus center");
        Checks.requireDirection(axis, "torus axis");
        Checks.requirePositive(majorRadius, "torus majorRadius");
        Checks.requirePositive(minorRadius, "torus minorRadius");
        if (!(minorRadius < majorRadius)) {
            throw new IllegalArgumentException("torus minorRadius must be below majorRadius (a ring torus; a horn or"
                    + " spindle torus intersects itself), got minorRadius " + minorRadius + " and majorRadius " + majorRadius);
        }
        frame = new Frame(axis.x, axis.y, axis.z);
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Frame f = frame;
        double big = majorRadius, r = minorRadius, bound = big + r;
        Vector3d o = ray.origin, dd = ray.direction;
        double ex = o.x - center.x, ey = o.y - center.y, ez = o.z - center.z;
        double ox = f.u(ex, ey, ez), oy = f.v(ex, ey, ez), oz = f.w(ex, ey, ez);
        double dx = f.u(dd.x, dd.y, dd.z), dy = f.v(dd.x, dd.y, dd.z), dz = f.w(dd.x, dd.y, dd.z);
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        if (!(len > 0) || len == Double.POSITIVE_INFINITY) {
            return false;
        }
        double ux = dx / len, uy = dy / len, uz = dz / len;
        // origin moved to the closest approach to the centre: a point of the ray is p + tau u, t = (tc + tau) / len
        double tc = -(ox * ux + oy * uy + oz * uz);
        double px = ox + tc * ux, py = oy + tc * uy, pz = oz + tc * uz;
        double dist = Math.sqrt(px * px + py * py + pz * pz);
        if (!(dist <= bound * (1 + 1e-9))) {
            return false;                                   // misses the bounding sphere (or NaN)
        }
        double half = Math.sqrt(Math.max(0, (bound - dist) * (bound + dist))) + 1e-9 * bound;
        if ((tc + half) / len < ray.tMin || (tc - half) / len > ray.tMax) {
            return false;
        }
        // the quartic tau^4 + c3 tau^3 + c2 tau^2 + c1 tau + c0
        double rr = big * big, e = px * px + py * py + pz * pz + rr - r * r;
        double fd = px * ux + py * uy + pz * uz, g = ux * ux + uy * uy;
        double hh = px * ux + py * uy, ii = px * px + py * py;
        double c3 = 4 * fd, c2 = 4 * fd * fd + 2 * e - 4 * rr * g;
        double c1 = 4 * fd * e - 8 * rr * hh;
        // roots of the second derivative 12 tau^2 + 6 c3 tau + 2 c2 split [-h, h] into stretches where the
        // first derivative is monotonic; its root in each is a critical point of the quartic
        double s1 = half, s2 = half;
        double disc = 36 * c3 * c3 - 96 * c2;
        if (disc > 0) {
            double q = -0.5 * (6 * c3 + Math.copySign(Math.sqrt(disc), c3));
            double a = q / 12, b = q == 0 ? -a : 2 * c2 / q;
            s1 = HitMath.clamp(Math.min(a, b), -half, half);
            s2 = HitMath.clamp(Math.max(a, b), -half, half);
        }
        double prev = -half;
        for (int seg = 0; seg < 4; seg++) {
            double lo = seg == 0 ? -half : seg == 1 ? s1 : s2, hi = seg == 0 ? s1 : seg == 1 ? s2 : half;
            double next;
            if (seg == 3) {
                next = half;
            } else if (hi > lo && slope(lo, c3, c2, c1) * slope(hi, c3, c2, c1) < 0) {
                next = criticalPoint(lo, hi, c3, c2, c1, 1e-12 * bound);
            } else {
                continue;
            }
            if (next > prev) {
                double tau = crossing(prev, next, px, py, pz, ux, uy, uz, big, r, 4 * HitMath.EPS * bound);
                if (!Double.isNaN(tau)) {
                    double t = (tc + tau) / len;
                    if (t > ray.tMax) {
                        return false;                       // later crossings are farther still
                    }
                    if (t >= ray.tMin) {
                        fill(record, px + tau * ux, py + tau * uy, pz + tau * uz, t, tubeDistance(prev, px, py, pz, ux, uy, uz, big, r) > 0);
                        return true;
                    }
                }
                prev = next;
            }
        }
        return false;
    }

    /** The quartic's first derivative, 4 tau^3 + 3 c3 tau^2 + 2 c2 tau + c1. */
    private static double slope(double x, double c3, double c2, double c1) {
        return ((4 * x + 3 * c3) * x + 2 * c2) * x + c1;
    }

    /** The root of the first derivative in [lo, hi], where it changes sign (safeguarded Newton). */
    private static double criticalPoint(double lo, double hi, double c3, double c2, double c1, double tol) {
        double flo = slope(lo, c3, c2, c1);
        double x = 0.5 * (lo + hi);
        for (int i = 0; i < MAX_ITERATIONS && hi - lo > tol; i++) {
            double fx = slope(x, c3, c2, c1);
            if (fx == 0) {
                return x;
            }
            if ((fx < 0) == (flo < 0)) {
                lo = x;
            } else {
                hi = x;
            }
            double nx = x - fx / ((12 * x + 6 * c3) * x + 2 * c2);
            if (nx > lo && nx < hi) {
                if (Math.abs(nx - x) <= tol) {
                    return nx;
                }
                x = nx;
            } else {
                x = 0.5 * (lo + hi);
            }
        }
        return x;
    }

    /**
     * The tau in [lo, hi] where the distance to the tube changes sign, or NaN when it has the same sign
     * at both ends. A point exactly on the surface counts as inside.
     */
    private static double crossing(double lo, double hi, double px, double py, double pz,
                                   double ux, double uy, double uz, double big, double r, double tol) {
        double slo = tubeDistance(lo, px, py, pz, ux, uy, uz, big, r);
        double shi = tubeDistance(hi, px, py, pz, ux, uy, uz, big, r);
        if ((slo > 0) == (shi > 0)) {
            return Double.NaN;
        }
        boolean loOutside = slo > 0;
        double x = 0.5 * (lo + hi);
        for (int i = 0; i < MAX_ITERATIONS; i++) {
            // distance to the tube at x and its derivative along u (the unit vector from the tube's middle)
            double qx = px + x * ux, qy = py + x * uy, qz = pz + x * uz;
            double rho = Math.sqrt(qx * qx + qy * qy);
            double s = rho > 0 ? 1 - big / rho : 0;
            double vx = qx * s, vy = qy * s, vz = qz;
            double dc = Math.sqrt(vx * vx + vy * vy + vz * vz);
            double sx = dc - r;
            if (sx == 0) {
                return x;
            }
            if ((sx > 0) == loOutside) {
                lo = x;
            } else {
                hi = x;
            }
            if (!(hi - lo > tol)) {
                break;
            }
            double slope = dc > 0 ? (vx * ux + vy * uy + vz * uz) / dc : 0;
            double nx = x - sx / slope;
            if (nx > lo && nx < hi) {
                if (Math.abs(nx - x) <= tol) {
                    return nx;
                }
                x = nx;
            } else {
                x = 0.5 * (lo + hi);
            }
        }
        return x;
    }

    /** Distance from p + tau u to the tube's surface, negative inside. */
    private static double tubeDistance(double tau, double px, double py, double pz,
                                       double ux, double uy, double uz, double big, double r) {
        double qx = px + tau * ux, qy = py + tau * uy, qz = pz + tau * uz;
        double rho = Math.sqrt(qx * qx + qy * qy);
        double a = rho - big;
        return Math.sqrt(a * a + qz * qz) - r;
    }

    /** Fills the record for the local point q: projected onto the tube, outward normal, world coordinates. */
    private void fill(IntersectionRecord rec, double qx, double qy, double qz, double t, boolean entering) {
        Frame f = frame;
        double big = majorRadius, r = minorRadius;
        double rho = Math.sqrt(qx * qx + qy * qy);
        double cx, cy;                                      // nearest point of the tube's middle circle
        if (rho > 0) {
            cx = big * qx / rho;
            cy = big * qy / rho;
        } else {
            cx = big;                                       // unreachable for r < R; any circle point
            cy = 0;
        }
        double vx = qx - cx, vy = qy - cy, vz = qz;
        double dc = Math.sqrt(vx * vx + vy * vy + vz * vz);
        double nx, ny, nz;
        if (dc > 0) {
            nx = vx / dc; ny = vy / dc; nz = vz / dc;
        } else {
            nx = 0; ny = 0; nz = 1;                         // unreachable: the middle circle is inside
        }
        double x = cx + r * nx, y = cy + r * ny, z = r * nz;
        rec.location.set(center.x + f.worldX(x, y, z), center.y + f.worldY(x, y, z), center.z + f.worldZ(x, y, z));
        HitMath.face(rec, f.worldX(nx, ny, nz), f.worldY(nx, ny, nz), f.worldZ(nx, ny, nz), entering);
        rec.t = t;
        rec.error = ERROR * (HitMath.maxAbs(center) + big + r);
        rec.surface = this;
    }

    /** True when (x, y, z) lies strictly inside the tube. */
    public boolean isInside(double x, double y, double z) {
        double ex = x - center.x, ey = y - center.y, ez = z - center.z;
        return tubeDistance(0, frame.u(ex, ey, ez), frame.v(ex, ey, ez), frame.w(ex, ey, ez), 0, 0, 0,
                majorRadius, minorRadius) < 0;
    }

    /** Closed: a solid, hit from inside with {@code frontFace} false, so it can be a CSG operand. */
    @Override
    public boolean isClosed() {
        return true;
    }

    @Override
    public Aabb bounds() {
        double pad = 1e-12 * (HitMath.maxAbs(center) + majorRadius + minorRadius);
        double ex = majorRadius * frame.circleExtent(0) + minorRadius + pad;
        double ey = majorRadius * frame.circleExtent(1) + minorRadius + pad;
        double ez = majorRadius * frame.circleExtent(2) + minorRadius + pad;
        return new Aabb(center.x - ex, center.y - ey, center.z - ez, center.x + ex, center.y + ey, center.z + ez);
    }

    @Override
    public String toString() {
        return "Torus[center " + center + ", axis " + axis + ", majorRadius " + majorRadius
                + ", minorRadius " + minorRadius + "]";
    }
}
