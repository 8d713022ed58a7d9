package ray.material;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;

/**
 * A glazed surface: a base material plus an ideal mirror reflection,
 * {@code L = L_base + k_m L_mirror} ({@code L_base} = 0 without a base). The mirror ray is followed
 * while the incoming ray's depth is below the scene's {@code MaxDepth}; past that it adds nothing.
 * {@code Glazed} in a scene file names this class too.
 *
 * <pre>
 * Material GlazedMaterial mirror
 * ref base shiny               # optional base material
 * double mirrorCoefficient 0.8 # k_m, default 0.5
 * </pre>
 */
public class GlazedMaterial extends Material {

    public Material base;
    public double mirrorCoefficient = 0.5;

    @Override
    public void init() {
        if (!Double.isFinite(mirrorCoefficient)) {
            throw new IllegalArgumentException("mirrorCoefficient must be a finite number, got " + mirrorCoefficient);
        }
        if (base == this) {
            throw new IllegalArgumentException("a glazed material cannot be its own base");
        }
    }

    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        return shadeWithContext(ray, record, scene);
    }

    @Override
    public void shade(Ray ray, IntersectionRecord rec, Scene scene, TraceContext ctx, Vector3d out) {
        if (base != null) {
            base.shade(ray, rec, scene, ctx, out);
        } else {
            out.set(0, 0, 0);
        }
        if (mirrorCoefficient == 0) {
            return;
        }
        Vector3d c = scene.traceMirror(ray, rec, ctx);   // null past MaxDepth: adds nothing
        if (c != null) {
            out.x += mirrorCoefficient * c.x;
            out.y += mirrorCoefficient * c.y;
            out.z += mirrorCoefficient * c.z;
        }
    }

    @Override
    public String toString() {
        return "GlazedMaterial[base " + base + ", mirrorCoefficient " + mirrorCoefficient + "]";
    }
}
