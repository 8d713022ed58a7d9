package ray.settings;

import java.util.Objects;
import ray.Scene;

/**
 * How to render a scene: the sampler, n_s, the adaptive target error, MaxDepth, whether to deliver the
 * image in passes, the random seed and whether to cut faint mirror paths. An immutable value: each
 * setter returns a new one. Values not set come from the scene's globals ({@code Sampler},
 * {@code AASamples}, {@code TargetError}, {@code MaxDepth}) when the settings are {@link #resolve resolved}
 * against it, once per render; the render plan and the renderer read only the resolved value, and nothing
 * writes into the parsed scene. Each value is checked against its row of {@link RenderOption}.
 *
 * <pre>
 * RenderSettings s = new RenderSettings().sampler("adaptive").samples(4).targetError(0.5);
 * Renderer r = new Renderer(scene).settings(s);
 * Image linear = r.render();
 * RenderSummary what = r.summary();    // time, rays by kind, mean spp, estimated RMSE
 * </pre>
 */
public final class RenderSettings implements java.io.Serializable {

    private static final long serialVersionUID = 1L;

    private static final int UNSET = -1;

    private final String sampler;
    private final int samples;
    private final double targetError;
    private final int maxDepth;
    private final boolean progressive;
    private final int seed;
    private final boolean cutFaint;

    /** Nothing set: everything comes from the scene. */
    public RenderSettings() {
        this(null, UNSET, Double.NaN, UNSET, false, 0, false);
    }

    private RenderSettings(String sampler, int samples, double targetError, int maxDepth, boolean progressive, int seed,
                           boolean cutFaint) {
        this.sampler = sampler;
        this.samples = samples;
        this.targetError = targetError;
        this.maxDepth = maxDepth;
        this.progressive = progressive;
        this.seed = seed;
        this.cutFaint = cutFaint;
    }

    /** The scene's own settings: its globals, nothing overridden. */
    public static RenderSettings of(Scene scene) {
        return new RenderSettings().resolve(scene);
    }

    /** One of {@link RenderOption#SAMPLER}'s choices. */
    public RenderSettings sampler(String name) {
        return new RenderSettings(RenderOption.SAMPLER.checked(name), samples, targetError, maxDepth, progressive, seed, cutFaint);
    }

    /** n_s: n_s x n_s samples per pixel (the adaptive sampler's budget). */
    public RenderSettings samples(int ns) {
        return new RenderSettings(sampler, RenderOption.SAMPLES.checked(ns), targetError, maxDepth, progressive, seed, cutFaint);
    }

    /** The adaptive sampler's target: standard error of a pixel's mean, in 8-bit steps (0: take every sample). */
    public RenderSettings targetError(double e) {
        return new RenderSettings(sampler, samples, RenderOption.TARGET_ERROR.checked(e), maxDepth, progressive, seed, cutFaint);
    }

    /** Mirror bounces followed, instead of the scene's MaxDepth. */
    public RenderSettings maxDepth(int d) {
        return new RenderSettings(sampler, samples, targetError, RenderOption.MAX_DEPTH.checked(d), progressive, seed, cutFaint);
    }

    /** Deliver the image in passes (a cheap first pass, then refinements) through the progress listener. */
    public RenderSettings progressive(boolean p) {
        return new RenderSettings(sampler, samples, targetError, maxDepth, p, seed, cutFaint);
    }

    /**
     * The random seed of the {@code jittered} and {@code sobol} samplers (default 0): another seed gives
     * an independent image of the same scene, as an unbiased check of an image's noise needs.
     */
    public RenderSettings seed(int s) {
        return new RenderSettings(sampler, samples, targetError, maxDepth, progressive, s, cutFaint);
    }

    /**
     * Whether to cut mirror paths whose remaining weight is below the plan's faint limit (off by default:
     * inexact, the {@code --cut-faint} option).
     */
    public RenderSettings cutFaint(boolean cut) {
        return new RenderSettings(sampler, samples, targetError, maxDepth, progressive, seed, cut);
    }

    /**
     * These settings with every value not set taken from {@code scene}'s globals (n_s at least 1, as the
     * framework's renderer always took it). Resolve once per render; the result resolves to itself.
     */
    public RenderSettings resolve(Scene scene) {
        return new RenderSettings(sampler != null ? sampler : scene.sampler,
                samples != UNSET ? samples : Math.max(1, scene.samplesPerPixel),
                !Double.isNaN(targetError) ? targetError : scene.targetError,
                maxDepth != UNSET ? maxDepth : scene.maxDepth, progressive, seed, cutFaint);
    }

    /** True when every value is set (by {@link #resolve} or by hand). */
    public boolean resolved() {
        return sampler != null && samples != UNSET && !Double.isNaN(targetError) && maxDepth != UNSET;
    }

    private void requireResolved() {
        if (!resolved()) {
            throw new IllegalStateException("settings not resolved against a scene yet: " + this);
        }
    }

    /** The sampler's name (resolved settings only). */
    public String sampler() {
        requireResolved();
        return sampler;
    }

    /** True for the adaptive sampler (resolved settings only). */
    public boolean adaptive() {
        return "adaptive".equals(sampler());
    }

    /** n_s (resolved settings only). */
    public int samples() {
        requireResolved();
        return samples;
    }

    /** The adaptive target error in 8-bit steps (resolved settings only). */
    public double targetError() {
        requireResolved();
        return targetError;
    }

    /** MaxDepth (resolved settings only). */
    public int maxDepth() {
        requireResolved();
        return maxDepth;
    }

    public boolean progressive() {
        return progressive;
    }

    public int seed() {
        return seed;
    }

    public boolean cutsFaintPaths() {
        return cutFaint;
    }

    /** The sampler these settings give {@code scene}. */
    public String samplerName(Scene scene) {
        return resolve(scene).sampler();
    }

    /** n_s these settings give {@code scene}. */
    public int samples(Scene scene) {
        return resolve(scene).samples();
    }

    /** The target error these settings give {@code scene}. */
    public double targetError(Scene scene) {
        return resolve(scene).targetError();
    }

    /** MaxDepth these settings give {@code scene}. */
    public int maxDepth(Scene scene) {
        return resolve(scene).maxDepth();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof RenderSettings s && Objects.equals(sampler, s.sampler) && samples == s.samples
                && Double.compare(targetError, s.targetError) == 0 && maxDepth == s.maxDepth && progressive == s.progressive
                && seed == s.seed && cutFaint == s.cutFaint;
    }

    @Override
    public int hashCode() {
        return Objects.hash(sampler, samples, targetError, maxDepth, progressive, seed, cutFaint);
    }

    @Override
    public String toString() {
        return "RenderSettings[sampler " + sampler + ", samples " + samples + ", targetError " + targetError + ", maxDepth "
                + maxDepth + (progressive ? ", progressive" : "") + ", seed " + seed + (cutFaint ? ", cutFaint" : "") + "]";
    }
}
