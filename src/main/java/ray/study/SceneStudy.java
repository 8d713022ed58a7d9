package ray.study;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import ray.Scene;
import ray.render.Image;

/**
 * The study of one scene: every setting rendered {@code repeats} times (after a warm-up render), then a
 * converged {@link Reference} good enough to judge them, then each compared with it.
 */
final class SceneStudy {

    /** What the study of one scene found; {@code fullWidth} x {@code fullHeight} is the scene's own size. */
    record Outcome(String name, Scene scene, int fullWidth, int fullHeight, Reference ref, List<Row> rows, List<Image> images) {

        Image reference() {
            return ref.image();
        }
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

    /** Studies {@code scene} (already fitted to the study's size); {@code fullWidth} x {@code fullHeight} is its own. */
    Outcome run(String name, Scene scene, int fullWidth, int fullHeight, Tick tick) {
        double pixels = (double) scene.width * scene.height;
        // warm-up: the JIT compiles the render path before anything is timed
        Setting warm = new Setting("grid", "warm-up", 1, 0, scene.maxDepth);
        renderer.render(scene, warm);
        tick.rendered(pixels);
        StudyRenderer.Result probe = renderer.render(scene, warm);
        tick.rendered(pixels);
        boolean mirrors = probe.rays().get(ray.RayKind.MIRROR) + probe.rays().get(ray.RayKind.REFRACTION) > 0;

        List<Setting> list = settings.settings(renderer.samplers(), scene.maxDepth, mirrors);
        List<StudyRenderer.Result> firsts = new ArrayList<>();
        List<double[]> times = new ArrayList<>();
        List<Image> images = new ArrayList<>();
        List<Setting> runs = new ArrayList<>();
        for (Setting s : list) {
            for (int r = 0; r < repeats; r++) {
                runs.add(s);
            }
        }
        List<StudyRenderer.Result> results = renderer.renderAll(scene, runs);
        for (int i = 0; i < list.size(); i++) {
            double[] seconds = new double[repeats];
            StudyRenderer.Result first = null;
            for (int r = 0; r < repeats; r++) {
                StudyRenderer.Result res = results.get(i * repeats + r);
                seconds[r] = res.seconds();
                tick.rendered(pixels * res.meanSpp());
                if (first == null) {
                    first = res;
                }
            }
            Arrays.sort(seconds);
            firsts.add(first);
            times.add(seconds);
            images.add(first.image());
        }
        // the reference after the settings: it goes on until its noise is small beside their errors
        Reference ref = Reference.build(renderer, scene, settings.referenceStartNs(), settings.referenceNs(), images, tick);
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            StudyRenderer.Result first = firsts.get(i);
            double[] seconds = times.get(i);
            rows.add(new Row(list.get(i), median(seconds), seconds[0], seconds[repeats - 1], first.rays().total(),
                    ImageError.of(first.image(), ref.image()), first.estimate(), first.meanSpp()));
        }
        return new Outcome(name, scene, fullWidth, fullHeight, ref, rows, images);
    }

    /**
     * Work of {@link #run} in samples x pixels, for the progress bar (adaptive counted at its budget, the
     * reference at its first level).
     */
    double work(Scene scene) {
        double pixels = (double) scene.width * scene.height;
        int refNs = settings.referenceStartNs();
        double w = 2 + 2 * refNs * refNs;
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
