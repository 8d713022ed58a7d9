package ray.plan;

/**
 * The exact skips the render plan makes: each leaves the image bit for bit the same (tests render
 * with and without each one). All are on by default; {@link RenderPlan#NO_SKIPS} turns them off, for
 * tests and for the "without the plan" line of {@code --plan}.
 */
public enum Skip {
    /** A light of zero intensity is not evaluated (no sample, no shadow ray). */
    DARK_LIGHTS("dark lights skipped"),
    /** A material with no direct term (k_d = k_s = 0) evaluates no light and casts no shadow ray. */
    NO_DIRECT_TERM("no light evaluation where there is no direct term"),
    /** A mirror coefficient of 0 casts no mirror ray. */
    ZERO_MIRROR("no mirror ray where k_m = 0"),
    /** A Glazed material whose base is a Glazed material casts one mirror ray for the whole chain. */
    FOLD_GLAZED("nested Glazed chains folded");

    private final String label;

    Skip(String label) {
        this.label = label;
    }

    public String label() {
        return label;
    }
}
