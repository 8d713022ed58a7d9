package ray.study;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import ray.Scene;
import ray.render.Image;

/**
 * The study of one scene: a converged reference, then every setting rendered {@code repeats} times
 * (after a warm-up render) and compared with it.
 */
final class SceneStudy {

    /** What the study of one scene found. */
    record Outcome(String name, Scene scene, Image reference, Image halfReference, ImageError referenceChange,
            int referenceNs, String referenceSampler, List<Row> rows, List<Image> images) {
    }

    /** Told after each render, with the samples per pixel it spent (for the progress bar). */
    interface Tick {
        void rendered(double sppTimesPixels);
    }

    private final StudyRenderer renderer;
    private final StudySettings settings;
    private final int repeats;

    SceneStudy(StudyRenderer renderer, StudySettings settings, int repeats) {
        this.renderer = renderer;
        this.settings = settings;
        this.repeats = repeats;
    }

    Outcome run(String name, Scene scene, Tick tick) {
        double pixels = (double) scene.width * scene.height;
        String refSampler = settings.referenceSampler(renderer.samplers());
        int refNs = settings.referenceNs();
        // warm-up: the JIT compiles the render path before anything is timed
        Setting warm = new Setting("grid", "warm-up", 1, 0, scene.maxDepth);
        renderer.render(scene, warm);
        tick.rendered(pixels);
        StudyRenderer.Result probe = renderer.render(scene, warm);
        tick.rendered(pixels);
        boolean mirrors = probe.rays().get(ray.RayKind.MIRROR) + probe.rays().get(ray.RayKind.REFRACTION) > 0;

        Image half = renderer.render(scene, new Setting(refSampler, "reference/2", refNs / 2, 0, scene.maxDepth)).image();
        tick.rendered(pixels * (refNs / 2) * (refNs / 2));
        Image reference = renderer.render(scene, new Setting(refSampler, "reference", refNs, 0, scene.maxDepth)).image();
        tick.rendered(pixels * refNs * refNs);

        List<Row> rows = new ArrayList<>();
        List<Image> images = new ArrayList<>();
        for (Setting s : settings.settings(renderer.samplers(), scene.maxDepth, mirrors)) {
            double[] seconds = new double[repeats];
            StudyRenderer.Result first = null;
            for (int r = 0; r < repeats; r++) {
                StudyRenderer.Result res = renderer.render(scene, s);
                seconds[r] = res.seconds();
                tick.rendered(pixels * res.meanSpp());
                if (first == null) {
                    first = res;
                }
            }
            Arrays.sort(seconds);
            rows.add(new Row(s, median(seconds), seconds[0], seconds[repeats - 1], first.rays().total(),
                    ImageError.of(first.image(), reference), first.estimatedRmseSteps(), first.meanSpp()));
            images.add(first.image());
        }
        return new Outcome(name, scene, reference, half, ImageError.of(half, reference), refNs, refSampler, rows, images);
    }

    /** Work of {@link #run} in samples x pixels, for the progress bar (adaptive counted at its budget). */
    double work(Scene scene) {
        double pixels = (double) scene.width * scene.height;
        int refNs = settings.referenceNs();
        double w = 2 + refNs * refNs + (refNs / 2) * (refNs / 2);
        for (Setting s : settings.settings(renderer.samplers(), scene.maxDepth, scene.maxDepth > 0)) {
            w += repeats * s.budget();
        }
        return w * pixels;
    }

    static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
