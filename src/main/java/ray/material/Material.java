package ray.material;

import java.util.EnumSet;
import java.util.Set;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.SceneObject;
import ray.TraceContext;
import ray.plan.RenderPlan;
import ray.plan.Term;

/**
 * How a surface reflects light. The framework's contract is {@link #shade}: the colour leaving
 * {@code record.location} back along {@code ray}.
 *
 * <p>The renderer calls the allocation-free {@link #shade(Ray, IntersectionRecord, Scene,
 * TraceContext, Vector3d)}; its default calls {@link #shade(Ray, IntersectionRecord, Scene)}, so a
 * material written against the framework works unchanged. Built-in materials implement the fast form
 * and let the framework form call it. A framework-form {@code shade} that returns null or a NaN colour stops
 * the render with a {@link BadColorException} naming the class and the pixel.
 */
public abstract class Material implements SceneObject {

    public abstract Vector3d shade(Ray ray, IntersectionRecord record, Scene scene);

    /**
     * Writes the colour leaving {@code record.location} back along {@code ray} into {@code out}, using
     * only {@code ctx}'s scratch objects. {@code record} belongs to the caller and must not be kept.
     */
    public void shade(Ray ray, IntersectionRecord record, Scene scene, TraceContext ctx, Vector3d out) {
        // a ray this code traces (scene.trace) is one bounce deeper than the ray being shaded, so it
        // gets the next depth's record and never the one passed in here
        int saved = ctx.level;
        ctx.level = Math.max(ctx.level, ray.depth) + 1;
        try {
            Vector3d c = shade(ray, record, scene);
            // the one check of a user's colour (built-in materials override this method and never pass here):
            // null or NaN stops the render with the class, the method and the pixel, not a silently black pixel
            if (c == null || Double.isNaN(c.x) || Double.isNaN(c.y) || Double.isNaN(c.z)) {
                throw new BadColorException(this, c, ctx.sample.x(), ctx.sample.y());
            }
            out.set(c);
        } finally {
            ctx.level = saved;
        }
    }

    /**
     * The terms this material's shading has, for the render plan (read once per render, before the
     * first ray). Declare only terms that can be non-zero for this object's field values. The default,
     * for a user's class the plan knows nothing about: every term, rays of its own included.
     */
    public Set<Term> terms() {
        return EnumSet.allOf(Term.class);
    }

    /**
     * Called once per render after the plan is derived and before the first ray: a built-in material
     * caches what the plan lets it skip. The default does nothing.
     */
    public void planned(RenderPlan plan) {
    }

    /** Framework form of the fast path, for built-in materials: runs it on this thread's context. */
    protected final Vector3d shadeWithContext(Ray ray, IntersectionRecord record, Scene scene) {
        Vector3d out = new Vector3d();
        TraceContext ctx = TraceContext.current(scene);
        IntersectionRecord copy = new IntersectionRecord();
        copy.set(record);
        shade(ray, copy, scene, ctx, out);
        return out;
    }

    static void requireColor(String name, Vector3d c) {
        if (!Double.isFinite(c.x) || !Double.isFinite(c.y) || !Double.isFinite(c.z)) {
            throw new IllegalArgumentException(name + " must be finite numbers, got " + c);
        }
    }
}
