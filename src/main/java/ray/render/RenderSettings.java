package ray.render;

import ray.Scene;
import ray.parse.Limits;

/**
 * How to sample a render, overriding the scene's globals where set: the sampler ({@code Sampler}),
 * n_s ({@code AASamples}), the adaptive target error ({@code TargetError}, in 8-bit steps) and
 * {@code MaxDepth}; and whether to deliver the image in passes. Unset values (the defaults of a new
 * object) come from the scene. Pass to {@link Renderer#settings}.
 *
 * <pre>
 * RenderSettings s = new RenderSettings().sampler("adaptive").samples(4).targetError(0.5);
 * Renderer r = new Renderer(scene).settings(s);
 * Image linear = r.render();
 * RenderSummary what = r.summary();    // time, rays by kind, mean spp, estimated RMSE
 * </pre>
 */
public final class RenderSettings {

    private String sampler;
    private int samples;
    private double targetError = Double.NaN;
    private int maxDepth = -1;
    private boolean progressive;
    private int seed;

    /** One of {@link Sampler#NAMES}. */
    public RenderSettings sampler(String name) {
        if (!Sampler.NAMES.contains(name)) {
            throw new IllegalArgumentException("unknown sampler '" + name + "' (expected one of " + String.join(", ", Sampler.NAMES) + ")");
        }
        sampler = name;
        return this;
    }

    /** n_s: n_s x n_s samples per pixel (the adaptive sampler's budget). */
    public RenderSettings samples(int ns) {
        if (ns < 1 || ns > Limits.MAX_AA_SAMPLES) {
            throw new IllegalArgumentException("samples must be 1 to " + Limits.MAX_AA_SAMPLES + ", got " + ns);
        }
        samples = ns;
        return this;
    }

    /** The adaptive sampler's target: standard error of a pixel's mean, in 8-bit steps (0: take every sample). */
    public RenderSettings targetError(double e) {
        if (!(e >= 0) || !Double.isFinite(e)) {
            throw new IllegalArgumentException("target error must be a number >= 0 (8-bit steps), got " + e);
        }
        targetError = e;
        return this;
    }

    /** Mirror bounces followed, instead of the scene's MaxDepth. */
    public RenderSettings maxDepth(int d) {
        if (d < 0 || d > Limits.MAX_DEPTH) {
            throw new IllegalArgumentException("MaxDepth must be 0 to " + Limits.MAX_DEPTH + ", got " + d);
        }
        maxDepth = d;
        return this;
    }

    /** Deliver the image in passes (a cheap first pass, then refinements) through the progress listener. */
    public RenderSettings progressive(boolean p) {
        progressive = p;
        return this;
    }

    /**
     * The random seed of the {@code jittered} and {@code sobol} samplers (default 0): another seed gives
     * an independent image of the same scene, as an unbiased check of an image's noise needs.
     */
    public RenderSettings seed(int s) {
        seed = s;
        return this;
    }

    public int seed() {
        return seed;
    }

    public String samplerName(Scene scene) {
        return sampler != null ? sampler : scene.sampler;
    }

    public int samples(Scene scene) {
        return samples > 0 ? samples : Math.max(1, scene.samplesPerPixel);
    }

    public double targetError(Scene scene) {
        return !Double.isNaN(targetError) ? targetError : scene.targetError;
    }

    public int maxDepth(Scene scene) {
        return maxDepth >= 0 ? maxDepth : scene.maxDepth;
    }

    public boolean progressive() {
        return progressive;
    }
}
