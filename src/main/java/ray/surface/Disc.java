package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/**
 * A flat disc, seen from both sides: the {@link Plane} through {@code center} with this normal,
 * clipped to {@code radius} around the centre (pbrt-v4, section 6.4 "Disks", without the inner radius
 * and sweep). It uses the plane's own kernel, so where the disc is, it renders exactly as that plane.
 *
 * <pre>
 * Surface Disc
 * Vector3d center [0 0 0]   # default [0 0 0]
 * Vector3d normal [0 1 0]   # need not be unit length; not zero (default [0 1 0])
 * double radius 1           # default 1, must be positive
 * ref material red
 * </pre>
 */
public class Disc extends Surface {

    public Vector3d center = new Vector3d();
    public Vector3d normal = new Vector3d(0, 1, 0);
    public double radius = 1;

    private Frame frame = new Frame(0, 1, 0);

    @Override
    public void init() {
        Checks.requireFinite(center, "disc center");
        Checks.requireDirection(normal, "disc normal");
        Checks.requirePositive(radius, "disc radius");
        frame = new Frame(normal.x, normal.y, normal.z);
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Frame f = frame;
        double t = Plane.hit(center, f.wx, f.wy, f.wz, ray);
        if (!(t >= ray.tMin && t <= ray.tMax)) {
            return false;
        }
        // inside the radius: the distance from the centre in the plane, from the unprojected point (the
        // projection moves it along the normal only)
        Vector3d o = ray.origin, d = ray.direction;
        double px = o.x + t * d.x - center.x, py = o.y + t * d.y - center.y, pz = o.z + t * d.z - center.z;
        double a = f.u(px, py, pz), b = f.v(px, py, pz);
        if (a * a + b * b > radius * radius) {
            return false;
        }
        Plane.fill(center, f.wx, f.wy, f.wz, ray, t, record);
        record.surface = this;
        return true;
    }

    @Override
    public Aabb bounds() {
        double pad = 1e-12 * (HitMath.maxAbs(center) + radius);
        double ex = radius * frame.circleExtent(0) + pad;
        double ey = radius * frame.circleExtent(1) + pad;
        double ez = radius * frame.circleExtent(2) + pad;
        return new Aabb(center.x - ex, center.y - ey, center.z - ez, center.x + ex, center.y + ey, center.z + ez);
    }

    @Override
    public String toString() {
        return "Disc[center " + center + ", normal " + normal + ", radius " + radius + "]";
    }
}
