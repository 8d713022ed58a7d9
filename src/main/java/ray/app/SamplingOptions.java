package ray.app;

import java.io.PrintStream;
import picocli.CommandLine.Option;
import ray.render.RenderSummary;
import ray.settings.RenderOption;
import ray.settings.RenderSettings;

/**
 * The command line's render options ({@code --sampler}, {@code --samples}, {@code --target-error},
 * {@code --max-depth}), mixed into {@link Main}: they override the scene's
 * {@code Sampler}, {@code AASamples}, {@code TargetError} and {@code MaxDepth} globals, as one
 * {@link RenderSettings} value that every mode (render, {@code --plan}, {@code --view}) resolves
 * against each scene. Their ranges are {@link RenderOption}'s.
 */
public final class SamplingOptions {

    @Option(names = "--sampler", paramLabel = "NAME", description = "grid (the scene format's, default), jittered, sobol or adaptive; "
            + "overrides the scene's Sampler")
    String sampler;

    @Option(names = "--samples", paramLabel = "N", description = "N x N samples per pixel (the adaptive sampler's budget); overrides AASamples")
    Integer samples;

    @Option(names = "--target-error", paramLabel = "E", description = "adaptive: stop refining a pixel when the standard error of its mean "
            + "is below E 8-bit steps (default: the scene's TargetError, else 0.5)")
    Double targetError;

    @Option(names = "--max-depth", paramLabel = "D", description = "mirror and refraction bounces followed; overrides MaxDepth")
    Integer maxDepth;

    /** What is wrong with the options, or null. */
    public String problem() {
        if (sampler != null && RenderOption.SAMPLER.problem("--sampler", sampler) != null) {
            return RenderOption.SAMPLER.problem("--sampler", sampler);
        }
        if (samples != null && RenderOption.SAMPLES.problem("--samples", samples) != null) {
            return RenderOption.SAMPLES.problem("--samples", samples);
        }
        if (targetError != null && RenderOption.TARGET_ERROR.problem("--target-error", targetError) != null) {
            return RenderOption.TARGET_ERROR.problem("--target-error", targetError);
        }
        if (maxDepth != null && RenderOption.MAX_DEPTH.problem("--max-depth", maxDepth) != null) {
            return RenderOption.MAX_DEPTH.problem("--max-depth", maxDepth);
        }
        return null;
    }

    /** The options given, as settings that override a scene's globals (check {@link #problem()} first). */
    public RenderSettings settings() {
        RenderSettings s = new RenderSettings();
        if (sampler != null) {
            s = s.sampler(sampler);
        }
        if (samples != null) {
            s = s.samples(samples);
        }
        if (targetError != null) {
            s = s.targetError(targetError);
        }
        if (maxDepth != null) {
            s = s.maxDepth(maxDepth);
        }
        return s;
    }

    /** For any sampler but the grid (whose output stays as it always was): samples per pixel and estimated error. */
    static void report(PrintStream out, RenderSummary summary) {
        if (summary != null && !summary.sampler.equals("grid")) {
            out.println("  " + summary.line());
        }
    }
}
