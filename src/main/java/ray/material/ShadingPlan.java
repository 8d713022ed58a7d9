package ray.material;

import ray.Scene;
import ray.light.Light;

/**
 * What the render plan tells a material once per render, before the first ray ({@link Material#planned}):
 * the lights a direct term evaluates and which exact skips to make. The plan ({@code ray.plan.RenderPlan})
 * is one; a material needs nothing else of it.
 */
public interface ShadingPlan {

    /**
     * With faint paths cut ({@link #cutsFaintPaths()}), a mirror ray is not cast where the product of the
     * mirror coefficients along its path is below this: half an 8-bit step for radiance up to 1.
     */
    double FAINT = 0.5 / 255;

    /** The scene being rendered. */
    Scene scene();

    /** The lights a direct term evaluates (dark ones left out when the plan skips them). */
    Light[] lights();

    /** True when a material with no direct term (k_d = k_s = 0) evaluates no light. */
    boolean skipsLightsWithoutDirectTerm();

    /** True when a mirror coefficient of 0 casts no mirror ray. */
    boolean skipsZeroMirrors();

    /** True when a chain of Glazed materials casts one mirror ray for the whole chain. */
    boolean foldsGlazedChains();

    /** True when mirror paths fainter than {@link #FAINT} are cut (inexact, opt-in). */
    boolean cutsFaintPaths();
}
