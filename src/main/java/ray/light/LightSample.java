package ray.light;

import javax.vecmath.Vector3d;
import ray.PixelSample;

/**
 * Light arriving at a shading point from one point of a light: where from, how far, and how much
 * (before any shadow test, unless {@link #shadowTested}). Materials read samples and never test light
 * types; a point light gives one sample, an area light many, a directional light one from infinitely
 * far ({@link #setAtInfinity}: the shadow ray then runs to infinity along {@link #direction}).
 *
 * <p>A light drawing random numbers (an area light's point) takes them from {@link #pixel}, the sample
 * being traced: handed in with the sample, never looked up on the thread.
 */
public final class LightSample {
    /** Unit vector from the shading point toward the light. */
    public final Vector3d direction = new Vector3d();
    /** The point on the light a shadow ray is aimed at (unused for a sample at infinity). */
    public final Vector3d position = new Vector3d();
    /** Distance to {@link #position}; {@link Double#POSITIVE_INFINITY} for a light infinitely far away. */
    public double distance;
    /** The pixel sample being traced: the sampler dimensions a light draws its random choices from. */
    public final PixelSample pixel;

    /** A sample whose random choices are the centre of everything (outside a render). */
    public LightSample() {
        this(new PixelSample());
    }

    /** A sample drawing its random choices from {@code pixel} (a render thread's {@code TraceContext.sample}). */
    public LightSample(PixelSample pixel) {
        this.pixel = pixel;
    }

    /**
     * Light from infinitely far along the unit vector {@code (dx, dy, dz)} (a sun, a directional light):
     * the shadow ray {@code Scene.occluded} casts runs to infinity that way.
     */
    public void setAtInfinity(double dx, double dy, double dz) {
        direction.set(dx, dy, dz);
        distance = Double.POSITIVE_INFINITY;
    }

    /** True when the light is infinitely far ({@link #setAtInfinity}). */
    public boolean atInfinity() {
        return distance == Double.POSITIVE_INFINITY;
    }
    /** Irradiance-like amount arriving (for a point light I / r^2), unshadowed. */
    public final Vector3d intensity = new Vector3d();
    /** True when {@link #intensity} already accounts for shadows (no shadow ray needed). */
    public boolean shadowTested;
}
