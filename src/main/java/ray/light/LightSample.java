package ray.light;

import javax.vecmath.Vector3d;

/**
 * Light arriving at a shading point from one point of a light: where from, how far, and how much
 * (before any shadow test, unless {@link #shadowTested}). Materials read samples and never test light
 * types; a point light gives one sample, an area light would give many.
 */
public final class LightSample {
    /** Unit vector from the shading point toward the light. */
    public final Vector3d direction = new Vector3d();
    /** The point on the light a shadow ray is aimed at. */
    public final Vector3d position = new Vector3d();
    /** Distance to {@link #position}. */
    public double distance;
    /** Irradiance-like amount arriving (for a point light I / r^2), unshadowed. */
    public final Vector3d intensity = new Vector3d();
    /** True when {@link #intensity} already accounts for shadows (no shadow ray needed). */
    public boolean shadowTested;
}
