package ray.material;

import java.util.Set;

/**
 * What one hit on a material does, as the render plan counts it ({@link Material#hitCost}): its terms
 * (its parts' included), the mirror and refraction rays it casts, whether it evaluates the lights (and
 * so may cast shadow rays), the most a secondary ray's colour is weighted by, and how many levels of a
 * chain it folds into one ray.
 *
 * @param terms          the terms of its shading, its parts' included
 * @param mirrorRays     mirror rays cast per hit
 * @param refractionRays refraction rays cast per hit
 * @param evaluatesLights true when it evaluates the lights (and may cast shadow rays)
 * @param weight         the most a secondary ray's colour is weighted by here (the sum of |k_m| of a
 *                       mirror chain), infinity where not weighted that way (refraction, user code), 0
 *                       without secondary rays
 * @param foldedLevels   levels of a chain folded into one mirror ray (1 where nothing was folded)
 */
public record HitCost(Set<Term> terms, int mirrorRays, int refractionRays, boolean evaluatesLights, double weight, int foldedLevels) {

    /** True when the material runs code the plan cannot see (it traces its own rays, any number). */
    public boolean unknown() {
        return terms.contains(Term.OWN_RAYS);
    }

    /** The cost a material's declared {@code terms} alone give: one ray per MIRROR and REFRACTION term. */
    public static HitCost of(Set<Term> terms) {
        int mirror = terms.contains(Term.MIRROR) ? 1 : 0, refraction = terms.contains(Term.REFRACTION) ? 1 : 0;
        boolean own = terms.contains(Term.OWN_RAYS);
        return new HitCost(terms, mirror, refraction, Term.direct(terms) || own, mirror + refraction > 0 || own ? Double.POSITIVE_INFINITY : 0, 1);
    }
}
