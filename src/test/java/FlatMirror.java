import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;

/**
 * A student's mirror: its own colour plus the reflection, found by calling scene.trace recursively
 * with a plain new Ray (the student knows nothing of depths; the scene's MaxDepth must stop it).
 *
 * <pre>
 * Material FlatMirror m
 * Vector3d color [1 0 0]
 * double reflectance 0.5
 * </pre>
 */
public class FlatMirror extends Material {

    public Vector3d color = new Vector3d(0, 0, 0);
    public double reflectance = 0.5;

    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d d = ray.direction;
        Vector3d n = record.normal;
        Vector3d r = new Vector3d(n);
        r.scale(-2 * d.dot(n));
        r.add(d);
        Vector3d result = scene.trace(new Ray(record.location, r));
        result.scale(reflectance);
        result.add(color);
        return result;
    }
}
