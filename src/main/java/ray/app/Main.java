package ray.app;

import java.awt.GraphicsEnvironment;
import java.io.File;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import ray.Failures;
import ray.Scene;
import ray.accel.Bvh;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.Renderer;
import ray.settings.RenderSettings;

/**
 * The command line: {@code raytracer scene.txt [more.txt ...]} renders each scene to a PNG of the same
 * name beside it; with no scene the Swing viewer opens. Exit status 0 when every scene rendered,
 * 1 when any failed (each is reported on one line), 2 for a bad command line.
 */
@Command(name = "raytracer", mixinStandardHelpOptions = true, versionProvider = Main.Version.class,
        sortOptions = false, subcommands = ray.grade.GradeCommand.class,
        description = {"Renders each scene file to a PNG of the same name beside it (a.txt -> a.png).",
                "With no scene files, opens the viewer.",
                "A scene named '-' is read from standard input and its PNG goes to standard output (or -o).",
                "'--' ends the options (for a scene whose name starts with '-'); '@name' is a scene like any other."},
        exitCodeListHeading = "%nExit status:%n",
        exitCodeList = {"0:every scene rendered", "1:a scene could not be read or rendered", "2:bad command line",
                "130:interrupted (Ctrl+C); no partial PNG is left"})
public final class Main implements Callable<Integer> {

    @Parameters(paramLabel = "SCENE", description = "scene files (.txt) to render")
    List<Path> scenes = new ArrayList<>();

    /** --output as typed: Path drops a trailing '/', which says "a folder". */
    @Option(names = {"-o", "--output"}, paramLabel = "PNG", description = "where to write the image: a file (one scene), an existing folder (each scene's PNG in it) "
            + "or '-' (standard output)")
    String outputArg;
    /** --output as a path (set from outputArg when the command runs). */
    Path output;

    @Option(names = {"-j", "--threads"}, paramLabel = "N", description = "render threads (default: all cores)")
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

    @Option(names = {"--class-path", "-cp"}, paramLabel = "PATH", description = "also find the scene's classes (your own "
            + "compiled classes) in these folders and jars, ':'-separated, after the renderer's own; $CLASSPATH "
            + "does the same (read by the raytracer launcher)")
    String classPath;

    @Option(names = "--view", description = "open the viewer on the scene (a window for each) instead of writing a PNG")
    boolean view;

    /** Most render threads: more only cost memory and start-up (each a thread of its own, with its stack). */
    static final int MAX_THREADS = 1024;

    /** What {@link #run} returns when the viewer was opened: the JVM must keep running (no System.exit). */
    public static final int VIEWER_OPEN = -1;
    @Option(names = "--study", description = "accuracy study: render each scene with every sampler and setting, time it and "
            + "measure its error against a converged reference; report in --report-dir (default build/reports/accuracy)")
    boolean study;

    @Option(names = "--quick", description = "with --study: a smaller grid of settings (n_s up to 4)")
    boolean quick;

    @Option(names = "--full-size", description = "with --study: render every scene at its own size (default: scenes over "
            + "200 x 150 pixels are scaled down to that many, same camera)")
    boolean fullSize;

    @Option(names = "--report-dir", paramLabel = "DIR", description = "with --study: where the CSVs, plots and index.html go")
    Path reportDir;

    /** The command line as given (a long render starts the launcher again with it: {@link JitPolicy}). */
    private String[] args = new String[0];
    /** The exit status of the launcher started again for a long render ({@link JitPolicy}), or -1. */
    private int relaunched = -1;
    /** Whether this command may still start the launcher again: only before its first scene is rendered. */
    private boolean mayRelaunch;

    private PrintStream out = System.out;
    /** Whether a scene already said that standard output lost its image (then no second line says so). */
    boolean stdoutLossReported;
    private PrintStream err = System.err;
    private java.io.InputStream in = System.in;

    /** Runs the command line and returns the exit status (never calls System.exit). */
    public static int run(String... args) {
        return run(System.out, System.err, args);
    }

    public static int run(PrintStream out, PrintStream err, String... args) {
        return run(System.in, out, err, args);
    }

    /** As {@link #run(PrintStream, PrintStream, String...)}, reading the scene '-' from {@code in}. */
    static int run(java.io.InputStream in, PrintStream out, PrintStream err, String... args) {
        Main simple = simpleCommandLine(args);
        if (simple != null) {
            simple.args = args.clone();
            simple.in = in;
            simple.out = out;
            simple.err = err;
            return simple.call();
        }
        Main main = new Main();
        main.args = args.clone();
        main.in = in;
        main.out = out;
        main.err = err;
        CommandLine cl = new CommandLine(main);
        cl.setOut(new java.io.PrintWriter(out, true));
        cl.setErr(new java.io.PrintWriter(err, true));
        cl.setExpandAtFiles(false);            // a scene may be named @x.txt; picocli would read it as an argument file
        cl.setParameterExceptionHandler(ParameterErrors.to(err));
        return cl.execute(args);
    }

