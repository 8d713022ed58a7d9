package ray.app;

import java.io.PrintStream;
import picocli.CommandLine.Option;
import ray.Scene;
import ray.parse.Limits;
import ray.render.RenderSummary;
import ray.render.Sampler;

/**
 * The command line's sampling options ({@code --sampler}, {@code --samples}, {@code --target-error}),
 * mixed into {@link Main}: they override the scene's {@code Sampler}, {@code AASamples} and
 * {@code TargetError} globals.
 */
final class SamplingOptions {

    @Option(names = "--sampler", paramLabel = "NAME", description = "grid (the scene format's, default), jittered, sobol or adaptive; "
            + "overrides the scene's Sampler")
    String sampler;

    @Option(names = "--samples", paramLabel = "N", description = "N x N samples per pixel (the adaptive sampler's budget); overrides AASamples")
    Integer samples;

    @Option(names = "--target-error", paramLabel = "E", description = "adaptive: stop refining a pixel when the standard error of its mean "
            + "is below E 8-bit steps (default: the scene's TargetError, else 0.5)")
    Double targetError;

    /** What is wrong with the options, or null. */
    String problem() {
        if (sampler != null && !Sampler.NAMES.contains(sampler)) {
            return "--sampler must be one of " + String.join(", ", Sampler.NAMES) + ", got '" + sampler + "'";
        }
        if (samples != null && (samples < 1 || samples > Limits.MAX_AA_SAMPLES)) {
            return "--samples must be 1 to " + Limits.MAX_AA_SAMPLES + ", got " + samples;
        }
        if (targetError != null && !(targetError >= 0 && targetError <= 255)) {
            return "--target-error must be 0 to 255 (8-bit steps), got " + targetError;
        }
        return null;
    }

    /** Writes the options given into the scene's globals. */
    void applyTo(Scene scene) {
        if (sampler != null) {
            scene.sampler = sampler;
        }
        if (samples != null) {
            scene.samplesPerPixel = samples;
        }
        if (targetError != null) {
            scene.targetError = targetError;
        }
    }

    /** For any sampler but the grid (whose output stays as it always was): samples per pixel and estimated error. */
    static void report(PrintStream out, RenderSummary summary) {
        if (summary != null && !summary.sampler.equals("grid")) {
            out.println("  " + summary.line());
        }
    }
}
