package ray.study;

import ray.RayStats;
import ray.Scene;
import ray.render.Image;

/** Renders a scene at one {@link Setting}; the study's only way into the renderer. */
public interface StudyRenderer {

    /** What one render produced. {@code estimatedRmseSteps} is NaN where the sampler makes no estimate. */
    record Result(Image image, double seconds, RayStats rays, double estimatedRmseSteps, double meanSpp) {
    }

    /** The sampler names this renderer knows, the default ({@code grid}) first. */
    java.util.List<String> samplers();

    Result render(Scene scene, Setting setting);
}
