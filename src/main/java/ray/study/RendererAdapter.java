package ray.study;

import java.util.List;
import ray.RayStats;
import ray.Scene;
import ray.render.Image;
import ray.render.Renderer;

/** The study's way into {@link Renderer}: the setting's n_s and MaxDepth on the scene, then one render. */
final class RendererAdapter implements StudyRenderer {

    private final int threads;

    RendererAdapter(int threads) {
        this.threads = threads;
    }

    @Override
    public List<String> samplers() {
        return List.of("grid");
    }

    @Override
    public Result render(Scene scene, Setting s) {
        int ns = scene.samplesPerPixel, depth = scene.maxDepth;
        scene.samplesPerPixel = s.ns();
        scene.maxDepth = s.maxDepth();
        try {
            Renderer r = new Renderer(scene).threads(threads);
            long t0 = System.nanoTime();
            Image image = r.render();
            double seconds = (System.nanoTime() - t0) / 1e9;
            RayStats rays = new RayStats();
            rays.add(r.stats());
            return new Result(image, seconds, rays, Double.NaN, s.budget());
        } finally {
            scene.samplesPerPixel = ns;
            scene.maxDepth = depth;
        }
    }
}
