package ray.material;

/**
 * A term of a material's shading, as the material declares it to the render plan
 * ({@link Material#terms()}), the way pbrt-v4's {@code BxDFFlags} and Mitsuba 3's
 * {@code BSDFFlags} name a BSDF's lobes. The plan reads the declarations once per render and casts
 * only what they allow.
 */
public enum Term {
    /** {@code k_a I_a}: no rays. */
    AMBIENT,
    /** Direct diffuse light: one light evaluation (and its shadow rays) per light sample. */
    DIFFUSE,
    /** Direct specular highlight: evaluated with the diffuse term, same shadow rays. */
    HIGHLIGHT,
    /** Ideal mirror reflection: at most one mirror ray per hit. */
    MIRROR,
    /** Refraction: at most one refraction ray per hit. */
    REFRACTION,
    /** Rays the material traces itself through {@code Scene.trace} (counted as {@code user}); how many is unknown. */
    OWN_RAYS;

    /** True when {@code terms} has a direct-light term, so the material may cast shadow rays. */
    public static boolean direct(java.util.Set<Term> terms) {
        return terms.contains(DIFFUSE) || terms.contains(HIGHLIGHT);
    }
}
