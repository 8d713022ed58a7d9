package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Overrides;
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

    private static final Class<?>[] FRAMEWORK = {IntersectionRecord.class, Scene.class};

    /**
     * True for a class whose {@code getIntensity} is declared below its {@code sample} (a student's
     * {@code MyLight extends PointLight} overriding only {@code getIntensity}): the renderer then samples
     * through {@code getIntensity}, and the plan believes only declarations made at or below it.
     */
    private static final ClassValue<Boolean> FRAMEWORK_INTENSITY = Overrides.declaredBelow("getIntensity", FRAMEWORK,
            "sample", IntersectionRecord.class, Scene.class, int.class, LightSample.class);
    private static final ClassValue<Boolean> TRUSTED_DARK = trusted("isDark");
    private static final ClassValue<Boolean> TRUSTED_RAYS = trusted("shadowRaysPerPoint");

    private static ClassValue<Boolean> trusted(String declaration) {
        return Overrides.trusted(FRAMEWORK_INTENSITY, "getIntensity", FRAMEWORK, declaration);
    }

    private final boolean frameworkIntensity = FRAMEWORK_INTENSITY.get(getClass());

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
        return sampleFramework(record, scene, out);
    }

    /**
     * How many samples the renderer draws per shading point: {@link #sampleCount()}, or 1 when this
     * object's class overrides {@code getIntensity} below its {@code sample} (see {@link #renderSample}).
     */
    public final int renderSampleCount() {
        return frameworkIntensity ? 1 : sampleCount();
    }

    /**
     * What the renderer calls: {@link #sample}, unless this object's class overrides the framework's
     * {@code getIntensity} below the class that wrote {@code sample} (then the light arrives through
     * {@code getIntensity}, as for a light that implements only it).
     */
    public final boolean renderSample(IntersectionRecord record, Scene scene, int index, LightSample out) {
        return frameworkIntensity ? sampleFramework(record, scene, out) : sample(record, scene, index, out);
    }

    /** True when this object's class overrides {@code getIntensity} below its {@code sample} (see {@link #renderSample}). */
    public final boolean usesFrameworkIntensity() {
        return frameworkIntensity;
    }

    /** {@link #isDark()} as the render plan reads it: false when the class overrides {@code getIntensity} below the class that declared it. */
    public final boolean plannedDark() {
        return TRUSTED_DARK.get(getClass()) && isDark();
    }

    /** {@link #shadowRaysPerPoint()} as the render plan reads it: unknown under the same rule as {@link #plannedDark()}. */
    public final int plannedShadowRays() {
        return TRUSTED_RAYS.get(getClass()) ? shadowRaysPerPoint() : UNKNOWN_RAYS;
    }

    private boolean sampleFramework(IntersectionRecord record, Scene scene, LightSample out) {
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
