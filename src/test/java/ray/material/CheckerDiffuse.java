package ray.material;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;

/**
 * The extension test's textured material (ray.ExtensionTest): Diffuse with k_d a checkerboard of
 * {@code diffuseColor} and {@code otherColor} in unit squares of x and z. Only the reflectance hook is
 * written; the light loop, the plan's cache, the shadow rays and the plan's declaration are Diffuse's.
 *
 * <pre>
 * Material CheckerDiffuse c
 * Vector3d diffuseColor [0.8 0.8 0.8]
 * Vector3d otherColor [0.1 0.1 0.1]
 * </pre>
 */
public class CheckerDiffuse extends Diffuse {

    public Vector3d otherColor = new Vector3d(0.1, 0.1, 0.1);

    @Override
    protected Vector3d diffuseColorAt(IntersectionRecord rec, Vector3d scratch) {
        boolean odd = ((long) Math.floor(rec.location.x) + (long) Math.floor(rec.location.z) & 1) != 0;
        return odd ? otherColor : diffuseColor;
    }
}
