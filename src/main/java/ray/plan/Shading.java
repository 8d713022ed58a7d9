package ray.plan;

import java.util.EnumSet;
import java.util.Set;
import ray.material.HitCost;
import ray.material.Material;
import ray.material.Term;

/**
 * What shading one hit on a material does under a plan's skips, as the material declares it
 * ({@link Material#hitCost}): its terms, the mirror and refraction rays it casts, whether it evaluates
 * the lights, and whether it runs code the plan cannot see. Read once per material per render; nothing
 * here runs per sample.
 */
final class Shading {
    final Set<Term> terms;
    /** Mirror and refraction rays cast per hit (Glazed levels not folded add one each). */
    final int mirror, refraction;
    /** Evaluates the lights (and so may cast shadow rays). */
    final boolean direct;
    /** Runs a user's code the plan knows nothing about (may trace any rays). */
    final boolean unknown;
    /** Levels of a chain folded into one mirror ray (1 where nothing was folded). */
    final int folded;
    /**
     * The most a secondary ray's colour is weighted by here (sum of |k_m| of a Glazed chain), or
     * infinity where secondary rays are not weighted that way (refraction, user code); 0 without any.
     */
    final double weight;

    private Shading(HitCost c) {
        this.terms = c.terms();
        this.mirror = c.mirrorRays();
        this.refraction = c.refractionRays();
        this.direct = c.evaluatesLights();
        this.unknown = c.unknown();
        this.folded = c.foldedLevels();
        this.weight = c.weight();
    }

    private static final Shading NONE = new Shading(HitCost.of(EnumSet.noneOf(Term.class)));

    static Shading of(Material m, RenderPlan plan) {
        return m == null ? NONE : new Shading(m.plannedCost(plan));
    }
}
