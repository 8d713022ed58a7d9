package ray.study;

import ray.RayStats;
import ray.Scene;
import ray.render.Image;

/** Renders a scene at one {@link Setting}; the study's only way into the renderer. */
public interface StudyRenderer {

    /** What one render produced; {@code estimate} is {@link Estimate#NONE} where the sampler makes none. */
    record Result(Image image, double seconds, RayStats rays, double meanSpp, Estimate estimate) {
    }

    /**
     * A render's estimate of its own RMSE (8-bit steps), its 95% interval, and what measuring it cost in
     * samples per pixel.
     */
    record Estimate(double rmseSteps, double lowSteps, double highSteps, double samplesPerPixel) {
        public static final Estimate NONE = new Estimate(Double.NaN, Double.NaN, Double.NaN, 0);
    }

    /** The sampler names this renderer knows, the default ({@code grid}) first. */
    java.util.List<String> samplers();

    Result render(Scene scene, Setting setting);
}
