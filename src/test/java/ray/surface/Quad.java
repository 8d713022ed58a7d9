package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/**
 * The extension test's new primitive (ray.ExtensionTest), written as a user would with nothing but the
 * API: a parallelogram {@code corner + a edge1 + b edge2}, a and b in [0, 1], seen from both sides.
 *
 * <pre>
 * Surface Quad
 * Vector3d corner [-1 0 -1]
 * Vector3d edge1 [2 0 0]
 * Vector3d edge2 [0 0 2]
 * ref material m
 * </pre>
 */
public class Quad extends Surface {

    public Vector3d corner = new Vector3d();
    public Vector3d edge1 = new Vector3d(1, 0, 0);
    public Vector3d edge2 = new Vector3d(0, 0, 1);

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d n = new Vector3d();
        n.cross(edge1, edge2);
        Vector3d d = ray.direction, o = ray.origin;
        double dn = n.dot(d);
        if (dn == 0) {
            return false;
        }
        Vector3d co = new Vector3d();
        co.sub(corner, o);
        double t = co.dot(n) / dn;
        if (!(t >= ray.tMin && t <= ray.tMax)) {
            return false;
        }
        Vector3d p = ray.evaluate(t), q = new Vector3d(), c = new Vector3d();
        q.sub(p, corner);
        c.cross(q, edge2);
        double a = c.dot(n) / n.dot(n);
        c.cross(edge1, q);
        double b = c.dot(n) / n.dot(n);
        if (a < 0 || a > 1 || b < 0 || b > 1) {
            return false;
        }
        n.normalize();
        record.frontFace = dn < 0;
        if (!record.frontFace) {
            n.negate();
        }
        record.t = t;
        record.location.set(p);
        record.normal.set(n);
        record.surface = this;
        return true;
    }

    @Override
    public Aabb bounds() {
        Aabb box = new Aabb();
        for (int i = 0; i < 4; i++) {
            box.include(corner.x + (i & 1) * edge1.x + (i >> 1) * edge2.x, corner.y + (i & 1) * edge1.y + (i >> 1) * edge2.y,
                    corner.z + (i & 1) * edge1.z + (i >> 1) * edge2.z);
        }
        return box;
    }
}
