package ray.study;

import java.util.List;
import ray.Scene;
import ray.render.Image;
import ray.render.RenderSummary;
import ray.render.Renderer;
import ray.render.Sampler;

/** The study's way into {@link Renderer}: one render with the setting's sampler, n_s, target and MaxDepth. */
final class RendererAdapter implements StudyRenderer {

    private final int threads;

    RendererAdapter(int threads) {
        this.threads = threads;
    }

    @Override
    public List<String> samplers() {
        return Sampler.NAMES;
    }

    @Override
    public Result render(Scene scene, Setting s) {
        Renderer r = new Renderer(scene).settings(s.renderSettings()).threads(threads).measureCpu(true);
        Image image = r.render();
        RenderSummary sum = r.summary();
        boolean adaptive = r.resolvedSettings().adaptive();
        return new Result(image, sum.seconds, sum.cpuSeconds, sum.stats, sum.meanSamplesPerPixel, adaptive
                ? new Estimate(sum.estimatedRmse, sum.estimatedRmseLow, sum.estimatedRmseHigh, sum.probeSamplesPerPixel) : Estimate.NONE, "");
    }
}
