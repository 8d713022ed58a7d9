package ray.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.api.java.function.Function;
import org.apache.spark.broadcast.Broadcast;
import ray.RayStats;
import ray.Scene;
import ray.render.Image;
import ray.study.Setting;
import ray.study.Study;
import ray.study.StudyRenderer;
import ray.study.StudySettings;

/**
 * {@code raytracer-spark --study}: {@code raytracer --study} (ray.study: the same settings, reference,
 * errors, CSVs, plots and index.html) with its renders run as Spark tasks: each scene's (setting, repeat)
 * renders as the tasks of one job, then the repeats of the settings whose times still spread widely as
 * further jobs; each render's CPU and wall time measured inside its task on the executor that ran it,
 * with that executor's host; the warm-up one task; the reference's renders (images only, no times) in tiles.
 */
final class StudyJob {

    private StudyJob() {
    }

    /**
     * Runs the study; {@code tile}: the side of the reference renders' tiles; {@code stdin}: the scene
     * {@code -} (read from standard input by the caller), or null.
     */
    static int run(JavaSparkContext jsc, List<Path> scenes, boolean quick, boolean fullSize, Path dir, int threads, int tile, byte[] stdin,
                   PrintStream out, PrintStream err, boolean progress) {
        SparkStudyRenderer renderer = new SparkStudyRenderer(jsc, threads, tile, fullSize ? 0 : StudySettings.MAX_PIXELS, stdin);
        Study s = new Study(renderer, quick ? StudySettings.QUICK : StudySettings.FULL, 3, out, err, progress);
        if (stdin != null) {
            s.in(new java.io.ByteArrayInputStream(stdin));
        }
        if (fullSize) {
            s.maxPixels(Integer.MAX_VALUE);
        }
        String mode = (quick ? "quick settings" : "full settings")
                + (fullSize ? ", every scene at its own size" : ", scenes over " + StudySettings.MAX_PIXELS + " pixels scaled down to that many")
                + "; rendered by raytracer-spark on " + jsc.master() + ": each render's CPU and wall time was measured inside its Spark "
                + "task on the executor that ran it (" + threads + " render thread(s) a task; CPU time from those threads' own clocks, so "
                + "tasks sharing an executor do not count each other's), so on a cluster the times come from different machines and "
                + "compare only as far as its machines are alike";
        try {
            return s.run(scenes, dir, mode);
        } finally {
            renderer.close();
        }
    }

    /** One render of the study: the setting's fields (Setting itself is not serializable). */
    record Render(String sampler, String label, int ns, double targetError, int maxDepth, int seed) implements Serializable {
        static Render of(Setting s) {
            return new Render(s.sampler(), s.label(), s.ns(), s.targetError(), s.maxDepth(), s.seed());
        }

        Setting setting() {
            return new Setting(sampler, label, ns, targetError, maxDepth, seed);
        }
    }

    /** What a task sends back: the result's parts (the study's records are not serializable), and where it ran. */
    record Rendered(Image image, double seconds, double cpuSeconds, RayStats rays, double meanSpp, double rmse, double low, double high,
                    double probeSpp, boolean estimated, String machine, String failure) implements Serializable {
        StudyRenderer.Result result() {
            return new StudyRenderer.Result(image, seconds, cpuSeconds, rays, meanSpp, estimated
                    ? new StudyRenderer.Estimate(rmse, low, high, probeSpp) : StudyRenderer.Estimate.NONE, machine);
        }
    }

    /**
     * Renders one setting on an executor with the built-in study renderer, as {@code raytracer --study}
     * does (the time is the renderer's own: BVH build and render, not parsing). Each task parses its own
     * copy of the scene, since renders with different settings prepare it differently; each JVM first
     * renders every scene once untimed, so the JIT has compiled the render path before anything is timed.
     */
    static final class RenderTask implements Function<Render, Rendered> {
        private static final long serialVersionUID = 1L;
        private static final Set<String> WARM = ConcurrentHashMap.newKeySet();
        private final Broadcast<SceneBundle> bundle;
        private final int threads;

        RenderTask(Broadcast<SceneBundle> bundle, int threads) {
            this.bundle = bundle;
            this.threads = threads;
        }

        @Override
        public Rendered call(Render r) {
            SceneBundle b = bundle.value();
            StudyRenderer local = Study.localRenderer(threads);
            try {
                if (WARM.add(b.key)) {
                    Scene warm = b.parse();
                    local.render(warm, new Setting("grid", "warm-up", 1, 0, r.maxDepth()));
                }
                StudyRenderer.Result res = local.render(b.parse(), r.setting());
                StudyRenderer.Estimate e = res.estimate();
                return new Rendered(res.image(), res.seconds(), res.cpuSeconds(), res.rays(), res.meanSpp(), e.rmseSteps(), e.lowSteps(),
                        e.highSteps(), e.samplesPerPixel(), e != StudyRenderer.Estimate.NONE, machine(), null);
            } catch (OutOfMemoryError e) {
                throw e;
            } catch (Throwable e) {   // a user's class: the same on any retry
                return new Rendered(null, 0, 0, null, 0, 0, 0, 0, 0, false, "", ray.app.RenderReport.failure(e));
            }
        }
    }

    /** The host this task runs on (the block manager's: what Spark calls the executor's host), for the report. */
    static String machine() {
        org.apache.spark.SparkEnv env = org.apache.spark.SparkEnv.get();
        return env == null ? "" : env.blockManager().blockManagerId().host();
    }

