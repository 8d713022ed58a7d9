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

    @Option(names = {"-q", "--quiet"}, description = "print nothing but errors")
    boolean quiet;

    @Option(names = "--stats", description = "print parse and render times and rays by kind")
    boolean stats;

    @Option(names = "--view", description = "open the viewer on the (first) scene instead of writing a PNG")
    boolean view;

    /** What {@link #run} returns when the viewer was opened: the JVM must keep running (no System.exit). */
    public static final int VIEWER_OPEN = -1;

    private PrintStream out = System.out;
    private PrintStream err = System.err;

    /** Runs the command line and returns the exit status (never calls System.exit). */
    public static int run(String... args) {
        return run(System.out, System.err, args);
    }

    public static int run(PrintStream out, PrintStream err, String... args) {
        Main main = new Main();
        main.out = out;
        main.err = err;
        CommandLine cl = new CommandLine(main);
        cl.setOut(new java.io.PrintWriter(out, true));
        cl.setErr(new java.io.PrintWriter(err, true));
        return cl.execute(args);
    }

    @Override
    public Integer call() {
        if (threads < 1) {
            err.println("raytracer: --threads must be at least 1");
            return 2;
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
        warnings.forEach(err::println);
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
        if (!quiet) {
            out.printf("%s -> %s (%dx%d, %dx%d AA, %.2f s)%n", scenePath, png, scene.width, scene.height,
                    scene.samplesPerPixel, scene.samplesPerPixel, (t3 - t0) / 1e9);
        }
        if (stats) {
            out.printf("  parse %.3f s, render %.3f s, write %.3f s; %s%n", (t1 - t0) / 1e9, (t2 - t1) / 1e9,
                    (t3 - t2) / 1e9, renderer.stats());
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

    static final class Version implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            String v = Main.class.getPackage().getImplementationVersion();
            return new String[] {"raytracer " + (v == null ? "(development build)" : v)};
        }
    }
}
