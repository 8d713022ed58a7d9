package ray.material;

import javax.vecmath.Vector3d;
import ray.Ray;

/**
 * Diffuse plus a Blinn-Phong highlight:
 * {@code L = k_a I_a + sum over lights [k_d (I/r^2) max(0, n.l) + k_s (I/r^2) max(0, n.h)^p]},
 * h the unit half vector between the light and the viewer. Lights behind the surface (n.l <= 0)
 * add nothing, highlight included.
 *
 * <pre>
 * Material BlinnPhong shiny
 * Vector3d ambientColor [0.1 0.1 0.1]   # k_a, default [0 0 0]
 * Vector3d diffuseColor [0.5 0.5 0.5]   # k_d, default [0.5 0.5 0.5]
 * Vector3d specularColor [1 1 1]        # k_s, default [1 1 1]
 * double exponent 50                    # p, default 50
 * </pre>
 */
public class BlinnPhong extends Diffuse {

    public Vector3d specularColor = new Vector3d(1, 1, 1);
    public double exponent = 50;

    @Override
    public void init() {
        super.init();
        requireColor("specularColor", specularColor);
        if (!Double.isFinite(exponent) || exponent < 0) {
            throw new IllegalArgumentException("exponent must be a number >= 0, got " + exponent);
        }
    }

    @Override
    protected double specular(Ray ray, Vector3d n, Vector3d l) {
        Vector3d d = ray.direction;
        double dl = Math.sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (!(dl > 0)) {
            return 0;
        }
        // h = normalize(l + v), v = -d / |d| (towards the viewer)
        double hx = l.x - d.x / dl, hy = l.y - d.y / dl, hz = l.z - d.z / dl;
        double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
        if (!(hl > 0)) {
            return 0;      // light exactly behind the viewer's line: no defined half vector
        }
        double nh = (n.x * hx + n.y * hy + n.z * hz) / hl;
        return nh > 0 ? Math.pow(nh, exponent) : 0;
    }

    @Override
    protected Vector3d specularColorOrNull() {
        return java.util.Objects.requireNonNull(specularColor, "specularColor");   // a highlight, always
    }

    @Override
    public String toString() {
        return "BlinnPhong[ambient " + ambientColor + ", diffuse " + diffuseColor
                + ", specular " + specularColor + ", exponent " + exponent + "]";
    }
}