    /**
     * The study's renderer: renders as Spark tasks, the scene shipped once per executor. A timed render is
     * one task (its time is the task's); the converged reference's renders, whose times the study does not
     * use, are cut into tiles like {@code raytracer-spark}'s renders (the same pixels, bit for bit).
     */
    static final class SparkStudyRenderer implements StudyRenderer {
        private final JavaSparkContext jsc;
        private final int threads, tile, maxPixels;
        private final byte[] stdin;
        private Broadcast<SceneBundle> current;

        SparkStudyRenderer(JavaSparkContext jsc, int threads, int tile, int maxPixels, byte[] stdin) {
            this.jsc = jsc;
            this.threads = threads;
            this.tile = tile;
            this.maxPixels = maxPixels;
            this.stdin = stdin;
        }

        @Override
        public List<String> samplers() {
            return Study.localRenderer(threads).samplers();
        }

        @Override
        public void studying(Path file, Scene scene) {
            close();
            SceneBundle.Overrides o = new SceneBundle.Overrides(new ray.settings.RenderSettings(), maxPixels);
            try {
                current = jsc.broadcast(file.toString().equals("-") && stdin != null
                        ? SceneBundle.of("-", stdin, Path.of("").toAbsolutePath(), scene, o) : SceneBundle.of(file, scene, o));
            } catch (IOException e) {
                throw new UncheckedIOException(file + ": cannot read the scene's files: " + e.getMessage(), e);
            }
        }

        @Override
        public Result render(Scene scene, Setting setting) {
            return renderAll(scene, List.of(setting)).get(0);
        }

        @Override
        public List<Result> renderAll(Scene scene, List<Setting> settings) {
            if (current == null) {
                throw new IllegalStateException("studying(file, scene) was not called");
            }
            // the reference's renders in tiles, the others one task each; the results in the order asked
            List<Integer> tiled = new ArrayList<>(), whole = new ArrayList<>();
            for (int i = 0; i < settings.size(); i++) {
                Setting s = settings.get(i);
                (s.label().equals(Setting.REFERENCE) && !s.sampler().equals("adaptive") ? tiled : whole).add(i);
            }
            Result[] results = new Result[settings.size()];
            if (!tiled.isEmpty()) {
                List<Result> r = renderTiled(scene, tiled.stream().map(settings::get).toList());
                for (int k = 0; k < tiled.size(); k++) {
                    results[tiled.get(k)] = r.get(k);
                }
            }
            if (!whole.isEmpty()) {
                List<Result> r = renderWhole(whole.stream().map(settings::get).toList());
                for (int k = 0; k < whole.size(); k++) {
                    results[whole.get(k)] = r.get(k);
                }
            }
            return List.of(results);
        }

        /** Each setting as one task, timed inside it. */
        private List<Result> renderWhole(List<Setting> settings) {
            List<Render> renders = new ArrayList<>();
            for (Setting s : settings) {
                renders.add(Render.of(s));
            }
            jsc.setJobDescription("raytracer-spark --study: " + current.value().name + ", " + renders.size() + " render(s)");
            List<Rendered> done = jsc.parallelize(renders, renders.size()).map(new RenderTask(current, threads)).collect();
            List<Result> out = new ArrayList<>();
            for (Rendered r : done) {
                if (r.failure() != null) {
                    throw new IllegalStateException(r.failure());   // the study reports the scene as failed and goes on
                }
                out.add(r.result());
            }
            return out;
        }

        /**
         * Each setting's image cut into tiles, all tiles one job (the render job's tasks: the scene parsed
         * and prepared once per executor JVM and setting), assembled here; the time is the job's.
         */
        private List<Result> renderTiled(Scene scene, List<Setting> settings) {
            SceneBundle[] bundles = new SceneBundle[settings.size()];
            List<Tasks.Task> tasks = new ArrayList<>();
            for (int i = 0; i < bundles.length; i++) {
                bundles[i] = current.value().with(new SceneBundle.Overrides(settings.get(i).renderSettings(), maxPixels));
                for (int y = 0; y < scene.height; y += tile) {
                    for (int x = 0; x < scene.width; x += tile) {
                        tasks.add(Tasks.Task.tile(i, x, y, Math.min(scene.width, x + tile), Math.min(scene.height, y + tile)));
                    }
                }
            }
            Broadcast<SceneBundle[]> shipped = jsc.broadcast(bundles);
            try {
                jsc.setJobDescription("raytracer-spark --study: " + current.value().name + ", reference, " + tasks.size() + " tiles");
                long t0 = System.nanoTime();
                List<Tasks.Result> done = jsc.parallelize(tasks, tasks.size()).map(new Tasks.Render(shipped, threads)).collect();
                double seconds = (System.nanoTime() - t0) / 1e9;
                ray.render.SplitRender.Assembly[] a = new ray.render.SplitRender.Assembly[bundles.length];
                for (Tasks.Result r : done) {
                    if (r.failure() != null) {
                        throw new IllegalStateException(r.failure());
                    }
                    if (a[r.scene()] == null) {
                        a[r.scene()] = new ray.render.SplitRender.Assembly(scene.width, scene.height);
                    }
                    a[r.scene()].add(r.piece());
                }
                List<Result> out = new ArrayList<>();
                for (ray.render.SplitRender.Assembly x : a) {
                    ray.render.RenderSummary sum = x.summary(seconds);
                    out.add(new Result(x.image(), seconds, x.stats(), sum.meanSamplesPerPixel, StudyRenderer.Estimate.NONE));
                }
                return out;
            } finally {
                shipped.destroy();
            }
        }

        void close() {
            if (current != null) {
                current.destroy();
                current = null;
            }
        }
    }
}
