package ray.app;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import ray.Failures;
import ray.Scene;
import ray.accel.Bvh;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.PngEncoder;
import ray.io.InputFiles;
import ray.io.OutputFile;
import ray.render.PngWriter;
import ray.render.Renderer;
import ray.plan.CostGate;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * One scene of the command line: checks the scene file and the image's destination, reads the scene,
 * renders it and writes the PNG, reporting any failure as one line on stderr. Whatever a user's class
 * throws (any {@link Throwable}) fails this scene only; {@link #run} returns whether it succeeded.
 */
final class SceneJob {

    private final Main main;
    private final Path scenePath;
    private final String name;
    private final Outputs outputs;
    private final PrintStream out;
    private final PrintStream err;

    SceneJob(Main main, Path scenePath, Outputs outputs) {
        this.main = main;
        this.scenePath = scenePath;
        this.name = Outputs.isStdin(scenePath) ? "<stdin>" : scenePath.toString();
        this.outputs = outputs;
        this.out = main.out();
        this.err = main.err();
    }

    private boolean fail(String message) {
        err.println(Main.oneLine(message));
        return false;
    }

    boolean run() {
        try {
            return runChecked();
        } finally {
            ExitGuard.idle();
        }
    }

    private boolean runChecked() {
        boolean stdin = Outputs.isStdin(scenePath);
        if (!stdin) {
            String refusal = sceneRefusal(scenePath);
            if (refusal != null) {
                return fail(name + ": " + refusal);
            }
        }
        Outputs.Target target;
        OutputFile.Pending pending = null;
        try {
            target = outputs.target(scenePath);
            if (!target.stdout()) {
                outputs.checkIdentity(scenePath, target.path());
                pending = prepare(target.path());
                if (pending == null) {
                    return false;
                }
            }
        } catch (IOException e) {
            return fail(name + ": " + e.getMessage());
        }
        try {
            return render(target, pending);
        } finally {
            if (pending != null) {
                pending.abandon();
            }
        }
    }

    /**
     * Why the scene file cannot be read as a scene without waiting or reading something else, or
     * null. A missing file or a folder is left to the parser, which says so in its own words.
     */
    static String sceneRefusal(Path scene) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(scene, BasicFileAttributes.class);
        } catch (IOException | SecurityException e) {
            return null;
        }
        if (a.isRegularFile() || a.isDirectory()) {
            return null;
        }
        return "cannot read the scene: not a regular file (" + OutputFile.kind(scene)
                + "); to read a scene from a pipe give '-' and send it to standard input";
    }

    /** Checks the destination before anything is rendered; null (reported) if it cannot be written. */
    private OutputFile.Pending prepare(Path png) {
        try {
            return PngWriter.prepare(png);
        } catch (IOException e) {
            fail(png + ": cannot write the image: " + e.getMessage());
            return null;
        }
    }

    /** 830, 41.2 k, 3.1 M: rays a second, three significant digits at most. */
    static String raysPerSecond(long rays, long nanos) {
        double r = nanos > 0 ? rays * 1e9 / nanos : 0;
        if (r < 1e3) {
            return Long.toString(Math.round(r));
        }
        double v = r < 1e6 ? r / 1e3 : r < 1e9 ? r / 1e6 : r / 1e9;
        String unit = r < 1e6 ? " k" : r < 1e9 ? " M" : " G";
        return (v < 10 ? Main.fixed(Math.round(v * 1e9), 2) : v < 100 ? Main.fixed(Math.round(v * 1e9), 1)
                : Long.toString(Math.round(v))) + unit;
    }

    private boolean render(Outputs.Target target, OutputFile.Pending pending) {
        long t0 = System.nanoTime();
        Scene scene;
        List<String> warnings = new ArrayList<>();
        ExitGuard.working(name, null);
        try {
            scene = Outputs.isStdin(scenePath)
                    ? Parser.parse(main.in(), name, warnings) : Parser.parse(scenePath, warnings, main.beforeFiles());
        } catch (JitPolicy.Relaunched e) {
            return true;   // the launcher, started again under C2 before the meshes were read, ran the command line
        } catch (SceneFormatException e) {
            return fail(e.getMessage());
        } catch (OutOfMemoryError e) {
            return fail(name + ": out of memory while reading the scene (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
        } catch (Throwable e) {       // a user's class (static initialiser, constructor, setter) or a parser bug
            return fail(name + ": reading the scene failed: " + Failures.describe(e));
        }
        for (String w : main.quiet ? List.<String>of() : warnings) {    // -q: nothing but errors
            err.println(Main.oneLine(w));
        }
        if (pending != null) {
            try {
                pending.protect(InputFiles.of(scene));   // -o model.obj for a scene that reads model.obj
            } catch (IOException e) {
                return fail(target + ": cannot write the image: " + e.getMessage());
            }
        }
        RenderSettings settings = main.renderSettings().resolve(scene);
        String tooLarge = ray.settings.PixelBudget.refusal(scene.width, scene.height, settings.sampler());
        if (tooLarge != null) {       // e.g. --sampler adaptive on an image the grid's budget admitted
            return fail(name + ": " + tooLarge);
        }
        RenderPlan plan;
        try {
            plan = RenderPlan.derive(scene, settings);   // the render's own plan: the renderer follows it
        } catch (RuntimeException e) {
            plan = null;   // a user's class failing in terms(): the render reports it, as it would any failure of that class
        } catch (Throwable e) {       // the plan asks the scene's own classes about themselves
            return fail(name + ": planning the render failed: " + Failures.describe(e));
        }
        try {
            if (plan != null && main.relaunchedForLongRender(plan, name, Outputs.isStdin(scenePath))) {
                return true;   // (the launcher started again reports the plan's notes and the render)
            }
            // the estimate's pilot render runs only where the bound leaves room for a long render
            PilotEstimate pilot = new PilotEstimate(scene, settings, main.threads);
            if (plan != null && !CostGate.check(name, plan, main.allowLong, main.threads, main.quiet, err, pilot)) {
                return false;
            }
        } catch (Throwable e) {
            return fail(name + ": planning the render failed: " + Failures.describe(e));
        }
        long t1 = System.nanoTime();
        Renderer renderer = new Renderer(scene).threads(main.threads).settings(settings).plan(plan);
        ProgressLine progress = !main.quiet && err == System.err && Terminal.stderr()
                ? new ProgressLine(err, name, (long) scene.width * scene.height).start() : null;
        if (progress != null) {
            renderer.listener(progress);
        }
        ExitGuard.working(name, progress);
        Image image;
        try {
            image = renderer.render();
        } catch (OutOfMemoryError e) {
            String m = Failures.message(e);
            if (m != null && m.contains("native thread")) {    // not the heap: the system refused another thread
                return fail(name + ": cannot start " + main.threads + " render threads (the system refused: " + m
                        + "); give fewer with -j");
            }
            return fail(name + ": out of memory while rendering (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
        } catch (Throwable e) {       // e.g. a user's own material failing, whatever it throws
            return fail(name + ": rendering failed: " + Failures.describe(e));
        } finally {
            if (progress != null) {
                progress.clear();
            }
        }
        long t2 = System.nanoTime();
        PrintStream summary = out;
        try {
            if (target.stdout()) {
                PngEncoder.write(image, out);
                out.flush();
                if (out.checkError()) {
                    main.stdoutLossReported = true;   // one line for the loss, not a second from Main.outputChecked
                    return fail(name + ": cannot write the image to standard output (closed, or the disk is full); the image is lost");
                }
                summary = err;
            } else {
                if (!main.quiet && "a FIFO".equals(OutputFile.kind(target.path()))) {
                    err.println(Main.oneLine(name + ": writing the image into the FIFO " + target + " (waits until something reads it)"));
                }
                pending.commit(PngWriter.png(image));
                outputs.wrote(scenePath, target.path());
            }
        } catch (IOException | RuntimeException e) {
            return fail(target + ": cannot write the image: " + Failures.message(e));
        }
        long t3 = System.nanoTime();
        // plain concatenation, not printf: java.util.Formatter's first use loads locale data (~20 ms)
        if (!main.quiet && !main.json) {   // with --json, stdout holds JSON Lines only
            summary.println(RenderReport.summaryLine(Main.oneLine(name), Main.oneLine(target.toString()), scene, settings, renderer.stats(),
                    t3 - t0, t2 - t1));
            SamplingOptions.report(summary, renderer.summary());
        }
        if (main.stats && main.json) {
            summary.println(StatsJson.line(scenePath, target.stdout() ? Path.of("-") : target.path(), scene, settings, renderer.stats(),
                    new long[] {t0, t1, t2, t3}));
        } else if (main.stats) {
            long build = scene.accelerator() instanceof Bvh b ? b.buildNanos() : 0;
            long bytes = scene.accelerator() instanceof Bvh b ? b.memoryBytes() : 0;
            long primitives = scene.accelerator() instanceof Bvh b ? b.primitiveCount() : 0;
            summary.println(RenderReport.statsLine(t1 - t0, build, t2 - t1 - build, t3 - t2, renderer.stats(), bytes, primitives,
                    Main.peakRssBytes(), Main.processCpuNanos()));
        }
        if (renderer.stats().invalidSamples > 0 && !main.quiet) {
            err.println(Main.oneLine(name) + ": warning: " + renderer.stats().invalidSamples + " samples were NaN or infinite and were left black");
        }
        return true;
    }

    /**
     * The long-render note's estimate, asked for only when needed (a class, not a lambda: a lambda's
     * first call loads the method-handle machinery on every render's start).
     */
    private static final class PilotEstimate implements java.util.function.Supplier<ray.plan.RayEstimate> {
        private final Scene scene;
        private final RenderSettings settings;
        private final int threads;

        PilotEstimate(Scene scene, RenderSettings settings, int threads) {
            this.scene = scene;
            this.settings = settings;
            this.threads = threads;
        }

        @Override
        public ray.plan.RayEstimate get() {
            try {
                return ray.render.Pilot.estimate(scene, settings, threads);
            } catch (RuntimeException e) {
                return null;   // a user's class failing in the pilot fails the render itself, with its own line
            }
        }
    }
}
