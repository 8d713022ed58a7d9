package ray.spark;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.apache.spark.SparkException;
import org.apache.spark.api.java.JavaRDD;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.broadcast.Broadcast;
import ray.Scene;
import ray.app.RenderReport;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.plan.CostGate;
import ray.plan.RenderPlan;
import ray.render.Image;
import ray.render.RenderSummary;
import ray.render.SplitRender;
import ray.settings.RenderSettings;
import scala.runtime.AbstractFunction2;
import scala.runtime.BoxedUnit;

/**
 * {@code raytracer-spark scene.txt...}: every scene read on the driver first (a bad one fails alone,
 * before any task), then all scenes' tiles as the tasks of one Spark job; the driver adds each tile to
 * its scene's image as it arrives and writes a scene's PNG as soon as its last tile is in. The adaptive
 * sampler's error probes, which need the whole image, are a second job over the scenes that use it.
 */
final class RenderJob {

    /** What the command line asked for. */
    record Options(String outputDir, int tile, int threads, SceneBundle.Overrides overrides, boolean quiet, boolean stats,
                   boolean json, boolean allowLong) {
    }

    private final JavaSparkContext jsc;
    private final Options o;
    private final PrintStream out, err;
    private final Progress progress;

    RenderJob(JavaSparkContext jsc, Options o, PrintStream out, PrintStream err, boolean showProgress) {
        this.jsc = jsc;
        this.o = o;
        this.out = out;
        this.err = err;
        this.progress = new Progress(err, showProgress && !o.quiet());
    }

    /** One scene's state on the driver. */
    private final class Job {
        final Path path;
        final String name;
        final Scene scene;
        /** The render's settings, resolved against the scene's globals (as raytracer resolves them). */
        final RenderSettings settings;
        final Output output;
        final SplitRender.Assembly assembly;
        final long t0, t1;
        long build, bvhBytes, primitives;
        int tasks, tasksDone;
        String failure;
        boolean finished;

        Job(Path path, Scene scene, RenderSettings settings, Output output, long t0, long t1) {
            this.path = path;
            this.name = path.toString();
            this.scene = scene;
            this.settings = settings;
            this.output = output;
            this.assembly = new SplitRender.Assembly(scene.width, scene.height);
            this.t0 = t0;
            this.t1 = t1;
        }

        boolean adaptive() {
            return settings.adaptive();
        }

        void take(Tasks.Result r) {
            tasksDone++;
            if (failure != null || finished) {
                return;
            }
            if (r.failure() != null) {
                fail(r.failure());
                return;
            }
            build = Math.max(build, r.buildNanos());
            bvhBytes = r.bvhBytes();
            primitives = r.primitives();
            if (r.piece() != null) {
                assembly.add(r.piece());
            } else {
                assembly.addProbes(r.probes());
            }
        }

        void fail(String message) {
            failure = message;
            output.abandon();
            progress.clear();
            err.println(RenderReport.oneLine(name + ": " + message));
        }

        /** Writes the PNG and prints the scene's lines. */
        void finish(long t2) {
            finished = true;
            Image image = assembly.image();
            RenderSummary summary = assembly.summary((t2 - t1) / 1e9);
            try {
                output.commit(image);
            } catch (IOException | RuntimeException e) {
                fail("cannot write the image to " + output.target() + ": " + RenderReport.message(e));
                return;
            }
            long t3 = System.nanoTime();
            progress.clear();
            if (!o.quiet() && !o.json()) {
                out.println(RenderReport.summaryLine(name, output.target(), scene, settings, summary.stats, t3 - t0, t2 - t1));
                RenderReport.samplingLine(out, summary);
            }
            if (o.stats() && o.json()) {
                out.println(RenderReport.statsJson(name, output.target(), scene, settings, summary.stats, new long[] {t0, t1, t2, t3}, build,
                        bvhBytes, primitives, RenderReport.peakRssBytes(), RenderReport.processCpuNanos()));
            } else if (o.stats()) {
                out.println(RenderReport.statsLine(t1 - t0, build, t2 - t1 - build, t3 - t2, summary.stats, bvhBytes, primitives,
                        RenderReport.peakRssBytes(), RenderReport.processCpuNanos()));
            }
            if (summary.stats.invalidSamples > 0) {
                err.println(name + ": warning: " + summary.stats.invalidSamples + " samples were NaN or infinite and were left black");
            }
        }
    }

