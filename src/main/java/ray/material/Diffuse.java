package ray.material;

import java.util.EnumSet;
import java.util.Set;
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
    public Set<Term> terms() {
        Set<Term> t = EnumSet.noneOf(Term.class);
        if (!zero(ambientColor)) {
            t.add(Term.AMBIENT);
        }
        if (!zero(diffuseColor)) {
            t.add(Term.DIFFUSE);
        }
        Vector3d ks = specularColorOrNull();
        if (ks != null && !zero(ks)) {
            t.add(Term.HIGHLIGHT);
        }
        return t;
    }

    /** Evaluates the lights unless it has no direct term and the plan skips them there. */
    @Override
    public HitCost hitCost(ShadingPlan plan) {
        HitCost c = super.hitCost(plan);
        return c.evaluatesLights() || plan.skipsLightsWithoutDirectTerm() ? c
                : new HitCost(c.terms(), c.mirrorRays(), c.refractionRays(), true, c.weight(), c.foldedLevels());
    }

    /** Caches k_a I_a and the lights to evaluate: none where the plan finds no direct term. */
    @Override
    public void planned(ShadingPlan plan) {
        Scene scene = plan.scene();
        Vector3d ia = scene.ambientLight;
        ambient = new double[] {ambientColor.x * ia.x, ambientColor.y * ia.y, ambientColor.z * ia.z};
        lights = hitCost(plan).evaluatesLights() ? plan.lights() : new Light[0];
        plannedFor = scene;
    }

    /** The scene {@link #planned} last ran for, and what it cached (k_a I_a, the lights to evaluate). */
    private Scene plannedFor;
    private double[] ambient;
    private Light[] lights;

    @Override
    public void shade(Ray ray, IntersectionRecord rec, Scene scene, TraceContext ctx, Vector3d out) {
        double r, g, b;
        Light[] ls;
        if (plannedFor == scene) {
            r = ambient[0];
            g = ambient[1];
            b = ambient[2];
            ls = lights;
        } else {   // shaded outside a planned render (a unit test, a hand-made scene): every light
            Vector3d ia = scene.ambientLight;
            r = ambientColor.x * ia.x;
            g = ambientColor.y * ia.y;
            b = ambientColor.z * ia.z;
            ls = scene.lights.toArray(new Light[0]);
        }
        Vector3d n = rec.normal;
        LightSample s = ctx.lightSample;
        Vector3d kd = diffuseColorAt(rec, ctx.reflectance);   // k_d here: the field, or a texture's value
        Vector3d ks = specularColorOrNull();   // null: no highlight term at all (plain Diffuse)
        for (int k = 0; k < ls.length; k++) {   // k: the occluder cache's slot for this light's shadow rays
            Light light = ls[k];
            for (int i = 0, count = light.renderSampleCount(); i < count; i++) {
                if (!light.renderSample(rec, scene, i, s)) {
                    continue;
                }
                Vector3d l = s.direction;
                double nl = n.x * l.x + n.y * l.y + n.z * l.z;
                // the light is behind the surface: no contribution, no shadow ray
                if (!(nl > 0) || (!s.shadowTested && scene.occluded(rec, s, ctx, k))) {
                    continue;
                }
                Vector3d li = s.intensity;
                if (ks == null) {
                    // k_d nl + 0: the same sums as with a zero highlight (0 * 0 = +0), without its calls
                    r += li.x * (kd.x * nl + 0.0);
                    g += li.y * (kd.y * nl + 0.0);
                    b += li.z * (kd.z * nl + 0.0);
                } else {
                    double spec = specular(ray, n, l);
                    r += li.x * (kd.x * nl + ks.x * spec);
                    g += li.y * (kd.y * nl + ks.y * spec);
                    b += li.z * (kd.z * nl + ks.z * spec);
                }
            }
        }
        out.set(r, g, b);
    }

    static boolean zero(Vector3d c) {
        return c.x == 0 && c.y == 0 && c.z == 0;
    }

    /**
     * The reflectance hook: k_d at the hit, for every light of this hit. The default is the
     * {@code diffuseColor} field; a textured material returns its texture's value there, written into
     * {@code scratch} (this thread's, free to overwrite) and returned, and copies nothing else: the light
     * loop, the plan's cache and the shadow rays stay Diffuse's.
     *
     * <pre>
     * public class Checker extends Diffuse {
     *     protected Vector3d diffuseColorAt(IntersectionRecord rec, Vector3d scratch) {
     *         boolean odd = ((int) Math.floor(rec.location.x) + (int) Math.floor(rec.location.z) &amp; 1) != 0;
     *         if (odd) {
     *             return diffuseColor;
     *         }
     *         scratch.set(0.1, 0.1, 0.1);
     *         return scratch;
     *     }
     * }
     * </pre>
     */
    protected Vector3d diffuseColorAt(IntersectionRecord rec, Vector3d scratch) {
        return diffuseColor;
    }

    /** The highlight hook: the specular factor for the unit light direction l (0 for a pure diffuse material). */
    protected double specular(Ray ray, Vector3d n, Vector3d l) {
        return 0;
    }

    /** k_s, or null when the material has no highlight (then {@link #specular} is never called). */
    protected Vector3d specularColorOrNull() {
        return null;
    }

    @Override
    public String toString() {
        return getClass().getSimpleName() + "[ambient " + ambientColor + ", diffuse " + diffuseColor + "]";
    }
}
