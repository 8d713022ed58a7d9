package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/**
 * A closed axis-aligned box. Its normals point outward; seen from inside, the record's normal is
 * turned to face the ray and {@code frontFace} is false.
 *
 * <pre>
 * Surface Box
 * Vector3d minPoint [-1 -1 -1]   # default [-1 -1 -1]
 * Vector3d maxPoint [1 1 1]      # default [1 1 1]; above minPoint in every coordinate
 * ref material red
 * </pre>
 *
 * The test is the slab method of Kay and Kajiya ("Ray Tracing Complex Scenes", SIGGRAPH 1986) in the
 * form of Williams et al. ("An Efficient and Robust Ray-Box Intersection Algorithm", JGT 10(1), 2005):
 * the ray's span inside the box is the intersection of its spans between each pair of parallel faces,
 * entered where the last slab is entered and left where the first is left. A ray parallel to a slab is
 * inside it or not as a whole (no 0 * infinity). Entry and exit come from one comparison, so a ray
 * through an edge or corner hits exactly one face there and a ray from outside that enters also leaves.
 * The hit point is put exactly on the face it hit (and clamped into the face), so it lies on the box.
 */
public class Box extends Surface {

    /** Relative rounding-error bound used for the spawn offset (the point itself lies on the box). */
    static final double ERROR = 32 * HitMath.EPS;

    public Vector3d minPoint = new Vector3d(-1, -1, -1);
    public Vector3d maxPoint = new Vector3d(1, 1, 1);

    @Override
    public void init() {
        Checks.requireFinite(minPoint, "box minPoint");
        Checks.requireFinite(maxPoint, "box maxPoint");
        if (!(minPoint.x < maxPoint.x && minPoint.y < maxPoint.y && minPoint.z < maxPoint.z)) {
            throw new IllegalArgumentException("box minPoint must be below maxPoint in every coordinate, got "
                    + minPoint + " and " + maxPoint);
        }
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d o = ray.origin, d = ray.direction;
        double enter = Double.NEGATIVE_INFINITY, exit = Double.POSITIVE_INFINITY;
        int enterFace = -1, exitFace = -1;     // axis, + 3 for the max face
        for (int axis = 0; axis < 3; axis++) {
            double oa = get(o, axis), da = get(d, axis), lo = get(minPoint, axis), hi = get(maxPoint, axis);
            if (da == 0) {
                if (oa < lo || oa > hi) {
                    return false;              // parallel to this slab, outside it
                }
                continue;
            }
            double t0 = (lo - oa) / da, t1 = (hi - oa) / da;
            int f0 = axis, f1 = axis + 3;
            if (t0 > t1) {
                double s = t0; t0 = t1; t1 = s;
                f0 = axis + 3; f1 = axis;
            }
            if (t0 > enter) {
                enter = t0;
                enterFace = f0;
            }
            if (t1 < exit) {
                exit = t1;
                exitFace = f1;
            }
        }
        if (!(enter <= exit) || enterFace < 0) {
            return false;                      // missed, or a zero direction
        }
        double t;
        int face;
        boolean front;
        if (enter >= ray.tMin && enter <= ray.tMax) {
            t = enter; face = enterFace; front = true;
        } else if (exit >= ray.tMin && exit <= ray.tMax && enter < ray.tMin) {
            t = exit; face = exitFace; front = false;
        } else {
            return false;
        }
        fill(ray, t, face, front, record);
        record.surface = this;
        return true;
    }

    private void fill(Ray ray, double t, int face, boolean front, IntersectionRecord rec) {
        Vector3d o = ray.origin, d = ray.direction;
        double x = HitMath.clamp(o.x + t * d.x, minPoint.x, maxPoint.x);
        double y = HitMath.clamp(o.y + t * d.y, minPoint.y, maxPoint.y);
        double z = HitMath.clamp(o.z + t * d.z, minPoint.z, maxPoint.z);
        int axis = face % 3;
        double side = face < 3 ? -1 : 1;
        double v = face < 3 ? get(minPoint, axis) : get(maxPoint, axis);
        if (axis == 0) x = v; else if (axis == 1) y = v; else z = v;
        rec.location.set(x, y, z);
        HitMath.face(rec, axis == 0 ? side : 0, axis == 1 ? side : 0, axis == 2 ? side : 0, front);
        rec.t = t;
        rec.error = ERROR * Math.max(HitMath.maxAbs(minPoint), HitMath.maxAbs(maxPoint));
    }

    private static double get(Vector3d v, int axis) {
        return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
    }


    /** True when (x, y, z) lies strictly inside the box. */
    public boolean isInside(double x, double y, double z) {
        return x > minPoint.x && x < maxPoint.x && y > minPoint.y && y < maxPoint.y && z > minPoint.z && z < maxPoint.z;
    }

    /** Closed: a solid, hit from inside with {@code frontFace} false, so it can be a CSG operand. */
    @Override
    public boolean isClosed() {
        return true;
    }

    @Override
    public Aabb bounds() {
        return new Aabb(minPoint.x, minPoint.y, minPoint.z, maxPoint.x, maxPoint.y, maxPoint.z);
    }

    @Override
    public String toString() {
        return "Box[" + minPoint + " .. " + maxPoint + "]";
    }
}