    /**
     * picocli's report of a bad command line, in one line. A class of its own, made through a method typed
     * with picocli's interface: a handler class written inside {@link #run} would make verifying Main load
     * that interface, a Java 5 class the class-data-sharing archive cannot hold, from picocli's jar in
     * every render, though the everyday command lines never reach picocli ({@link #simpleCommandLine}).
     */
    static final class ParameterErrors implements CommandLine.IParameterExceptionHandler {
        private final PrintStream err;

        private ParameterErrors(PrintStream err) {
            this.err = err;
        }

        static CommandLine.IParameterExceptionHandler to(PrintStream err) {
            return new ParameterErrors(err);
        }

        @Override
        public int handleParseException(CommandLine.ParameterException e, String[] a) {
            err.println(oneLine("raytracer: " + e.getMessage() + " (see raytracer --help)"));
            return 2;
        }
    }

    /**
     * The {@code raytracer} process: {@link #run} with the exit guard installed, so a user's class that
     * calls System.exit while its scene renders cannot end the run with a success status.
     */
    /** The process's real standard output, once {@link #runProcess} has moved System.out to stderr. */
    private static volatile PrintStream processStdout;

    public static int runProcess(String... args) {
        // Standard output carries only the image (-o -, the scene '-') or JSON Lines: what a user's class
        // prints there (System.out.println, the usual debug line in shade()) goes to stderr instead.
        PrintStream stdout = System.out;
        processStdout = stdout;
        System.setOut(new PrintStream(new java.io.FileOutputStream(java.io.FileDescriptor.err), true));
        ExitGuard.install(System.err);
        ExitGuard.active(true);
        int status = run(System.in, stdout, System.err, args);
        if (status != VIEWER_OPEN) {
            ExitGuard.active(false); // the status is ours now (RayTracer.main exits with it); the open viewer stays guarded
        }
        return status;
    }

