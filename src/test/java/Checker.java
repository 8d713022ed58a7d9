import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.light.Light;
import ray.material.Material;

/**
 * A student's checkerboard for a floor (squares in x and z), lit by whatever each light's
 * getIntensity says, with no n.l term: only the framework's shade(Ray, IntersectionRecord, Scene).
 *
 * <pre>
 * Material Checker board
 * Vector3d color1 [1 1 1]
 * Vector3d color2 [0 0 0]
 * double size 1
 * </pre>
 */
public class Checker extends Material {

    public Vector3d color1 = new Vector3d(1, 1, 1);
    public Vector3d color2 = new Vector3d(0, 0, 0);
    public double size = 1;

    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d p = record.location;
        int sum = (int) Math.floor(p.x / size) + (int) Math.floor(p.z / size);
        Vector3d c = (sum % 2 == 0) ? color1 : color2;
        Vector3d result = new Vector3d();
        for (int i = 0; i < scene.lights.size(); i++) {
            Light light = scene.lights.get(i);
            Vector3d intensity = light.getIntensity(record, scene);
            result.x += c.x * intensity.x;
            result.y += c.y * intensity.y;
            result.z += c.z * intensity.z;
        }
        return result;
    }
}
