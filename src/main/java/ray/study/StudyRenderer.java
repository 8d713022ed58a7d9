package ray.study;

import ray.RayStats;
import ray.Scene;
import ray.render.Image;

/** Renders a scene at one {@link Setting}; the study's only way into the renderer. */
public interface StudyRenderer {

    /**
     * What one render produced; {@code estimate} is {@link Estimate#NONE} where the sampler makes none.
     * {@code seconds} is its wall time and {@code cpuSeconds} its CPU time (NaN where not measured), both
     * measured where it ran; {@code machine} names the machine it ran on ({@code ""}: this process), so
     * the report can say when times come from different machines.
     */
    record Result(Image image, double seconds, double cpuSeconds, RayStats rays, double meanSpp, Estimate estimate, String machine) {

        /** A render in this process without a CPU time. */
        public Result(Image image, double seconds, RayStats rays, double meanSpp, Estimate estimate) {
            this(image, seconds, Double.NaN, rays, meanSpp, estimate, "");
        }
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

    /**
     * Renders each of {@code settings} in turn and returns the results in order. A renderer that runs
     * renders elsewhere (raytracer-spark: one task each) renders them all at once. The study calls it
     * once per scene for every (setting, repeat), then again, in smaller batches, for the settings whose
     * times still spread widely ({@link SceneStudy}); a setting may appear several times in a batch.
     */
    default java.util.List<Result> renderAll(Scene scene, java.util.List<Setting> settings) {
        java.util.List<Result> out = new java.util.ArrayList<>();
        for (Setting s : settings) {
            out.add(render(scene, s));
        }
        return out;
    }

    /** Told which scene file the next renders are of ({@code scene}: it parsed and fitted to the study's size). */
    default void studying(java.nio.file.Path file, Scene scene) {
    }
}
