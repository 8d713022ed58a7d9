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
        // inside framework-style material code, ctx.level is the depth of the rays it traces: one more
        // than the ray it is shading (which may be a fresh Ray of depth 0 it made itself)
        int depth = Math.max(ray.depth, ctx.level - 1);
        if (mirrorCoefficient == 0 || depth >= scene.maxDepth) {
            return;
        }
        // mirror direction r = d - 2 (d.n) n
        Vector3d d = ray.direction, n = rec.normal;
        double dn = 2 * (d.x * n.x + d.y * n.y + d.z * n.z);
        Ray mirror = ctx.ray(depth + 1);
        rec.spawnRay(d.x - dn * n.x, d.y - dn * n.y, d.z - dn * n.z, mirror);
        mirror.depth = depth + 1;
        Vector3d c = ctx.color(depth + 1);
        ctx.stats.mirror++;
        scene.traceInto(mirror, ctx, c);
        out.x += mirrorCoefficient * c.x;
        out.y += mirrorCoefficient * c.y;
        out.z += mirrorCoefficient * c.z;
    }

    @Override
    public String toString() {
        return "GlazedMaterial[base " + base + ", mirrorCoefficient " + mirrorCoefficient + "]";
    }
}
