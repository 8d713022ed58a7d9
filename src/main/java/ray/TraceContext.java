package ray;

import javax.vecmath.Vector3d;
import ray.light.LightSample;

/**
 * One render thread's scratch objects: a ray, a hit record and a colour per recursion depth, the
 * shadow ray, the light sample, the ray counters and a slot for the accelerator's own scratch. Everything the hot path
 * needs is here, so tracing a ray allocates nothing. Never shared between threads.
 */
public final class TraceContext {

    private static final ThreadLocal<TraceContext> CURRENT = new ThreadLocal<>();

    private Ray[] rays = new Ray[0];
    private IntersectionRecord[] records = new IntersectionRecord[0];
    private Vector3d[] colors = new Vector3d[0];

    public final Ray shadowRay = new Ray();
    /** The pixel sample being traced: light and effect code draws its sampler dimensions here (no allocation). */
    public final PixelSample sample = new PixelSample();
    /** The light sample materials fill, drawing its random choices from {@link #sample}. */
    public final LightSample lightSample = new LightSample(sample);
    /** Scratch for a material's reflectance at the hit being shaded (a texture's value), read within its light loop. */
    public final Vector3d reflectance = new Vector3d();
    public final RayStats stats = new RayStats();
    /** Rays cast together (a block of camera rays, {@link Scene#castCameras}): empty until a render reserves it. */
    public final RayPacket packet = new RayPacket();
    /**
     * The scene accelerator's own per-thread scratch (for the BVH its {@code RayQuery}: traversal stack,
     * per-ray set-up); made and used by the accelerator only.
     */
    public Object acceleratorScratch;
    /**
     * While framework-style material code runs, the depth of the rays it traces with {@link Scene#trace(Ray)}:
     * one more than the ray it is shading (0 outside such code). Bounds user recursion by MaxDepth and keeps
     * a nested trace off the records still in use.
     */
    public int level;
    /**
     * The product of the mirror coefficients along the path being traced (1 for a camera ray); read
     * only when the plan cuts faint mirror paths (an inexact, opt-in skip: {@code --cut-faint}).
     */
    public double pathWeight = 1;

    /**
     * The render's MaxDepth: the ray-query layer casts no secondary ray deeper than this. Fixed by the
     * render that made the context (its resolved settings); a context made by {@link #current} for code
     * outside a render follows the scene's own global.
     */
    public int maxDepth;
    /** Made by {@link #current}, outside any render: {@link #maxDepth} follows the scene asked about. */
    private boolean followsScene;

    public TraceContext(int maxDepth) {
        this.maxDepth = maxDepth;
        grow(maxDepth + 2);
    }

    /** The calling thread's context, made on first use (for code that calls the framework API directly). */
    public static TraceContext current(Scene scene) {
        TraceContext c = CURRENT.get();
        if (c == null) {
            c = new TraceContext(scene.maxDepth);
            c.followsScene = true;
            CURRENT.set(c);
        } else if (c.followsScene) {
            c.maxDepth = scene.maxDepth;
        }
        return c;
    }

    /** Makes {@code c} the calling thread's context (render workers do this once). */
    public static void bind(TraceContext c) {
        CURRENT.set(c);
    }

    public Ray ray(int depth) {
        if (depth >= rays.length) {
            grow(depth + 2);
        }
        return rays[depth];
    }

    public IntersectionRecord record(int depth) {
        if (depth >= records.length) {
            grow(depth + 2);
        }
        return records[depth];
    }

    public Vector3d color(int depth) {
        if (depth >= colors.length) {
            grow(depth + 2);
        }
        return colors[depth];
    }

    private void grow(int n) {
        int old = rays.length;
        rays = java.util.Arrays.copyOf(rays, n);
        records = java.util.Arrays.copyOf(records, n);
        colors = java.util.Arrays.copyOf(colors, n);
        for (int i = old; i < n; i++) {
            rays[i] = new Ray();
            records[i] = new IntersectionRecord();
            colors[i] = new Vector3d();
        }
    }
}