    /** Returns the exit status: 0 when every scene was written, 1 when any failed. */
    int run(List<Path> scenes) {
        int failed = 0;
        if (o.outputDir() != null) {
            try {
                Output.makeFolder(o.outputDir(), jsc.hadoopConfiguration());
            } catch (IOException | RuntimeException e) {
                err.println(RenderReport.oneLine(o.outputDir() + ": cannot write images there: " + RenderReport.message(e)));
                return 1;
            }
        }
        List<Job> jobs = new ArrayList<>();
        List<SceneBundle> bundles = new ArrayList<>();
        for (Path p : scenes) {
            Job j = read(p);
            if (j == null) {
                failed++;
                continue;
            }
            try {
                bundles.add(SceneBundle.of(p, j.scene, o.overrides()));
            } catch (IOException e) {
                j.fail("cannot read the scene's files: " + RenderReport.message(e));
                failed++;
                continue;
            }
            jobs.add(j);
        }
        if (jobs.isEmpty()) {
            return 1;
        }
        Broadcast<SceneBundle[]> shipped = jsc.broadcast(bundles.toArray(new SceneBundle[0]));
        try {
            List<Tasks.Task> tasks = new ArrayList<>();
            for (int i = 0; i < jobs.size(); i++) {
                Scene s = jobs.get(i).scene;
                for (int y = 0; y < s.height; y += o.tile()) {
                    for (int x = 0; x < s.width; x += o.tile()) {
                        tasks.add(Tasks.Task.tile(i, x, y, Math.min(s.width, x + o.tile()), Math.min(s.height, y + o.tile())));
                        jobs.get(i).tasks++;
                    }
                }
            }
            progress.start(tasks.size(), jobs.size());
            runTasks(tasks, jobs, shipped, "render");
            // the adaptive sampler's error probes, over each finished image
            List<Tasks.Task> probes = new ArrayList<>();
            for (int i = 0; i < jobs.size(); i++) {
                Job j = jobs.get(i);
                if (j.failure == null && !j.finished && j.adaptive() && j.assembly.complete()) {
                    for (SplitRender.ProbeTile t : j.assembly.probeTiles(o.tile())) {
                        probes.add(Tasks.Task.probes(i, t));
                        j.tasks++;
                    }
                    if (j.tasks == j.tasksDone) {
                        j.finish(System.nanoTime());
                    }
                }
            }
            if (!probes.isEmpty()) {
                progress.more(probes.size());
                runTasks(probes, jobs, shipped, "error probes");
            }
        } finally {
            progress.clear();
            shipped.destroy();
        }
        for (Job j : jobs) {
            if (!j.finished && j.failure == null) {
                j.fail("rendering failed: the Spark job ended before this scene's tiles were all rendered");
            }
            if (j.failure != null) {
                failed++;
            }
        }
        return failed == 0 ? 0 : 1;
    }

