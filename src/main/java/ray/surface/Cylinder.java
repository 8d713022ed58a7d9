package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;

/**
 * A closed circular cylinder: the side and both caps. Its normals point outward; seen from inside, the
 * record's normal is turned to face the ray and {@code frontFace} is false.
 *
 * <pre>
 * Surface Cylinder
 * Vector3d base [0 0 0]     # centre of the bottom cap (default [0 0 0])
 * Vector3d axis [0 1 0]     # bottom cap centre to top cap centre; its length is the height (default [0 1 0])
 * double radius 1           # default 1, must be positive
 * ref material red
 * </pre>
 *
 * The solid is the intersection of an infinite cylinder and the slab between the caps (pbrt-v4,
 * section 6.3 "Cylinders", closed by the caps as in section 6.4): in the cylinder's own frame the ray's
 * span inside the infinite cylinder comes from the distance of the axis to the ray's line (the
 * improved quadratic of Haines et al., Ray Tracing Gems ch. 7, in 2D), its span between the caps from
 * two divisions, and the hit is where the intersection of the two spans begins (or, from inside,
 * ends). Side and caps are decided by one comparison, so the rim has no crack and no double hit. The
 * hit point is put on the part it hit (radius exactly r on the side, height exactly 0 or h on a cap).
 */
public class Cylinder extends AxialSurface {

    private static final int SIDE = 0, BOTTOM = 1, TOP = 2;

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Frame f = frame();
        double r = radius, h = height();
        Vector3d o = ray.origin, dd = ray.direction;
        double ex = o.x - base.x, ey = o.y - base.y, ez = o.z - base.z;
        double ox = f.u(ex, ey, ez), oy = f.v(ex, ey, ez), oz = f.w(ex, ey, ez);
        double dx = f.u(dd.x, dd.y, dd.z), dy = f.v(dd.x, dd.y, dd.z), dz = f.w(dd.x, dd.y, dd.z);
        double enter = Double.NEGATIVE_INFINITY, exit = Double.POSITIVE_INFINITY;
        int enterPart = -1, exitPart = -1;
        // span inside the infinite cylinder
        double a = dx * dx + dy * dy;
        if (a > 0) {
            double tc = -(ox * dx + oy * dy) / a;
            double qx = ox + tc * dx, qy = oy + tc * dy;
            double dist = Math.sqrt(qx * qx + qy * qy);
            double disc = (r - dist) * (r + dist);     // r^2 - dist^2 without cancellation
            if (!(disc >= 0)) {
                return false;
            }
            double half = Math.sqrt(disc / a);
            enter = tc - half;
            exit = tc + half;
            enterPart = exitPart = SIDE;
        } else if (!(ox * ox + oy * oy <= r * r)) {
            return false;                              // along the axis, outside the side
        }
        // span between the caps
        if (dz != 0) {
            double t0 = -oz / dz, t1 = (h - oz) / dz;
            int p0 = BOTTOM, p1 = TOP;
            if (t0 > t1) {
                double s = t0; t0 = t1; t1 = s;
                p0 = TOP; p1 = BOTTOM;
            }
            if (t0 > enter) {
                enter = t0;
                enterPart = p0;
            }
            if (t1 < exit) {
                exit = t1;
                exitPart = p1;
            }
        } else if (!(oz >= 0 && oz <= h)) {
            return false;                              // parallel to the caps, outside them
        }
        if (!(enter <= exit) || enterPart < 0 || exitPart < 0) {
            return false;
        }
        double t;
        int part;
        boolean front;
        if (enter >= ray.tMin && enter <= ray.tMax) {
            t = enter; part = enterPart; front = true;
        } else if (enter < ray.tMin && exit >= ray.tMin && exit <= ray.tMax) {
            t = exit; part = exitPart; front = false;
        } else {
            return false;
        }
        // hit point in the local frame, put on the part hit
        double x = ox + t * dx, y = oy + t * dy, z;
        double nx = 0, ny = 0, nz;
        double rho = Math.sqrt(x * x + y * y);
        if (part == SIDE) {
            z = HitMath.clamp(oz + t * dz, 0, h);
            if (rho > 0) {
                nx = x / rho;
                ny = y / rho;
            } else {
                nx = 1;                                // unreachable for r > 0; keep a unit normal
            }
            x = r * nx;
            y = r * ny;
            nz = 0;
        } else {
            z = part == TOP ? h : 0;
            nz = part == TOP ? 1 : -1;
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
        return radius;
    }

    @Override
    public String toString() {
        return "Cylinder[base " + base + ", axis " + axis + ", radius " + radius + "]";
    }
}
