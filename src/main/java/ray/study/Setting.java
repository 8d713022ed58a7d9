package ray.study;

/**
 * One point of the study: a sampler at a sample budget (n_s x n_s samples per pixel at most), with a
 * target error for {@code adaptive} (8-bit steps; 0 elsewhere) and the MaxDepth to render with.
 */
public record Setting(String sampler, String label, int ns, double targetError, int maxDepth) {

    /** Samples per pixel of a non-adaptive render (adaptive spends at most this many). */
    public int budget() {
        return ns * ns;
    }
}
