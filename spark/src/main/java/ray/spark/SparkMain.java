package ray.spark;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import org.apache.spark.api.java.JavaSparkContext;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import ray.app.RenderReport;
import ray.app.SamplingOptions;

/**
 * {@code raytracer-spark [--master URL] [-o DIR] scene.txt...}: {@code raytracer}'s render on an Apache
 * Spark cluster (or embedded, {@code local[*]}), and {@code --study}, the accuracy study's renders as
 * Spark tasks. Exit status 0 when every scene rendered, 1 when any failed, 2 for a bad command line.
 * Works as the main class of {@code spark-submit} too (the master then comes from spark-submit).
 */
@Command(name = "raytracer-spark", mixinStandardHelpOptions = true, versionProvider = SparkMain.Version.class, sortOptions = false,
        description = {"Renders each scene file to a PNG on an Apache Spark cluster: tiles as tasks, one job for all scenes.",
                "The images are raytracer's, pixel for pixel. Default master: local[*] (this machine, no cluster needed)."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every scene rendered", "1:a scene could not be read or rendered", "2:bad command line"},
        subcommands = GradeJob.class)
public final class SparkMain implements Callable<Integer> {

    /** Tile side in pixels (docs/scale-out.md: measured, 64 balances task overhead against load balance). */
    static final int DEFAULT_TILE = 64;

    @Parameters(paramLabel = "SCENE", description = "scene files (.txt) to render; with --study, - reads one from standard input")
    List<Path> scenes = new ArrayList<>();

    /** --master, --conf. */
    @CommandLine.Mixin
    ClusterOptions cluster = new ClusterOptions();

    @Option(names = {"-o", "--output"}, paramLabel = "DIR", description = "the folder the PNGs go into: a local folder or a Hadoop "
            + "file system URI (hdfs://..., s3a://..., file:/...); default: beside each scene")
    String output;

    @Option(names = "--tile", paramLabel = "N", description = "tile side in pixels, one task a tile (default: ${DEFAULT-VALUE}; "
            + "--study: its reference renders' tiles)")
    int tile = DEFAULT_TILE;

    @Option(names = {"-j", "--threads"}, paramLabel = "N", description = "render threads per task (default 1; also sets spark.task.cpus)")
    int threads = 1;

    /** --sampler, --samples, --target-error, --max-depth: raytracer's own options, with its checks. */
    @CommandLine.Mixin
    SamplingOptions sampling = new SamplingOptions();

    @Option(names = "--cut-faint", description = "stop mirror paths whose remaining weight is below half an 8-bit step: faster, not exact")
    boolean cutFaint;

    @Option(names = {"-q", "--quiet"}, description = "print nothing but errors")
    boolean quiet;

    @Option(names = "--stats", description = "print parse (driver), build (executor), render and write times, rays by kind")
    boolean stats;

    @Option(names = "--json", description = "with --stats: JSON Lines on stdout (raytracer's keys, docs/json.md)")
    boolean json;

    @Option(names = "--allow-long", description = "render even a scene whose plan bounds it above 1e11 rays")
    boolean allowLong;

    @Option(names = "--study", description = "the accuracy study (raytracer --study) with its renders as Spark tasks")
    boolean study;

    @Option(names = "--quick", description = "with --study: the smaller grid of settings")
    boolean quick;

    @Option(names = "--full-size", description = "with --study: every scene at its own size")
    boolean fullSize;

    @Option(names = "--report-dir", paramLabel = "DIR", description = "with --study: where the CSVs, plots and index.html go "
            + "(default build/reports/accuracy)")
    Path reportDir;

    PrintStream out = System.out;
    PrintStream err = System.err;
    /** Where the study's scene {@code -} is read from. */
    java.io.InputStream in = System.in;

    public static void main(String[] args) {
        int status = run(System.out, System.err, args);
        System.out.flush();
        System.exit(status);
    }

    /** Runs the command line and returns the exit status (never exits the JVM). */
    public static int run(PrintStream out, PrintStream err, String... args) {
        return run(System.in, out, err, args);
    }

    /** The same, the scene {@code -} (with --study) read from {@code in}. */
    public static int run(java.io.InputStream in, PrintStream out, PrintStream err, String... args) {
        SparkMain m = new SparkMain();
        m.in = in;
        m.out = out;
        m.err = err;
        CommandLine cl = new CommandLine(m);
        cl.setOut(new java.io.PrintWriter(out, true));
        cl.setErr(new java.io.PrintWriter(err, true));
        cl.setExpandAtFiles(false);
        cl.setParameterExceptionHandler((e, a) -> {
            String name = e.getCommandLine() == cl ? "raytracer-spark" : "raytracer-spark " + e.getCommandLine().getCommandName();
            err.println(RenderReport.oneLine(name + ": " + e.getMessage() + " (see " + name + " --help)"));
            return 2;
        });
        return cl.execute(args);
    }

    /** What is wrong with the options, or null. */
    String problem() {
        if (scenes.isEmpty()) {
            return "give scene files to render (see --help)";
        }
        if (tile < 1) {
            return "--tile must be at least 1";
        }
        if (threads < 1) {
            return "--threads must be at least 1";
        }
        if (sampling.problem() != null) {
            return sampling.problem();
        }
        if (json && !stats) {
            return "--json goes with --stats";
        }
        if (study && output != null) {
            return "--study writes its report to --report-dir, not --output";
        }
        if (cluster.problem() != null) {
            return cluster.problem();
        }
        long stdin = scenes.stream().filter(p -> p.toString().equals("-")).count();
        if (stdin > 1) {
            return "standard input ('-') can be read only once";
        }
        if (stdin > 0 && !study) {
            return "a scene from standard input ('-') is read by --study only; to render it, give its file (the PNG is named after it)";
        }
        if (!study) {
            Set<String> names = new LinkedHashSet<>();
            for (Path p : scenes) {
                String target = output == null ? p.toAbsolutePath().normalize().resolveSibling(Output.pngName(p)).toString() : Output.pngName(p);
                if (!names.add(target)) {
                    return "two scenes would write the same image " + target + (output == null ? "" : " in " + output);
                }
            }
        }
        return null;
    }

    @Override
    public Integer call() {
        String problem = problem();
        if (problem != null) {
            err.println(RenderReport.oneLine("raytracer-spark: " + problem));
            return 2;
        }
        byte[] stdin = null;
        if (scenes.stream().anyMatch(p -> p.toString().equals("-"))) {
            try {
                stdin = in.readAllBytes();   // before Spark starts: the driver ships these bytes as the scene's file
            } catch (java.io.IOException e) {
                err.println(RenderReport.oneLine("raytracer-spark: cannot read standard input: " + e.getMessage()));
                return 1;
            }
        }
        try (JavaSparkContext jsc = new JavaSparkContext(cluster.sparkConf(threads))) {
            if (study) {
                return StudyJob.run(jsc, scenes, quick, fullSize, reportDir != null ? reportDir : Path.of("build", "reports", "accuracy"),
                        threads, tile, stdin, out, err, !quiet && RenderReport.stderrIsTerminal());
            }
            RenderJob.Options o = new RenderJob.Options(output, tile, threads,
                    overrides(0), quiet, stats, json, allowLong);
            return new RenderJob(jsc, o, out, err, RenderReport.stderrIsTerminal()).run(scenes);
        }
    }

    /** The render options given, for each scene to resolve ({@code maxPixels}: the study's size limit, 0 for none). */
    SceneBundle.Overrides overrides(int maxPixels) {
        return new SceneBundle.Overrides(sampling.settings().cutFaint(cutFaint), maxPixels);
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"raytracer-spark (Spark " + org.apache.spark.package$.MODULE$.SPARK_VERSION() + ", Java "
                    + System.getProperty("java.version") + ")"};
        }
    }
}
