import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.light.Light;
import ray.light.PointLight;
import ray.material.Material;

/**
 * A student's reflective diffuse material: it traces the reflection first and then lights the point,
 * reading record.location and record.normal after the recursive scene.trace call, and it works out
 * the light direction itself by looking at PointLight's fields.
 *
 * <pre>
 * Material Metal m
 * Vector3d diffuseColor [1 1 1]
 * double reflectance 0.5
 * </pre>
 */
public class Metal extends Material {

    public Vector3d diffuseColor = new Vector3d(1, 1, 1);
    public double reflectance = 0.5;

    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d d = ray.direction;
        Vector3d r = new Vector3d(record.normal);
        r.scale(-2 * d.dot(record.normal));
        r.add(d);
        Vector3d result = scene.trace(new Ray(record.location, r));
        result.scale(reflectance);
        for (Light light : scene.lights) {
            if (!(light instanceof PointLight)) {
                continue;
            }
            Vector3d l = new Vector3d(((PointLight) light).position);
            l.sub(record.location);
            l.normalize();
            double nl = record.normal.dot(l);
            if (nl > 0) {
                Vector3d intensity = light.getIntensity(record, scene);
                result.x += diffuseColor.x * intensity.x * nl;
                result.y += diffuseColor.y * intensity.y * nl;
                result.z += diffuseColor.z * intensity.z * nl;
            }
        }
        return result;
    }
}
