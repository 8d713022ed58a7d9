package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;
import ray.TraceContext;

/**
 * A light defined by its samples: implement {@link #sample} (and {@link #sampleCount} for more than
 * one) and the framework's {@link #getIntensity} comes for free, as the unshadowed samples added up
 * (each shadow-tested through {@link Scene#occluded(IntersectionRecord, LightSample)} unless the sample
 * says it already is). The built-in lights are sampled lights; so is a new one, which then copies
 * nothing.
 *
 * <pre>
 * public class Sun extends SampledLight {
 *     public Vector3d direction = new Vector3d(0, 1, 0), intensity = new Vector3d(1, 1, 1);
 *     public boolean sample(IntersectionRecord rec, Scene scene, int index, LightSample out) {
 *         out.setAtInfinity(...);         // the unit vector toward the sun
 *         out.intensity.set(intensity);
 *         out.shadowTested = false;
 *         return true;
 *     }
 *     public int shadowRaysPerPoint() { return 1; }   // for the render plan
 * }
 * </pre>
 */
public abstract class SampledLight extends Light {

    @Override
    public abstract boolean sample(IntersectionRecord record, Scene scene, int index, LightSample out);

    /**
     * The light arriving at {@code record.location}: the sum of the samples that reach it (the framework's
     * form, for a user's material; it draws random choices from the calling thread's pixel sample).
     */
    @Override
    public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
        TraceContext ctx = TraceContext.current(scene);
        LightSample s = new LightSample(ctx.sample);
        Vector3d result = new Vector3d();
        for (int k = 0, count = sampleCount(); k < count; k++) {
            if (sample(record, scene, k, s) && (s.shadowTested || !scene.occluded(record, s, ctx))) {
                result.add(s.intensity);
            }
        }
        return result;
    }
}
