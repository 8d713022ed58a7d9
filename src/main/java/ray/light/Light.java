package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;
import ray.SceneObject;

/**
 * A light source. The framework's contract is {@link #getIntensity}: the light arriving at a hit
 * point, zero where something lies between. Renderers call {@link #sample} instead, which also says
 * where the light comes from, so a material can skip the shadow ray when the light is behind the
 * surface.
 *
 * <p>A subclass that only implements {@code getIntensity} still works: its light is taken to arrive
 * along the surface normal (full strength for a diffuse surface), already shadowed by
 * {@code getIntensity} itself.
 */
public abstract class Light implements SceneObject {

    /** The light arriving at {@code record.location}, zero where a surface lies between (shadow). */
    public abstract Vector3d getIntensity(IntersectionRecord record, Scene scene);

    /** How many samples {@link #sample} gives per shading point (1 for a point light). */
    public int sampleCount() {
        return 1;
    }

    /**
     * Fills {@code out} with sample {@code index} of this light as seen from {@code record}; returns
     * false when nothing arrives from it (then {@code out} is undefined).
     */
    public boolean sample(IntersectionRecord record, Scene scene, int index, LightSample out) {
        Vector3d i = getIntensity(record, scene);
        if (i == null || !(i.x > 0 || i.y > 0 || i.z > 0)) {
            return false;
        }
        out.intensity.set(i);
        out.direction.set(record.normal);
        out.distance = Double.POSITIVE_INFINITY;
        out.position.set(record.location);
        out.shadowTested = true;
        return true;
    }

    /**
     * For the render plan: true when this light adds nothing anywhere (zero intensity), so the plan
     * skips it (no evaluation, no shadow ray). The default: false.
     */
    public boolean isDark() {
        return false;
    }

    /**
     * For the render plan: the most shadow rays one shading point can cost for this light (through
     * {@code Scene.occluded}), or {@link #UNKNOWN_RAYS} (the default, a user's light whose
     * {@code getIntensity} may trace anything).
     */
    public int shadowRaysPerPoint() {
        return UNKNOWN_RAYS;
    }

    /** What {@link #shadowRaysPerPoint()} returns when the light cannot say. */
    public static final int UNKNOWN_RAYS = -1;
}