    /** Reads a scene on the driver as {@code raytracer} does (same messages); null (reported) when it cannot be rendered. */
    private Job read(Path p) {
        String name = p.toString();
        long t0 = System.nanoTime();
        Scene scene;
        List<String> warnings = new ArrayList<>();
        try {
            scene = Parser.parse(p, warnings);
        } catch (SceneFormatException e) {
            err.println(RenderReport.oneLine(e.getMessage()));
            return null;
        } catch (OutOfMemoryError e) {
            err.println(name + ": out of memory while reading the scene (raise the driver's heap, e.g. JAVA_OPTS=-Xmx16g)");
            return null;
        } catch (Throwable e) {       // a user's class (static initialiser, constructor, setter) or a parser bug
            err.println(RenderReport.oneLine(name + ": reading the scene failed: " + RenderReport.failure(e)));
            return null;
        }
        for (String w : warnings) {
            err.println(w);
        }
        RenderSettings settings = o.overrides().settings().resolve(scene);
        try {
            RenderPlan plan = RenderPlan.derive(scene, settings);
            if (!CostGate.check(name, plan, o.allowLong(), o.threads(), o.quiet(), err)) {
                return null;
            }
        } catch (RuntimeException e) {
            // a user's class failing in terms(): the render reports it, as raytracer does
        } catch (Throwable e) {       // the plan asks the scene's own classes about themselves
            err.println(RenderReport.oneLine(name + ": planning the render failed: " + RenderReport.failure(e)));
            return null;
        }
        Output output;
        try {
            output = Output.prepare(p, o.outputDir(), jsc.hadoopConfiguration(), ray.io.InputFiles.of(scene));
        } catch (IOException | RuntimeException e) {
            err.println(RenderReport.oneLine(name + ": cannot write the image: " + RenderReport.message(e)));
            return null;
        }
        return new Job(p, scene, settings, output, t0, System.nanoTime());
    }

    /** Runs the tasks as one Spark job, one task a partition, handing each result to its scene as it arrives. */
    private void runTasks(List<Tasks.Task> tasks, List<Job> jobs, Broadcast<SceneBundle[]> shipped, String what) {
        JavaRDD<Tasks.Task> rdd = jsc.parallelize(tasks, tasks.size());
        jsc.setJobDescription("raytracer-spark: " + what + " (" + jobs.size() + " scene(s), " + tasks.size() + " tasks)");
        try {
            jsc.sc().runJob(rdd.rdd(), new EachTask<>(new Tasks.Render(shipped, o.threads()), Tasks.Result.class), new OnResult(jobs),
                    EachTask.arrayTag(Tasks.Result.class));
        } catch (Exception e) {       // SparkException, thrown undeclared by Scala code
            // the job failed as a whole (a task lost spark.task.maxFailures times, the cluster gone): the
            // scenes not yet written fail with Spark's reason, the others are kept
            Throwable cause = !(e instanceof SparkException) && e.getCause() instanceof SparkException ? e.getCause() : e;
            String reason = firstLine(cause.getMessage());
            for (Job j : jobs) {
                if (!j.finished && j.failure == null) {
                    j.fail("rendering failed: the Spark job failed: " + reason);
                }
            }
        }
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "(no message)";
        }
        int n = s.indexOf('\n');
        return n < 0 ? s : s.substring(0, n);
    }

    /** The driver side: each partition's results, as they arrive (Spark calls this from one thread). */
    private final class OnResult extends AbstractFunction2<Object, Tasks.Result[], BoxedUnit> {
        private final List<Job> jobs;
        private final Set<Integer> seen = new HashSet<>();

        OnResult(List<Job> jobs) {
            this.jobs = jobs;
        }

        @Override
        public BoxedUnit apply(Object partition, Tasks.Result[] results) {
            if (!seen.add((Integer) partition)) {
                return BoxedUnit.UNIT;   // a speculative or rerun copy of a task already in
            }
            for (Tasks.Result r : results) {
                Job j = jobs.get(r.scene());
                j.take(r);
                if (j.failure == null && !j.finished && j.tasksDone == j.tasks && j.assembly.complete()
                        && (!j.adaptive() || j.tasks > countTiles(j))) {
                    j.finish(System.nanoTime());
                }
            }
            progress.done(results.length, jobs.stream().filter(j -> j.finished || j.failure != null).count());
            return BoxedUnit.UNIT;
        }

        /** The scene's tile tasks (its probe tasks come on top). */
        private int countTiles(Job j) {
            int tx = (j.scene.width + o.tile() - 1) / o.tile(), ty = (j.scene.height + o.tile() - 1) / o.tile();
            return tx * ty;
        }
    }
}
