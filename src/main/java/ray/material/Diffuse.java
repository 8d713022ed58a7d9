package ray.material;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.light.Light;
import ray.light.LightSample;

/**
 * Lambertian reflection with an ambient term:
 * {@code L = k_a I_a + sum over lights k_d (I / r^2) max(0, n.l)}.
 *
 * <pre>
 * Material Diffuse red
 * Vector3d ambientColor [0.1 0 0]   # k_a, default [0 0 0]
 * Vector3d diffuseColor [0.8 0 0]   # k_d, default [0.5 0.5 0.5]
 * </pre>
 */
public class Diffuse extends Material {

    public Vector3d ambientColor = new Vector3d();
    public Vector3d diffuseColor = new Vector3d(0.5, 0.5, 0.5);

    @Override
    public void init() {
        requireColor("ambientColor", ambientColor);
        requireColor("diffuseColor", diffuseColor);
    }

    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        return shadeWithContext(ray, record, scene);
    }

    @Override
    public void shade(Ray ray, IntersectionRecord rec, Scene scene, TraceContext ctx, Vector3d out) {
        Vector3d ia = scene.ambientLight;
        double r = ambientColor.x * ia.x, g = ambientColor.y * ia.y, b = ambientColor.z * ia.z;
        Vector3d n = rec.normal;
        LightSample s = ctx.lightSample;
        Vector3d ks = specularColorOrNull();   // null: no highlight term at all (plain Diffuse)
        java.util.List<Light> lights = scene.lights;
        // an index loop: a for-each would allocate an Iterator per shading point wherever the JIT does
        // not remove it (C1, the launcher's compiler, has no escape analysis)
        for (int k = 0, lightCount = lights.size(); k < lightCount; k++) {
            Light light = lights.get(k);
            for (int i = 0, count = light.sampleCount(); i < count; i++) {
                if (!light.sample(rec, scene, i, s)) {
                    continue;
                }
                Vector3d l = s.direction;
                double nl = n.x * l.x + n.y * l.y + n.z * l.z;
                // the light is behind the surface: no contribution, no shadow ray
                if (!(nl > 0) || (!s.shadowTested && scene.occluded(rec, s, ctx))) {
                    continue;
                }
                Vector3d li = s.intensity;
                if (ks == null) {
                    // k_d nl + 0: the same sums as with a zero highlight (0 * 0 = +0), without its calls
                    r += li.x * (diffuseColor.x * nl + 0.0);
                    g += li.y * (diffuseColor.y * nl + 0.0);
                    b += li.z * (diffuseColor.z * nl + 0.0);
                } else {
                    double spec = specular(ray, n, l);
                    r += li.x * (diffuseColor.x * nl + ks.x * spec);
                    g += li.y * (diffuseColor.y * nl + ks.y * spec);
                    b += li.z * (diffuseColor.z * nl + ks.z * spec);
                }
            }
        }
        out.set(r, g, b);
    }

    /** Specular factor for the light direction l (0 for a pure diffuse material). */
    double specular(Ray ray, Vector3d n, Vector3d l) {
        return 0;
    }

    /** k_s, or null when the material has no highlight (then {@link #specular} is never called). */
    Vector3d specularColorOrNull() {
        return null;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[ambient " + ambientColor + ", diffuse " + diffuseColor + "]";
    }
}
