import javax.vecmath.Vector3d;

/**
 * Diffuse reflection plus a Blinn-Phong highlight.
 *
 * <pre>
 * Material BlinnPhong shiny
 * Vector3d ambientColor [0.1 0.1 0.1]   # k_a
 * Vector3d diffuseColor [0.5 0.5 0.5]   # k_d
 * Vector3d specularColor [1 1 1]        # k_s
 * double exponent 50                    # p
 * </pre>
 */
public class BlinnPhong extends Material {

    public Vector3d ambientColor = new Vector3d();
    public Vector3d diffuseColor = new Vector3d(0.5, 0.5, 0.5);
    public Vector3d specularColor = new Vector3d(1, 1, 1);
    public double exponent = 50;

    /**
     * Method 7 of 11. L = k_a I_a + sum over lights of [k_d I max(0, n.l) + k_s I max(0, n.h)^p],
     * as {@link Diffuse#shade} plus a highlight. h is the half vector: normalize(l + v), where v is the
     * unit vector towards the viewer (minus the ray's direction, made unit length). A light behind the
     * surface (n.l <= 0) adds nothing, highlight included. Return a new vector.
     */
    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 7 of 11
        // STUB: return null;
        Vector3d color = new Vector3d();
        color.x = ambientColor.x * scene.ambientLight.x;
        color.y = ambientColor.y * scene.ambientLight.y;
        color.z = ambientColor.z * scene.ambientLight.z;
        Vector3d toViewer = new Vector3d(ray.direction);
        toViewer.negate();
        toViewer.normalize();
        for (Light light : scene.lights) {
            Vector3d l = light.getDirection(record);
            double nl = record.normal.dot(l);
            if (nl <= 0) {
                continue;
            }
            Vector3d intensity = light.getIntensity(record, scene);
            Vector3d h = new Vector3d();
            h.add(l, toViewer);
            h.normalize();
            double highlight = Math.pow(Math.max(0, record.normal.dot(h)), exponent);
            color.x += intensity.x * (diffuseColor.x * nl + specularColor.x * highlight);
            color.y += intensity.y * (diffuseColor.y * nl + specularColor.y * highlight);
            color.z += intensity.z * (diffuseColor.z * nl + specularColor.z * highlight);
        }
        return color;
        // END SOLUTION
    }

    @Override
    public String toString() {
        return "BlinnPhong[ambient " + ambientColor + ", diffuse " + diffuseColor + ", specular " + specularColor
                + ", exponent " + exponent + "]";
    }
}
