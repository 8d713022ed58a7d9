package ray.study;

/**
 * One point of the study: a sampler at a sample budget (n_s x n_s samples per pixel at most), with a
 * target error for {@code adaptive} (8-bit steps; 0 elsewhere), the MaxDepth to render with, and the
 * randomised samplers' seed (0 for the settings studied; the reference's two halves use 1 and 2).
 */
public record Setting(String sampler, String label, int ns, double targetError, int maxDepth, int seed) {

    /** The label of the converged reference's renders: only their images count, not their times. */
    public static final String REFERENCE = "reference";

    public Setting(String sampler, String label, int ns, double targetError, int maxDepth) {
        this(sampler, label, ns, targetError, maxDepth, 0);
    }

    /** The renderer's settings for this point: sampler, n_s, MaxDepth, seed, and adaptive's target error. */
    public ray.settings.RenderSettings renderSettings() {
        ray.settings.RenderSettings s = new ray.settings.RenderSettings().sampler(sampler).samples(ns).maxDepth(maxDepth).seed(seed);
        return sampler.equals("adaptive") ? s.targetError(targetError) : s;
    }

    /** Samples per pixel of a non-adaptive render (adaptive spends at most this many). */
    public int budget() {
        return ns * ns;
    }
}
