package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;

/**
 * A closed right circular cone: the side from the base circle to the apex, and the base disc. Its
 * normals point outward; seen from inside, the record's normal is turned to face the ray and
 * {@code frontFace} is false.
 *
 * <pre>
 * Surface Cone
 * Vector3d base [0 0 0]     # centre of the base disc (default [0 0 0])
 * Vector3d axis [0 1 0]     # base centre to apex; its length is the height (default [0 1 0])
 * double radius 1           # base radius (default 1, must be positive)
 * ref material red
 * </pre>
 *
 * In the cone's frame (z along the axis, apex at z = h, k = r / h) the side is
 * x^2 + y^2 = k^2 (h - z)^2 (pbrt-v3, section 3.5.1 "Cones", closed here by the base disc). The solid is
 * the nappe of that double cone that holds the base, cut by the slab 0 <= z <= h; the ray's span
 * inside the nappe comes from the quadratic (solved in the stable form, after moving the ray's origin
 * to its closest approach to the cone's middle, so the coefficients are of the cone's size), its span
 * in the slab from two divisions, and the hit is where both spans overlap first (or, from inside, where
 * the overlap ends). Side and base are decided by one comparison (no crack at the rim). The hit point
 * is put on the part it hit.
 */
public class Cone extends AxialSurface {

    private static final int SIDE = 0, BASE = 1;

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Frame f = frame();
        double r = radius, h = height(), k = r / h, kk = k * k;
        Vector3d o = ray.origin, dd = ray.direction;
        double ex = o.x - base.x, ey = o.y - base.y, ez = o.z - base.z;
        double ox = f.u(ex, ey, ez), oy = f.v(ex, ey, ez), oz = f.w(ex, ey, ez);
        double dx = f.u(dd.x, dd.y, dd.z), dy = f.v(dd.x, dd.y, dd.z), dz = f.w(dd.x, dd.y, dd.z);
        double dd2 = dx * dx + dy * dy + dz * dz;
        if (!(dd2 > 0) || dd2 == Double.POSITIVE_INFINITY) {
            return false;
        }
        // move the origin to the ray's closest approach to the middle of the axis: t = tc + tau
        double tc = -(ox * dx + oy * dy + (oz - 0.5 * h) * dz) / dd2;
        double px = ox + tc * dx, py = oy + tc * dy, ps = h - (oz + tc * dz);   // s = h - z: 0 at the apex
        double ds = -dz;
        // inside the double cone: A tau^2 + 2 B tau + C <= 0
        double qa = dx * dx + dy * dy - kk * ds * ds;
        double qb = px * dx + py * dy - kk * ps * ds;
        double qc = px * px + py * py - kk * ps * ps;
        double enter = Double.NEGATIVE_INFINITY, exit = Double.POSITIVE_INFINITY;
        if (qa == 0) {
            // along a generator: one root of the linear equation, a half-line (or all or nothing)
            if (qb == 0) {
                if (qc > 0) {
                    return false;
                }
            } else if (qb > 0) {
                exit = -qc / (2 * qb);
            } else {
                enter = -qc / (2 * qb);
            }
        } else {
            double disc = qb * qb - qa * qc;
            if (disc < 0) {
                if (qa > 0) {
                    return false;
                }
                disc = 0;                              // through the apex, up to rounding
            }
            double q = -(qb + Math.copySign(Math.sqrt(disc), qb));
            double t1 = q == 0 ? 0 : qc / q, t2 = q == 0 ? 0 : q / qa;
            if (t1 > t2) {
                double s = t1; t1 = t2; t2 = s;
            }
            if (qa > 0) {
                enter = t1;                            // between the roots: within one nappe (cut below)
                exit = t2;
            } else if (ds > 0) {
                enter = t2;                            // two half-lines: the one running into s > 0
            } else {
                exit = t1;
            }
        }
        int enterPart = SIDE, exitPart = SIDE;
        // the slab 0 <= s <= h: s = 0 is the apex's plane (only the apex itself), s = h the base
        if (ds != 0) {
            double t0 = -ps / ds, t1 = (h - ps) / ds;
            int p0 = SIDE, p1 = BASE;
            if (t0 > t1) {
                double s = t0; t0 = t1; t1 = s;
                p0 = BASE; p1 = SIDE;
            }
            if (t0 > enter) {
                enter = t0;
                enterPart = p0;
            }
            if (t1 < exit) {
                exit = t1;
                exitPart = p1;
            }
        } else if (!(ps >= 0 && ps <= h)) {
            return false;
        }
        if (!(enter <= exit) || enter == Double.NEGATIVE_INFINITY || exit == Double.POSITIVE_INFINITY) {
            return false;
        }
        double t, tau;
        int part;
        boolean front;
        if (tc + enter >= ray.tMin && tc + enter <= ray.tMax) {
            tau = enter; part = enterPart; front = true;
        } else if (tc + enter < ray.tMin && tc + exit >= ray.tMin && tc + exit <= ray.tMax) {
            tau = exit; part = exitPart; front = false;
        } else {
            return false;
        }
        t = tc + tau;
        // hit point in the local frame, put on the part hit
        double x = px + tau * dx, y = py + tau * dy, z;
        double rho = Math.sqrt(x * x + y * y);
        double nx, ny, nz;
        if (part == SIDE) {
            z = HitMath.clamp(h - (ps + tau * ds), 0, h);
            double target = k * (h - z);               // the side's radius at this height
            double c = 1 / Math.sqrt(1 + kk);
            if (rho > 0 && target > 0) {
                x *= target / rho;
                y *= target / rho;
                nx = c * x / target;
                ny = c * y / target;
                nz = c * k;
            } else {                                   // at the apex: the axis
                x = 0; y = 0; nx = 0; ny = 0; nz = 1;
            }
        } else {
            z = 0;
            nx = 0; ny = 0; nz = -1;
            if (rho > r) {
                x *= r / rho;
                y *= r / rho;
            }
        }
        fill(record, t, x, y, z, nx, ny, nz, front);
        return true;
    }

    @Override
    double radiusAt(double z) {
        return radius / height() * (height() - z);
    }

    @Override
    public String toString() {
        return "Cone[base " + base + ", axis " + axis + ", radius " + radius + "]";
    }
}
