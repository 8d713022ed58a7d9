package ray.material;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;

/**
 * A clear dielectric (glass, water): {@code L = k (R L_reflected + (1 - R) L_refracted)}, the model of
 * Shirley's book. Snell's law bends the refracted ray, R is the Fresnel reflectance (Schlick's
 * approximation by default, the unpolarised Fresnel equations with {@code fresnel exact}), and where
 * Snell's law has no solution all light is reflected (total internal reflection, R = 1). Both rays are
 * one bounce deeper and are followed while the incoming ray's depth is below {@code MaxDepth}; past
 * that the surface adds black.
 *
 * <p>Inside is the side the outward normal points away from: a hit on the back face
 * ({@code frontFace} false) is a ray leaving the medium, which has travelled {@code d = t |direction|}
 * inside it and is attenuated by Beer's law {@code k = exp(-a d)} per channel (k = 1 for a ray
 * arriving from outside). A camera inside the glass thus sees through it attenuated from the eye on.
 * {@code Dielectric} in a scene file names this class too.
 *
 * <pre>
 * Material DielectricMaterial glass
 * double refractiveIndex 1.5        # n inside; outside is 1 (default 1.5)
 * Vector3d attenuation [0 0.2 0.4]  # a, absorption per unit length (default [0 0 0]: clear)
 * String fresnel exact              # schlick (default) or exact
 * </pre>
 */
public class DielectricMaterial extends Material {

    public double refractiveIndex = 1.5;
    public Vector3d attenuation = new Vector3d();
    public String fresnel = "schlick";

    private boolean exact;
    private boolean absorbs;

    @Override
    public void init() {
        if (!(refractiveIndex > 0) || refractiveIndex == Double.POSITIVE_INFINITY) {
            throw new IllegalArgumentException("refractiveIndex must be a finite number > 0, got " + refractiveIndex);
        }
        requireColor("attenuation", attenuation);
        if (attenuation.x < 0 || attenuation.y < 0 || attenuation.z < 0) {
            throw new IllegalArgumentException("attenuation must be >= 0 in each channel, got " + attenuation);
        }
        if ("exact".equals(fresnel)) {
            exact = true;
        } else if ("schlick".equals(fresnel)) {
            exact = false;
        } else {
            throw new IllegalArgumentException("fresnel must be schlick or exact, got '" + fresnel + "'");
        }
        absorbs = attenuation.x > 0 || attenuation.y > 0 || attenuation.z > 0;
    }

    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        return shadeWithContext(ray, record, scene);
    }

    /** Glass needs an inside: the refracted ray travels through it. */
    @Override
    public boolean needsInside() {
        return true;
    }

    /** For the render plan: at most one mirror and one refraction ray per hit, no light evaluated. */
    @Override
    public java.util.Set<ray.material.Term> terms() {
        return java.util.EnumSet.of(ray.material.Term.MIRROR, ray.material.Term.REFRACTION);
    }

    @Override
    public void shade(Ray ray, IntersectionRecord rec, Scene scene, TraceContext ctx, Vector3d out) {
        Vector3d d = ray.direction, n = rec.normal;
        double len = Math.sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (!(len > 0) || len == Double.POSITIVE_INFINITY) {
            out.set(0, 0, 0);
            return;
        }
        double dx = d.x / len, dy = d.y / len, dz = d.z / len;
        // n faces the ray, so cosI = -d.n >= 0 (clamped against rounding)
        double cosI = Math.min(1, Math.max(0, -(dx * n.x + dy * n.y + dz * n.z)));
        boolean entering = rec.frontFace;
        double n1 = entering ? 1 : refractiveIndex, n2 = entering ? refractiveIndex : 1;
        double eta = n1 / n2;
        double cosT = Fresnel.cosTransmitted(eta, cosI);
        double r;
        if (cosT != cosT) {
            r = 1;                                   // total internal reflection
        } else if (exact) {
            r = Fresnel.exact(n1, n2, cosI, cosT);
        } else {
            r = Fresnel.schlick(refractiveIndex, entering ? cosI : cosT);
        }
        // each ray is cast one bounce deeper; past MaxDepth the casting methods cast nothing (null: black)
        double red = 0, green = 0, blue = 0;
        if (r > 0) {
            Vector3d c = scene.traceMirror(ray, rec, ctx);
            if (c != null) {
                red = r * c.x;
                green = r * c.y;
                blue = r * c.z;
            }
        }
        if (r < 1) {
            // Snell: t = eta d + (eta cosI - cosT) n, leaving on the far side of the surface
            double k = eta * cosI - cosT;
            Vector3d c = scene.traceRefraction(ray, rec, eta * dx + k * n.x, eta * dy + k * n.y, eta * dz + k * n.z, ctx);
            if (c != null) {
                double t = 1 - r;
                red += t * c.x;
                green += t * c.y;
                blue += t * c.z;
            }
        }
        if (!entering && absorbs) {
            // Beer's law over the distance just travelled inside
            double dist = rec.t * len;
            red *= Math.exp(-attenuation.x * dist);
            green *= Math.exp(-attenuation.y * dist);
            blue *= Math.exp(-attenuation.z * dist);
        }
        out.set(red, green, blue);
    }

    @Override
    public String toString() {
        return "DielectricMaterial[refractiveIndex " + refractiveIndex + ", attenuation " + attenuation
                + ", fresnel " + fresnel + "]";
    }
}
