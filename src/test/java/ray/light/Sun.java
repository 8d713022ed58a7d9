package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;

/**
 * The extension test's directional light (ray.ExtensionTest): light of irradiance {@code intensity}
 * arriving from infinitely far along {@code -direction}, casting hard shadows. Only {@link #sample} and
 * the plan's declaration are written; {@code getIntensity} comes from {@link SampledLight}.
 *
 * <pre>
 * Light Sun
 * Vector3d direction [0 -1 0]   # the way the light travels
 * Vector3d intensity [1 1 1]
 * </pre>
 */
public class Sun extends SampledLight {

    public Vector3d direction = new Vector3d(0, -1, 0);
    public Vector3d intensity = new Vector3d(1, 1, 1);

    @Override
    public boolean sample(IntersectionRecord record, Scene scene, int index, LightSample out) {
        double len = direction.length();
        out.setAtInfinity(-direction.x / len, -direction.y / len, -direction.z / len);
        out.intensity.set(intensity);
        out.shadowTested = false;
        return true;
    }

    @Override
    public boolean isDark() {
        return intensity.x == 0 && intensity.y == 0 && intensity.z == 0;
    }

    @Override
    public int shadowRaysPerPoint() {
        return 1;
    }
}
