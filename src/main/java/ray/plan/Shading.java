package ray.plan;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import ray.material.Diffuse;
import ray.material.GlazedMaterial;
import ray.material.Material;

/**
 * What shading one hit on a material does under a set of skips: its terms, the mirror and refraction
 * rays it casts, whether it evaluates the lights, and whether it runs code the plan cannot see.
 * Read once per material per render; nothing here runs per sample.
 */
final class Shading {
    final Set<Term> terms;
    /** Mirror and refraction rays cast per hit (Glazed levels not folded add one each). */
    final int mirror, refraction;
    /** Evaluates the lights (and so may cast shadow rays). */
    final boolean direct;
    /** Runs a user's code the plan knows nothing about (may trace any rays). */
    final boolean unknown;
    /** A Glazed material whose chain ends without a base: only the mirror term. */
    final boolean pureMirror;
    /** Levels of a Glazed chain folded into one mirror ray (1 where nothing was folded). */
    final int folded;
    /**
     * The most a secondary ray's colour is weighted by here (sum of |k_m| of a Glazed chain), or
     * infinity where secondary rays are not weighted that way (refraction, user code); 0 without any.
     */
    double weight;

    private Shading(Set<Term> terms, int mirror, int refraction, boolean direct, boolean unknown, boolean pureMirror, int folded) {
        this.terms = terms;
        this.mirror = mirror;
        this.refraction = refraction;
        this.direct = direct;
        this.unknown = unknown;
        this.pureMirror = pureMirror;
        this.folded = folded;
    }

    private static final Shading NONE = new Shading(EnumSet.noneOf(Term.class), 0, 0, false, false, false, 1);

    static Shading of(Material m, Set<Skip> skips) {
        if (m == null) {
            return NONE;
        }
        if (!Trust.material(m)) {
            Shading unknown = new Shading(EnumSet.allOf(Term.class), 1, 1, true, true, false, 1);
            unknown.weight = Double.POSITIVE_INFINITY;
            return unknown;
        }
        Set<Term> terms = m.terms();
        if (m instanceof GlazedMaterial g) {
            List<GlazedMaterial> levels = skips.contains(Skip.FOLD_GLAZED) ? g.chain() : List.of(g);
            int rays = 0;
            for (GlazedMaterial level : levels) {
                if (level.mirrorCoefficient != 0 || !skips.contains(Skip.ZERO_MIRROR)) {
                    rays++;
                }
            }
            Material bottom = levels.get(levels.size() - 1).base;
            Shading base = of(bottom, skips);
            int own = skips.contains(Skip.FOLD_GLAZED) ? Math.min(rays, 1) : rays;
            double k = 0;
            for (GlazedMaterial level : levels) {
                k += Math.abs(level.mirrorCoefficient);
            }
            Shading glazed = new Shading(terms, own + base.mirror, base.refraction, base.direct, base.unknown,
                    bottom == null, levels.size());
            glazed.weight = base.mirror + base.refraction > 0 || base.unknown ? Double.POSITIVE_INFINITY : k;
            return glazed;
        }
        boolean direct = Term.direct(terms) || m instanceof Diffuse && !skips.contains(Skip.NO_DIRECT_TERM);
        Shading other = new Shading(terms, terms.contains(Term.MIRROR) ? 1 : 0, terms.contains(Term.REFRACTION) ? 1 : 0,
                direct, terms.contains(Term.OWN_RAYS), false, 1);
        other.weight = other.mirror + other.refraction > 0 || other.unknown ? Double.POSITIVE_INFINITY : 0;
        return other;
    }
}
