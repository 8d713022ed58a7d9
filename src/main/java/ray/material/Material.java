package ray.material;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Overrides;
import ray.Ray;
import ray.Scene;
import ray.SceneObject;
import ray.TraceContext;

/**
 * How a surface reflects light. The framework's contract is {@link #shade}: the colour leaving
 * {@code record.location} back along {@code ray}.
 *
 * <p>The renderer calls the allocation-free {@link #shade(Ray, IntersectionRecord, Scene,
 * TraceContext, Vector3d)}; its default calls {@link #shade(Ray, IntersectionRecord, Scene)}, so a
 * material written against the framework works unchanged. Built-in materials implement the fast form
 * and let the framework form call it; the renderer calls {@link #shadeHit}, which takes the fast form
 * unless a subclass overrides the framework form below it (a student's {@code MyDiffuse extends Diffuse}
 * overriding only {@code shade(ray, record, scene)} is shaded by its override). A framework-form {@code shade} that returns null or a NaN colour stops
 * the render with a {@link BadColorException} naming the class and the pixel.
 */
public abstract class Material implements SceneObject {

    private static final Class<?>[] FRAMEWORK = {Ray.class, IntersectionRecord.class, Scene.class};
    private static final Class<?>[] FAST = {Ray.class, IntersectionRecord.class, Scene.class, TraceContext.class, Vector3d.class};

    /**
     * True for a class whose framework {@code shade} is declared below its fast form (a student's
     * {@code MyDiffuse extends Diffuse} overriding only {@code shade(ray, record, scene)}): the renderer
     * then calls the framework form, and the plan believes only declarations made at or below it.
     */
    private static final ClassValue<Boolean> FRAMEWORK_SHADE = Overrides.declaredBelow("shade", FRAMEWORK, "shade", FAST);
    private static final ClassValue<Boolean> TRUSTED_TERMS = Overrides.trusted(FRAMEWORK_SHADE, "shade", FRAMEWORK, "terms");
    private static final ClassValue<Boolean> TRUSTED_COST = Overrides.trusted(FRAMEWORK_SHADE, "shade", FRAMEWORK,
            "hitCost", ShadingPlan.class);

    private final boolean frameworkShade = FRAMEWORK_SHADE.get(getClass());

    public abstract Vector3d shade(Ray ray, IntersectionRecord record, Scene scene);

    /**
     * Writes the colour leaving {@code record.location} back along {@code ray} into {@code out}, using
     * only {@code ctx}'s scratch objects. {@code record} belongs to the caller and must not be kept.
     */
    public void shade(Ray ray, IntersectionRecord record, Scene scene, TraceContext ctx, Vector3d out) {
        shadeFramework(ray, record, scene, ctx, out);
    }

    /**
     * What the renderer calls for a hit: the fast form {@link #shade(Ray, IntersectionRecord, Scene,
     * TraceContext, Vector3d)}, unless this object's class overrides the framework form below the class
     * that wrote the fast one (then the framework form, so a student's override of a built-in is used).
     */
    public final void shadeHit(Ray ray, IntersectionRecord record, Scene scene, TraceContext ctx, Vector3d out) {
        if (frameworkShade) {
            shadeFramework(ray, record, scene, ctx, out);
        } else {
            shade(ray, record, scene, ctx, out);
        }
    }

    /** True when this object's class overrides the framework {@code shade} below its fast form (see {@link #shadeHit}). */
    public final boolean usesFrameworkShade() {
        return frameworkShade;
    }

    /**
     * {@link #terms()} as the render plan reads it: every term when the class overrides the framework
     * {@code shade} below the class that declared its terms (an inherited declaration does not describe
     * a {@code shade} written after it).
     */
    public final Set<Term> plannedTerms() {
        return TRUSTED_TERMS.get(getClass()) ? terms() : EnumSet.allOf(Term.class);
    }

    /** {@link #hitCost} as the render plan reads it, with the same rule as {@link #plannedTerms()}. */
    public final HitCost plannedCost(ShadingPlan plan) {
        return TRUSTED_COST.get(getClass()) ? hitCost(plan) : HitCost.of(plannedTerms());
    }

    private void shadeFramework(Ray ray, IntersectionRecord record, Scene scene, TraceContext ctx, Vector3d out) {
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
     * The terms this material's shading has, its parts' included, for the render plan (read once per
     * render, before the first ray), the way pbrt-v4's {@code BxDFFlags} name a BSDF's lobes. Declare only
     * terms that can be non-zero for this object's field values. A subclass inherits the declaration it
     * does not change (override this when your {@code shade} does something the class above does not).
     * The default, for a class that declares nothing: every term, rays of its own included, so the plan
     * assumes it needs everything.
     */
    public Set<Term> terms() {
        return EnumSet.allOf(Term.class);
    }

    /**
     * The materials this one shades through (a composite's parts, as {@code Surface.operands()} lists a
     * CSG's): the plan hands itself to them too. Glazed: its base. The default: none.
     */
    public List<Material> parts() {
        return List.of();
    }

    /**
     * What one hit on this material casts under {@code plan}'s exact skips, its parts' rays included. The
     * default reads {@link #terms()}: one mirror ray for {@link Term#MIRROR}, one refraction ray for
     * {@link Term#REFRACTION}, the lights evaluated for a direct term (and for rays of its own). A
     * composite that folds work (Glazed folds a chain of Glazed bases into one mirror ray) says so here.
     */
    public HitCost hitCost(ShadingPlan plan) {
        return HitCost.of(terms());
    }

    /**
     * True when this material needs a closed surface, one with an inside (it refracts): a surface that
     * can be open (a mesh) refuses it unless closed. The default: false.
     */
    public boolean needsInside() {
        return false;
    }

    /**
     * Called once per render after the plan is derived and before the first ray: a built-in material
     * caches what the plan lets it skip. The default does nothing.
     */
    public void planned(ShadingPlan plan) {
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
