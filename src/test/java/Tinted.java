import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;

/**
 * A student's filter over another material (built-in or not), calling its framework shade method.
 *
 * <pre>
 * Material Tinted t
 * ref inner glass
 * Vector3d tint [1 1 1]
 * </pre>
 */
public class Tinted extends Material {

    public Material inner;
    public Vector3d tint = new Vector3d(1, 1, 1);

    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d c = inner.shade(ray, record, scene);
        return new Vector3d(c.x * tint.x, c.y * tint.y, c.z * tint.z);
    }
}
