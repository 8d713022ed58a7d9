import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;
import ray.light.Light;

/**
 * A student's light that reaches everywhere with the same intensity and casts no shadow; it hands
 * back its own field, as students did.
 *
 * <pre>
 * Light ConstantLight
 * Vector3d intensity [0.1 0.1 0.1]
 * </pre>
 */
public class ConstantLight extends Light {

    public Vector3d intensity = new Vector3d(0.1, 0.1, 0.1);

    public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
        return intensity;
    }
}
