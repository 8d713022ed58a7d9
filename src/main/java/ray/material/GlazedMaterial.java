package ray.material;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;

/**
 * A glazed surface: a base material plus an ideal mirror reflection,
 * {@code L = L_base + k_m L_mirror} ({@code L_base} = 0 without a base). The mirror ray is followed
 * while the incoming ray's depth is below the scene's {@code MaxDepth}; past that it adds nothing.
 * {@code Glazed} in a scene file names this class too.
 *
 * <pre>
 * Material GlazedMaterial mirror
 * ref base shiny               # optional base material
 * double mirrorCoefficient 0.8 # k_m, default 0.5
 * </pre>
 */
public class GlazedMaterial extends Material {

    public Material base;
    public double mirrorCoefficient = 0.5;

    /** Longest chain of Glazed materials, each the base of the next (each level is a nested call). */
    public static final int MAX_CHAIN = 100;

    @Override
    public void init() {
        if (!Double.isFinite(mirrorCoefficient)) {
            throw new IllegalArgumentException("mirrorCoefficient must be a finite number, got " + mirrorCoefficient);
        }
        if (base == this) {
            throw new IllegalArgumentException("a glazed material cannot be its own base");
        }
        // each level of a chain of Glazed bases is a nested call (shading, the plan): bounded here, with
        // its cause named, rather than a StackOverflowError later
        int levels = 1;
        for (Material m = base; m instanceof GlazedMaterial g && levels <= MAX_CHAIN; m = g.base) {
            levels++;
        }
        if (levels > MAX_CHAIN) {
            throw new IllegalArgumentException("a chain of more than " + MAX_CHAIN
                    + " Glazed materials, each the base of the next (expected a shorter chain: the coefficients of a chain "
                    + "multiply, so one Glazed with their sum reflects the same)");
        }
    }

    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        return shadeWithContext(ray, record, scene);
    }

    /** The base's terms and, where this level reflects, the mirror term. */
    @Override
    public Set<Term> terms() {
        Set<Term> t = EnumSet.noneOf(Term.class);
        if (base != null) {
            t.addAll(base.plannedTerms());
        }
        if (mirrorCoefficient != 0) {
            t.add(Term.MIRROR);
        }
        return t;
    }

    /** The base, which this material shades through. */
    @Override
    public List<Material> parts() {
        return base == null ? List.of() : List.of(base);
    }

    /**
     * One mirror ray per level of the chain (one for the whole chain when the plan folds it, none for a
     * level with k_m = 0 when the plan skips those), plus what the base at the bottom casts; the mirror
     * ray's weight is the sum of the levels' |k_m| where the base casts no secondary ray itself.
     */
    @Override
    public HitCost hitCost(ShadingPlan plan) {
        List<GlazedMaterial> levels = plan.foldsGlazedChains() ? chain() : List.of(this);
        int rays = 0;
        double k = 0;
        for (GlazedMaterial level : levels) {
            if (level.mirrorCoefficient != 0 || !plan.skipsZeroMirrors()) {
                rays++;
            }
            k += Math.abs(level.mirrorCoefficient);
        }
        Material bottom = levels.get(levels.size() - 1).base;
        HitCost b = bottom == null ? HitCost.of(EnumSet.noneOf(Term.class)) : bottom.plannedCost(plan);
        int own = plan.foldsGlazedChains() ? Math.min(rays, 1) : rays;
        double weight = b.mirrorRays() + b.refractionRays() > 0 || b.unknown() ? Double.POSITIVE_INFINITY : k;
        return new HitCost(terms(), own + b.mirrorRays(), b.refractionRays(), b.evaluatesLights(), weight, levels.size());
    }

    /**
     * The Glazed materials from this one down its chain of bases that are plain GlazedMaterials
     * (outermost first; a subclass, which may shade its own way, ends the chain, as does a loop).
     */
    public List<GlazedMaterial> chain() {
        List<GlazedMaterial> levels = new ArrayList<>();
        for (GlazedMaterial g = this; g != null && !levels.contains(g);
                g = g.base != null && g.base.getClass() == GlazedMaterial.class ? (GlazedMaterial) g.base : null) {
            levels.add(g);
        }
        return levels;
    }

    /**
     * Folds the chain of Glazed bases: each level's shade would add k_i times the same mirror ray's
     * colour (same point, same direction, same depth) after its base's value, so one ray and the
     * coefficients added in that order (innermost first) give the unfolded sums bit for bit.
     */
    @Override
    public void planned(ShadingPlan plan) {
        List<GlazedMaterial> levels = plan.foldsGlazedChains() ? chain() : List.of(this);
        boolean skipZero = plan.skipsZeroMirrors();
        double[] ks = new double[levels.size()];
        int n = 0;
        for (int i = levels.size() - 1; i >= 0; i--) {
            double k = levels.get(i).mirrorCoefficient;
            if (k != 0 || !skipZero) {
                ks[n++] = k;
            }
        }
        coefficients = java.util.Arrays.copyOf(ks, n);
        weight = 0;
        for (double k : coefficients) {
            weight += Math.abs(k);
        }
        cutFaint = plan.cutsFaintPaths();
        foldedBase = levels.get(levels.size() - 1).base;
        plannedFor = plan.scene();
    }

    /** The scene {@link #planned} last ran for, the base at the bottom of the folded chain and its coefficients. */
    private Scene plannedFor;
    private Material foldedBase;
    private double[] coefficients;
    /** With the plan's (inexact) cut of faint paths: the sum of |k| over the folded levels, the mirror ray's weight. */
    private boolean cutFaint;
    private double weight;

    @Override
    public void shade(Ray ray, IntersectionRecord rec, Scene scene, TraceContext ctx, Vector3d out) {
        boolean planned = plannedFor == scene;
        Material b = planned ? foldedBase : base;
        int mirrors = planned ? coefficients.length : mirrorCoefficient == 0 ? 0 : 1;
        if (b != null) {
            b.shadeHit(ray, rec, scene, ctx, out);
        } else {
            out.set(0, 0, 0);
        }
        if (mirrors == 0) {
            return;
        }
        Vector3d c;
        if (planned && cutFaint) {   // opt-in, inexact: no ray where the path can no longer move a pixel much
            double before = ctx.pathWeight, w = before * weight;
            if (w < ShadingPlan.FAINT) {
                return;
            }
            ctx.pathWeight = w;
            c = scene.traceMirror(ray, rec, ctx);
            ctx.pathWeight = before;
        } else {
            c = scene.traceMirror(ray, rec, ctx);   // null past MaxDepth: adds nothing
        }
        if (c == null) {
            return;
        }
        for (int i = 0; i < mirrors; i++) {   // innermost level first, as the unfolded shades add them
            double k = planned ? coefficients[i] : mirrorCoefficient;
            out.x += k * c.x;
            out.y += k * c.y;
            out.z += k * c.z;
        }
    }

    @Override
    public String toString() {
        return "GlazedMaterial[base " + base + ", mirrorCoefficient " + mirrorCoefficient + "]";
    }
}
