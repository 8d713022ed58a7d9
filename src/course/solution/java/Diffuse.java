import javax.vecmath.Vector3d;

/**
 * Lambertian (matte) reflection with an ambient term.
 *
 * <pre>
 * Material Diffuse red
 * Vector3d ambientColor [0.1 0 0]   # k_a
 * Vector3d diffuseColor [0.8 0 0]   # k_d
 * </pre>
 */
public class Diffuse extends Material {

    public Vector3d ambientColor = new Vector3d();
    public Vector3d diffuseColor = new Vector3d(0.5, 0.5, 0.5);

    /**
     * Method 6 of 11. L = k_a I_a + sum over the scene's lights of k_d I max(0, n.l), where I_a is
     * {@code scene.ambientLight}, I is {@code light.getIntensity(record, scene)} (already I / r^2 and
     * black in shadow), n is record.normal and l is {@code light.getDirection(record)}. Products of
     * two colours are per channel (red times red, ...). A light behind the surface (n.l <= 0) adds
     * nothing. Return a new vector.
     */
    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 6 of 11
        // STUB: return null;
        Vector3d color = new Vector3d();
        color.x = ambientColor.x * scene.ambientLight.x;
        color.y = ambientColor.y * scene.ambientLight.y;
        color.z = ambientColor.z * scene.ambientLight.z;
        for (Light light : scene.lights) {
            double nl = record.normal.dot(light.getDirection(record));
            if (nl <= 0) {
                continue;
            }
            Vector3d intensity = light.getIntensity(record, scene);
            color.x += diffuseColor.x * intensity.x * nl;
            color.y += diffuseColor.y * intensity.y * nl;
            color.z += diffuseColor.z * intensity.z * nl;
        }
        return color;
        // END SOLUTION
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[ambient " + ambientColor + ", diffuse " + diffuseColor + "]";
    }
}
