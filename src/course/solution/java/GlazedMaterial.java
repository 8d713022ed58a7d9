import javax.vecmath.Vector3d;

/**
 * A mirror glaze over an optional base material: L = L_base + k_m L_mirror.
 *
 * <pre>
 * Material GlazedMaterial mirror     # "Glazed" names the same class
 * ref base shiny                     # optional
 * double mirrorCoefficient 0.8       # k_m
 * </pre>
 */
public class GlazedMaterial extends Material {

    /** The material under the glaze, or null for none (then L_base is black). */
    public Material base;
    public double mirrorCoefficient = 0.5;

    /**
     * Method 8 of 11. L = L_base + k_m L_mirror. L_base is {@code base.shade(ray, record, scene)}, or
     * black when there is no base (base == null). L_mirror is the colour {@code scene.trace} finds along
     * the mirror ray: from record.location in the reflected direction r = d - 2 (d.n) n (d the ray's
     * direction, n record.normal), with depth ray.depth + 1 (Scene.trace stops rays deeper than
     * MaxDepth). Return a new vector: do not change the one the base returned.
     */
    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 8 of 11
        // STUB: return null;
        Vector3d color = new Vector3d();
        if (base != null) {
            color.set(base.shade(ray, record, scene));
        }
        Vector3d reflected = new Vector3d();
        reflected.scaleAdd(-2 * ray.direction.dot(record.normal), record.normal, ray.direction);
        Ray mirrorRay = new Ray(record.location, reflected);
        mirrorRay.depth = ray.depth + 1;
        color.scaleAdd(mirrorCoefficient, scene.trace(mirrorRay), color);
        return color;
        // END SOLUTION
    }

    @Override
    public String toString() {
        return "GlazedMaterial[base " + base + ", mirrorCoefficient " + mirrorCoefficient + "]";
    }
}