    /**
     * The everyday command lines, read without picocli, whose start-up costs about 0.15 s of CPU
     * (it reflects over the annotations of the whole command): scene files, {@code -o/--output PNG},
     * {@code -j/--threads N}, {@code -q/--quiet}, {@code --stats} and {@code --json} (what {@code gradle bench}
     * runs), each option at most once, values
     * as separate words. Returns null for anything else (no arguments, help, version, other options,
     * repeated options, unusual values), which picocli then reads and reports exactly
     * as before.
     */
    static Main simpleCommandLine(String[] args) {
        if (args.length == 0 || args[0].equals("grade")) {
            return null;   // no scene, or the course grader's subcommand (ray.grade.GradeCommand)
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
                    case "--json" -> {
                        if (m.json) {
                            return null;
                        }
                        m.json = true;
                    }
                    case "-o", "--output" -> {
                        if (m.output != null || i + 1 == args.length || !plainWord(args[i + 1])) {
                            return null;
                        }
                        m.outputArg = args[++i];
                        m.output = Path.of(m.outputArg);
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

    /** Not an option, {@code -} or empty: a word picocli takes as a plain value ({@code @x.txt} too: no argument files). */
    private static boolean plainWord(String a) {
        return !a.isEmpty() && a.charAt(0) != '-';
    }

    @Override
    public Integer call() {
        if (classPath != null) {
            // the launcher takes the option out and puts the path on the JVM's class path; here the JVM
            // was started another way (java RayTracer, an IDE) and its class path is already fixed
            err.println(oneLine("raytracer: --class-path is read by the raytracer launcher (bin/raytracer); started with java, "
                    + "put the folder on java's own class path: java -cp \"" + classPath + File.pathSeparator + "<install>/lib/*\" RayTracer ..."));
            return 2;
        }
        if (outputArg != null) {
            try {
                output = Path.of(outputArg);
            } catch (java.nio.file.InvalidPathException e) {
                err.println(oneLine("raytracer: --output " + outputArg + " is not a file name (" + e.getReason() + ")"));
                return 2;
            }
        }
        if (threads < 1 || threads > MAX_THREADS) {
            err.println("raytracer: --threads must be 1 to " + MAX_THREADS + ", got " + threads);
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
        String conflict = conflict();
        if (conflict == null) {
            conflict = undecodableName();
        }
        if (conflict == null) {
            conflict = sceneProblem();
        }
        if (conflict != null) {
            err.println(oneLine("raytracer: " + conflict));
            return 2;
        }
        if (plan) {
            return outputChecked(PlanCommand.run(scenes, json, quiet, renderSettings(), in, out, err));
        }
        if (study) {
            if (scenes.isEmpty() || output != null) {
                err.println("raytracer: --study takes scene files and no --output (see --help)");
                return 2;
            }
            return outputChecked(ray.study.Study.run(scenes, quick, fullSize, reportDir != null ? reportDir : Path.of("build", "reports", "accuracy"),
                    threads, in, out, err, !this.quiet && err == System.err && Terminal.stderr(), TerminalWidth::columns,
                    name -> {            // a user's class calling System.exit is named with the scene being studied
                        if (name == null) {
                            ExitGuard.idle();
                        } else {
                            ExitGuard.working(name, null, "studied");
                        }
                    }));
        }
        if (scenes.isEmpty() || view) {
            return openViewer();
        }
        Outputs outputs;
        try {
            outputs = Outputs.of(scenes, outputArg, Terminal.stdout());
        } catch (Outputs.UsageException e) {
            err.println("raytracer: " + e.getMessage());
            return 2;
        }
        int failed = 0;
        mayRelaunch = in == System.in && out == (processStdout != null ? processStdout : System.out) && err == System.err
                && JitPolicy.launcher() != null;
        for (Path scene : scenes) {
            boolean ok = new SceneJob(this, scene, outputs).run();
            if (relaunched >= 0) {
                return relaunched;   // the launcher, started again under C2, ran the whole command line
            }
            mayRelaunch = false;
            if (!ok) {
                failed++;
            }
        }
        return outputChecked(failed == 0 ? 0 : 1);
    }

    /**
     * {@code status}, or 1 with a line when standard output lost what was written to it (a full disk,
     * {@code >/dev/full}, a closed pipe): the summary lines, --stats, --json, --plan and --study output
     * are the run's result, and losing them is a failure.
     */
    private int outputChecked(int status) {
        out.flush();
        if (out.checkError() && !stdoutLossReported) {
            err.println("raytracer: cannot write to standard output (closed, or the disk is full); its output is lost");
            return Math.max(status, 1);
        }
        return status;
    }

    /**
     * An option that would do nothing with the others given (refused, status 2, rather than silently
     * ignored), or null.
     */
    String conflict() {
        if (outputArg != null && outputArg.isEmpty()) {
            return "--output is empty (expected a file, an existing folder or '-')";
        }
        if (plan && study) {
            return "--plan and --study are different runs; give one of them";
        }
        String mode = plan ? "--plan" : study ? "--study" : null;
        if (mode != null && view) {
            return "--view does nothing with " + mode;
        }
        if (mode != null && stats) {
            return "--stats reports a render; it does nothing with " + mode;
        }
        if (plan && outputArg != null) {
            return "--output does nothing with --plan (nothing is rendered)";
        }
        if (plan && allowLong) {
            return "--allow-long does nothing with --plan (nothing is rendered)";
        }
        if (!study && (quick || fullSize || reportDir != null)) {
            return (quick ? "--quick" : fullSize ? "--full-size" : "--report-dir") + " goes with --study";
        }
        if (study && (sampling.sampler != null || sampling.samples != null || sampling.targetError != null || sampling.maxDepth != null
                || cutFaint || allowLong)) {
            return "--sampler, --samples, --target-error, --max-depth, --cut-faint and --allow-long do nothing with --study "
                    + "(it renders every sampler at every setting itself)";
        }
        if (view && outputArg != null) {
            return "--output does nothing with --view (save from the viewer's File menu)";
        }
        if (view && stats) {
            return "--stats does nothing with --view";
        }
        return null;
    }

    /**
     * A file name the JVM could not decode, or null. A name whose bytes are not valid UTF-8 (Latin-1, say)
     * reaches Java with U+FFFD in place of those bytes, so it names another file: a scene by it is "no
     * such file", an image by it would be written under a name the user never typed. The installed
     * launcher says so before the JVM starts; this catches {@code java RayTracer} started by hand. A name
     * with U+FFFD that exists as decoded (typed so, in UTF-8) is used.
     */
    String undecodableName() {
        List<String> names = new ArrayList<>();
        for (Path p : scenes) {   // (a loop, not forEach(lambda): no lambda on a render's path, StartupClassesTest)
            names.add(p.toString());
        }
        if (outputArg != null) {
            names.add(outputArg);
        }
        if (reportDir != null) {
            names.add(reportDir.toString());
        }
        for (String n : names) {
            if (n.indexOf('\uFFFD') >= 0 && !java.nio.file.Files.exists(Path.of(n), java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
                return "the name '" + n.replace('\uFFFD', '?') + "' is not valid UTF-8 (a name in another encoding, e.g. Latin-1), "
                        + "and Java cannot open a file by such a name: rename the file (e.g. convmv -f latin1 -t utf8), or give it by redirection: raytracer - < NAME "
                        + "reads a scene, raytracer -o - scene.txt > NAME writes an image";
            }
        }
        return null;
    }

    /**
     * A scene argument that cannot be meant, or null: an empty name, or one scene given twice (the same
     * file on disk however spelled: it would be read twice and its image written twice).
     */
    String sceneProblem() {
        java.util.Map<Object, Path> seen = new java.util.HashMap<>();
        int stdin = 0;
        for (Path p : scenes) {
            String s = p.toString();
            if (s.isEmpty()) {
                return "an empty scene name ('') (expected a scene file, or '-' for standard input)";
            }
            if (s.equals(Outputs.STDIN)) {
                if (++stdin > 1) {
                    return "standard input ('-') can be read only once";
                }
                continue;
            }
            Object key;
            try {
                key = java.nio.file.Files.readAttributes(p, java.nio.file.attribute.BasicFileAttributes.class).fileKey();
            } catch (java.io.IOException | RuntimeException e) {
                key = null;
            }
            if (key == null) {
                key = p.toAbsolutePath().normalize();
            }
            Path earlier = seen.putIfAbsent(key, p);
            if (earlier != null) {
                return "the scene " + p + " is given twice" + (earlier.toString().equals(s) ? "" : " (also as " + earlier + ")")
                        + "; give each scene once";
            }
        }
        return null;
    }

    /**
     * The viewer, or one line and status 2 when there is no display to show it on: none set, or one
     * that does not answer (a stale or unreachable DISPLAY makes AWT throw instead of saying headless).
     */
    private int openViewer() {
        String noDisplay = "raytracer: no display for the viewer; give scene files to render (see --help)";
        if (GraphicsEnvironment.isHeadless()) {
            err.println(noDisplay);
            return 2;
        }
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();   // connects to the display now
        } catch (java.awt.AWTError | java.awt.HeadlessException | InternalError | UnsatisfiedLinkError e) {
            String display = System.getenv("DISPLAY");
            err.println(oneLine(noDisplay.replace("viewer;", "viewer (" + (display == null ? "none found"
                    : "DISPLAY=" + display + " does not answer") + ");")));
            return 2;
        }
        ExitGuard.viewerOpen();      // the viewer's own exit (its windows closed) is ours; a user's class's is not
        ray.viewer.ViewingFrame.open(scenes, renderSettings());
        return VIEWER_OPEN;
    }

    /** The render options given (sampling, MaxDepth, --cut-faint), as settings each scene resolves against its globals. */
    RenderSettings renderSettings() {
        return sampling.settings().cutFaint(cutFaint);
    }

    PrintStream out() {
        return out;
    }

    /**
     * Before the first scene's first ray: when that render is long and the launcher allows it, runs the
     * whole command line again under C2 ({@link JitPolicy}) and returns true (its status is then this
     * command's); false to render here.
     */
    boolean relaunchedForLongRender(ray.plan.RenderPlan plan, String name, boolean fromStdin) {
        if (!mayRelaunch || fromStdin || !JitPolicy.isLong(plan, name, allowLong)) {
            return false;
        }
        return relaunchNow(JitPolicy.wantsWide(plan.scene().surfaces));
    }

    /**
     * What the parser of the first scene tells before it reads a Mesh's OBJ file, or null when this
     * process may not start the launcher again: {@link JitPolicy.BeforeMeshes} decides a long mesh render
     * there, before its large files are read ({@link JitPolicy#isLongBeforeFiles}).
     */
    ray.parse.BeforeFile beforeFiles() {
        return mayRelaunch ? new JitPolicy.BeforeMeshes(this) : null;
    }

    /**
     * Runs the whole command line again under C2, once, and returns true (its status is then this
     * command's), or false when this process may not or the launcher could not be started. {@code wide}:
     * the scene's tree is large enough for the SIMD traversal ({@link JitPolicy#wantsWide}).
     */
    boolean relaunchNow(boolean wide) {
        if (!mayRelaunch) {
            return false;
        }
        mayRelaunch = false;
        relaunched = JitPolicy.relaunch(JitPolicy.launcher(), args, wide);
        return relaunched >= 0;
    }

    PrintStream err() {
        return err;
    }

    java.io.InputStream in() {
        return in;
    }

    /** Keeps an error report on one line whatever an exception's message holds. */
    static String oneLine(String s) {
        return Failures.oneLine(s);
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
            return new String[] {"raytracer " + version() + " (Java " + System.getProperty("java.version") + ")"};
        }

        /** The build's version: ray/app/version.txt (written by the build), else the jar's manifest. */
        static String version() {
            try (java.io.InputStream in = Main.class.getResourceAsStream("version.txt")) {
                if (in != null) {
                    String v = new String(in.readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).trim();
                    if (!v.isEmpty()) {
                        return v;
                    }
                }
            } catch (java.io.IOException e) {
                // fall through to the manifest
            }
            String v = Main.class.getPackage().getImplementationVersion();
            return v == null ? "(development build: classes not built by Gradle)" : v;
        }
    }
}
