import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.surface.Surface;

/**
 * A student's infinite plane, written only against the 2003 framework API (only the imports are new):
 * a naive absolute epsilon, no bounds(), and the record's normal pointed straight at this object's
 * own field, as students did. The project must cope with all three. (Named StudentPlane, not Plane:
 * a default-package class shadows the built-in {@code ray.surface.Plane} of the same name, and this one
 * is on the class path of every test.)
 *
 * <pre>
 * Surface StudentPlane
 * Vector3d point [0 0 0]
 * Vector3d normal [0 1 0]   # unit length
 * ref material floor
 * </pre>
 */
public class StudentPlane extends Surface {

    public Vector3d point = new Vector3d(0, 0, 0);
    public Vector3d normal = new Vector3d(0, 1, 0);

    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        double denom = normal.dot(ray.direction);
        if (Math.abs(denom) < 1e-9) {
            return false;
        }
        Vector3d toPoint = new Vector3d();
        toPoint.sub(point, ray.origin);
        double t = toPoint.dot(normal) / denom;
        if (t < 0.0001 || t < ray.tMin || t > ray.tMax) {
            return false;
        }
        record.t = t;
        record.location = ray.evaluate(t);
        record.normal = normal;
        record.surface = this;
        return true;
    }
}
