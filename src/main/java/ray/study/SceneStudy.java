package ray.study;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import ray.Scene;
import ray.render.Image;

/**
 * The study of one scene: every setting rendered {@code repeats} times in one batch (after a warm-up
 * render), then the settings whose CPU times still spread widely ({@link #settled}) again, a batch of
 * {@code repeats} more at a time, up to {@link #MAX_REPEATS} times as often; each render's wall and CPU
 * time as measured where it ran ({@link StudyRenderer.Result}); then a converged {@link Reference} good
 * enough to judge them, then each compared with it.
 */
final class SceneStudy {

    /** What the study of one scene found; {@code fullWidth} x {@code fullHeight} is the scene's own size. */
    record Outcome(String name, Scene scene, int fullWidth, int fullHeight, Reference ref, List<Row> rows, List<Image> images,
                   List<String> machines) {

        Image reference() {
            return ref.image();
        }
    }

    /** Told after each render, with the samples per pixel it spent (for the progress bar). */
    interface Tick {
        void rendered(double sppTimesPixels);

        /** Told before renders {@link #work(Scene)} did not count (repeats of settings whose times spread widely). */
        default void added(double sppTimesPixels) {
        }
    }

    /** At most this many times the study's repeats are timed for one setting. */
    static final int MAX_REPEATS = 3;

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
        // every (setting, repeat) in one batch, then, while some settings' times still spread widely
        // against their median, those settings again in further batches, up to MAX_REPEATS x repeats
        // renders each: a setting's time must be its own, not the machine's other work
        List<List<StudyRenderer.Result>> timed = new ArrayList<>();
        List<Integer> again = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            timed.add(new ArrayList<>());
            again.add(i);
        }
        for (int batch = 0; !again.isEmpty(); batch++) {
            List<Setting> runs = new ArrayList<>();
            for (int i : again) {
                for (int r = 0; r < repeats; r++) {
                    runs.add(list.get(i));
                }
            }
            if (batch > 0) {
                tick.added(work(runs, pixels));
            }
            List<StudyRenderer.Result> results = renderer.renderAll(scene, runs);
            if (results.size() != runs.size()) {
                throw new IllegalStateException(renderer.getClass().getName() + ".renderAll returned " + results.size() + " results for "
                        + runs.size() + " renders");
            }
            for (int k = 0; k < results.size(); k++) {
                StudyRenderer.Result res = results.get(k);
                timed.get(again.get(k / repeats)).add(res);
                tick.rendered(pixels * res.meanSpp());
            }
            List<Integer> next = new ArrayList<>();
            for (int i : again) {
                if (timed.get(i).size() + repeats <= MAX_REPEATS * repeats && !settled(timed.get(i))) {
                    next.add(i);
                }
            }
            again = next;
        }
        List<Image> images = new ArrayList<>();
        for (List<StudyRenderer.Result> t : timed) {
            images.add(t.get(0).image());
        }
        // the reference after the settings: it goes on until its noise is small beside their errors
        Reference ref = Reference.build(renderer, scene, settings.referenceStartNs(), settings.referenceNs(), images, tick);
        List<Row> rows = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            List<StudyRenderer.Result> t = timed.get(i);
            StudyRenderer.Result first = t.get(0);
            double[] wall = sorted(t, StudyRenderer.Result::seconds), cpu = sorted(t, StudyRenderer.Result::cpuSeconds);
            rows.add(new Row(list.get(i), median(wall), wall[0], wall[wall.length - 1], first.rays().total(),
                    ImageError.of(first.image(), ref.image()), first.estimate(), first.meanSpp(), median(cpu), quantile(cpu, 0.25),
                    quantile(cpu, 0.75), t.size()));
        }
        List<String> machines = new ArrayList<>();
        for (List<StudyRenderer.Result> t : timed) {
            for (StudyRenderer.Result r : t) {
                if (!machines.contains(r.machine())) {
                    machines.add(r.machine());
                }
            }
        }
        return new Outcome(name, scene, fullWidth, fullHeight, ref, rows, images, machines);
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

    /**
     * A setting's times say what they can: the middle half of its CPU times (wall times where none was
     * measured) spans at most a tenth of their median, or 3 ms, so the differences the report draws and
     * judges between settings are theirs and not the machine's other work.
     */
    static boolean settled(List<StudyRenderer.Result> timed) {
        double[] t = sorted(timed, StudyRenderer.Result::cpuSeconds);
        if (Double.isNaN(t[t.length - 1]) || Double.isNaN(t[0])) {
            t = sorted(timed, StudyRenderer.Result::seconds);
        }
        return quantile(t, 0.75) - quantile(t, 0.25) <= Math.max(0.1 * median(t), 0.003);
    }

    private static double[] sorted(List<StudyRenderer.Result> l, java.util.function.ToDoubleFunction<StudyRenderer.Result> f) {
        double[] a = new double[l.size()];
        for (int i = 0; i < a.length; i++) {
            a[i] = f.applyAsDouble(l.get(i));
        }
        Arrays.sort(a);
        return a;
    }

    /** The {@code q} quantile of sorted values, interpolated between neighbours (the median at 0.5). */
    static double quantile(double[] sorted, double q) {
        double at = q * (sorted.length - 1);
        int i = (int) Math.floor(at);
        return i + 1 < sorted.length ? sorted[i] + (at - i) * (sorted[i + 1] - sorted[i]) : sorted[i];
    }

    private double work(List<Setting> runs, double pixels) {
        double w = 0;
        for (Setting s : runs) {
            w += s.budget() * pixels;
        }
        return w;
    }

    static double median(double[] sorted) {
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    }
}
