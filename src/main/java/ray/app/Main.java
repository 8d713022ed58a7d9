package ray.app;

import java.awt.GraphicsEnvironment;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import ray.Scene;
import ray.accel.Bvh;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.PngWriter;
import ray.render.Renderer;

/**
 * The command line: {@code raytracer scene.txt [more.txt ...]} renders each scene to a PNG of the same
 * name beside it; with no scene the Swing viewer opens. Exit status 0 when every scene rendered,
 * 1 when any failed (each is reported on one line), 2 for a bad command line.
 */
@Command(name = "raytracer", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        sortOptions = false,
        description = {"Renders each scene file to a PNG of the same name beside it (a.txt -> a.png).",
                "With no scene files, opens the viewer."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every scene rendered", "1:a scene could not be read or rendered", "2:bad command line"})
public final class Main implements Callable<Integer> {

    @Parameters(paramLabel = "SCENE", description = "scene files (.txt) to render")
    List<Path> scenes = new ArrayList<>();

    @Option(names = {"-o", "--output"}, paramLabel = "PNG", description = "where to write the image (one scene only)")
    Path output;

    @Option(names = {"-j", "--threads"}, paramLabel = "N", description = "render threads (default: all cores, ${DEFAULT-VALUE})")
    int threads = Runtime.getRuntime().availableProcessors();

    @CommandLine.Mixin
    SamplingOptions sampling = new SamplingOptions();

    @Option(names = {"-q", "--quiet"}, description = "print nothing but errors")
    boolean quiet;

    @Option(names = "--stats", description = "print parse, build, render and write times, rays by kind, peak memory and BVH size")
    boolean stats;

    @Option(names = "--plan", description = "print each scene's render plan (effects, why, ray bounds, what the plan saves) without rendering")
    boolean plan;

    @Option(names = "--json", description = "with --plan or --stats: print JSON Lines on stdout instead, one object per scene (docs/json.md)")
    boolean json;

    @Option(names = "--cut-faint", description = "stop mirror paths whose remaining weight (product of k_m) is below half an 8-bit step: "
            + "faster, not exact (named in --plan)")
    boolean cutFaint;

    @Option(names = "--allow-long", description = "render even a scene whose plan bounds it above 1e11 rays (refused otherwise)")
    boolean allowLong;

    @Option(names = "--view", description = "open the viewer on the (first) scene instead of writing a PNG")
    boolean view;

    /** What {@link #run} returns when the viewer was opened: the JVM must keep running (no System.exit). */
    public static final int VIEWER_OPEN = -1;
    @Option(names = "--study", description = "accuracy study: render each scene with every sampler and setting, time it and "
            + "measure its error against a converged reference; report in --report-dir (default build/reports/accuracy)")
    boolean study;

    @Option(names = "--quick", description = "with --study: a smaller grid of settings (n_s up to 4)")
    boolean quick;

    @Option(names = "--report-dir", paramLabel = "DIR", description = "with --study: where the CSVs, plots and index.html go")
    Path reportDir;

    private PrintStream out = System.out;
    private PrintStream err = System.err;

    /** Runs the command line and returns the exit status (never calls System.exit). */
    public static int run(String... args) {
        return run(System.out, System.err, args);
    }

    public static int run(PrintStream out, PrintStream err, String... args) {
        Main simple = simpleCommandLine(args);
        if (simple != null) {
            simple.out = out;
            simple.err = err;
            return simple.call();
        }
        Main main = new Main();
        main.out = out;
        main.err = err;
        CommandLine cl = new CommandLine(main);
        cl.setOut(new java.io.PrintWriter(out, true));
        cl.setErr(new java.io.PrintWriter(err, true));
        return cl.execute(args);
    }

    /**
     * The everyday command lines, read without picocli, whose start-up costs about 0.15 s of CPU
     * (it reflects over the annotations of the whole command): scene files, {@code -o/--output PNG},
     * {@code -j/--threads N}, {@code -q/--quiet} and {@code --stats}, each option at most once, values
     * as separate words. Returns null for anything else (no arguments, help, version, other options,
     * {@code @files}, repeated options, unusual values), which picocli then reads and reports exactly
     * as before.
     */
    static Main simpleCommandLine(String[] args) {
        if (args.length == 0) {
            return null;
        }
        Main m = new Main();
        boolean threadsSet = false;
        try {
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                switch (a) {
                    case "-q", "--quiet" -> {
                        if (m.quiet) {
                            return null;
                        }
                        m.quiet = true;
                    }
                    case "--stats" -> {
                        if (m.stats) {
                            return null;
                        }
                        m.stats = true;
                    }
                    case "-o", "--output" -> {
                        if (m.output != null || i + 1 == args.length || !plainWord(args[i + 1])) {
                            return null;
                        }
                        m.output = Path.of(args[++i]);
                    }
                    case "-j", "--threads" -> {
                        if (threadsSet || i + 1 == args.length || !smallNumber(args[i + 1])) {
                            return null;
                        }
                        m.threads = Integer.parseInt(args[++i]);
                        threadsSet = true;
                    }
                    default -> {
                        if (!plainWord(a)) {
                            return null;
                        }
                        m.scenes.add(Path.of(a));
                    }
                }
            }
        } catch (java.nio.file.InvalidPathException e) {
            return null;
        }
        return m;
    }

    /** One to nine ASCII digits. */
    private static boolean smallNumber(String a) {
        if (a.isEmpty() || a.length() > 9) {
            return false;
        }
        for (int i = 0; i < a.length(); i++) {
            if (a.charAt(i) < '0' || a.charAt(i) > '9') {
                return false;
            }
        }
        return true;
    }

    /** Not an option, an {@code @file} or empty: a word picocli takes as a plain value. */
    private static boolean plainWord(String a) {
        return !a.isEmpty() && a.charAt(0) != '-' && a.charAt(0) != '@';
    }

    @Override
    public Integer call() {
        if (threads < 1) {
            err.println("raytracer: --threads must be at least 1");
            return 2;
        }
        if (sampling.problem() != null) {
            err.println("raytracer: " + sampling.problem());
            return 2;
        }
        if (json && !plan && !stats) {
            err.println("raytracer: --json goes with --plan or --stats");
            return 2;
        }
        if (plan) {
            return ray.plan.PlanCommand.run(scenes, json, scene -> {
                sampling.applyTo(scene);
                scene.planCutFaint(cutFaint);
            }, out, err);
        }
        if (study) {
            if (scenes.isEmpty() || output != null) {
                err.println("raytracer: --study takes scene files and no --output (see --help)");
                return 2;
            }
            return ray.study.Study.run(scenes, quick, reportDir != null ? reportDir : Path.of("build", "reports", "accuracy"),
                    threads, out, err, !this.quiet && System.console() != null);
        }
        if (output != null && scenes.size() != 1) {
            err.println("raytracer: --output needs exactly one scene file");
            return 2;
        }
        if (scenes.isEmpty() || view) {
            if (GraphicsEnvironment.isHeadless()) {
                err.println("raytracer: no display for the viewer; give scene files to render (see --help)");
                return 2;
            }
            ray.viewer.ViewingFrame.open(scenes.isEmpty() ? null : scenes.get(0));
            return VIEWER_OPEN;
        }
        int failed = 0;
        for (Path scene : scenes) {
            if (!renderOne(scene, output != null ? output : pngBeside(scene))) {
                failed++;
            }
        }
        return failed == 0 ? 0 : 1;
    }

    /** a.txt -> a.png in the same directory (a name without .txt gets .png appended). */
    static Path pngBeside(Path scene) {
        String name = scene.getFileName().toString();
        String base = name.endsWith(".txt") ? name.substring(0, name.length() - 4) : name;
        return scene.resolveSibling(base + ".png");
    }

    private boolean renderOne(Path scenePath, Path png) {
        if (png.toAbsolutePath().normalize().equals(scenePath.toAbsolutePath().normalize())) {
            err.println(scenePath + ": the output would overwrite the scene file itself");
            return false;
        }
        long t0 = System.nanoTime();
        Scene scene;
        List<String> warnings = new ArrayList<>();
        try {
            scene = Parser.parse(scenePath, warnings);
        } catch (SceneFormatException e) {
            err.println(e.getMessage());
            return false;
        } catch (RuntimeException e) {            // a parser bug: still one line, no stack trace
            err.println(oneLine(scenePath + ": internal error while reading the scene: " + describe(e) + " (please report it)"));
            return false;
        }
        for (String w : warnings) {
            err.println(w);
        }
        sampling.applyTo(scene);
        scene.planCutFaint(cutFaint);
        if (!ray.plan.CostGate.check(scenePath.toString(), scene, allowLong, threads, quiet, err)) {
            return false;
        }
        long t1 = System.nanoTime();
        Renderer renderer = new Renderer(scene).threads(threads);
        ProgressLine progress = !quiet && err == System.err && System.console() != null
                ? new ProgressLine(err, scenePath.toString()) : null;
        if (progress != null) {
            renderer.listener(progress);
        }
        Image image;
        try {
            image = renderer.render();
        } catch (OutOfMemoryError e) {
            err.println(scenePath + ": out of memory while rendering (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
            return false;
        } catch (RuntimeException | StackOverflowError e) {   // e.g. a user's own material failing
            StackTraceElement[] where = e.getStackTrace();      // point at the failing method
            err.println(oneLine(scenePath + ": rendering failed: " + describe(e) + (where.length == 0 ? "" : " at " + where[0])));
            return false;
        } finally {
            if (progress != null) {
                progress.clear();
            }
        }
        long t2 = System.nanoTime();
        try {
            PngWriter.write(image, png);
        } catch (java.io.IOException | RuntimeException e) {
            err.println(oneLine(png + ": cannot write the image (" + (e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage()) + ")"));
            return false;
        }
        long t3 = System.nanoTime();
        // plain concatenation, not printf: java.util.Formatter's first use loads locale data (~20 ms)
        if (!quiet && !json) {   // with --json, stdout holds JSON Lines only
            out.println(scenePath + " -> " + png + " (" + scene.width + "x" + scene.height + ", " + scene.samplesPerPixel
                    + "x" + scene.samplesPerPixel + " AA, " + fixed(t3 - t0, 2) + " s)");
            SamplingOptions.report(out, renderer.summary());
        }
        if (stats && json) {
            out.println(StatsJson.line(scenePath, png, scene, renderer.stats(), new long[] {t0, t1, t2, t3}));
        } else if (stats) {
            long build = scene.accelerator() instanceof Bvh b ? b.buildNanos() : 0;
            String bvh = scene.accelerator() instanceof Bvh b && b.primitiveCount() > 0
                    ? "; BVH " + fixed(Math.round(1e9 * b.memoryBytes() / b.primitiveCount()), 1) + " bytes/primitive" : "";
            long peak = peakRssBytes();
            out.println("  parse " + fixed(t1 - t0, 3) + " s, build " + fixed(build, 3) + " s, render " + fixed(t2 - t1 - build, 3)
                    + " s, write " + fixed(t3 - t2, 3) + " s; " + renderer.stats()
                    + (peak > 0 ? "; peak RSS " + (peak >> 20) + " MiB" : "") + bvh + "; cpu " + fixed(processCpuNanos(), 3) + " s");
        }
        if (renderer.stats().invalidSamples > 0) {
            err.println(scenePath + ": warning: " + renderer.stats().invalidSamples + " samples were NaN or infinite and were left black");
        }
        return true;
    }

    private static String describe(Throwable e) {
        return (e instanceof IllegalArgumentException || e instanceof IllegalStateException) && e.getMessage() != null
                ? e.getMessage() : e.getClass().getSimpleName() + (e.getMessage() == null ? "" : " (" + e.getMessage() + ")");
    }

    /** Keeps an error report on one line whatever an exception's message holds. */
    static String oneLine(String s) {
        return s.replaceAll("[\\p{Cntrl}\u2028\u2029]+", " ");
    }

    /** {@code nanos} as seconds with {@code digits} decimals (half up), without java.util.Formatter. */
    static String fixed(long nanos, int digits) {
        long scale = digits == 1 ? 10 : digits == 2 ? 100 : 1000;
        long units = (nanos * scale + 500_000_000L) / 1_000_000_000L;
        String frac = Long.toString(units % scale);
        while (frac.length() < digits) {
            frac = "0" + frac;
        }
        return units / scale + "." + frac;
    }

    /**
     * CPU time of this process so far (all threads: render, JIT compiler, GC), or 0 where unknown.
     * From /proc/self/stat on Linux (clock ticks, usually 10 ms): the management API would load
     * enough classes to add ~25 ms to the process being measured.
     */
    static long processCpuNanos() {
        try {
            String stat = new String(java.nio.file.Files.readAllBytes(Path.of("/proc/self/stat")), java.nio.charset.StandardCharsets.US_ASCII);
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).trim().split(" ");
            long ticks = Long.parseLong(f[11]) + Long.parseLong(f[12]);   // utime, stime (fields 14, 15)
            return ticks * 10_000_000L;   // USER_HZ is 100 on Linux
        } catch (java.io.IOException | RuntimeException e) {
            return 0;
        }
    }

    /** Peak resident set size of this process (VmHWM on Linux), or 0 where unknown. */
    static long peakRssBytes() {
        try {
            String status = new String(java.nio.file.Files.readAllBytes(Path.of("/proc/self/status")), java.nio.charset.StandardCharsets.US_ASCII);
            int i = status.indexOf("VmHWM:");
            if (i < 0) {
                return 0;
            }
            int e = status.indexOf("kB", i);
            return 1024 * Long.parseLong(status.substring(i + 6, e).trim());
        } catch (java.io.IOException | RuntimeException e) {
            return 0;   // not Linux: unknown
        }
    }

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"raytracer " + (v == null ? "(development build)" : v)};
        }
    }
}
