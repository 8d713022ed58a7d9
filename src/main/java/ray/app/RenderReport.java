package ray.app;

import ray.Failures;
import java.io.PrintStream;
import ray.RayStats;
import ray.Scene;
import ray.render.RenderSummary;
import ray.settings.RenderSettings;

/**
 * The lines {@code raytracer} prints about a rendered scene, for the commands that render elsewhere
 * ({@code raytracer-spark}) to print them the same way: the summary line, the sampler's line, the
 * {@code --stats} line and its {@code --json} object, and a failure described in one line.
 */
public final class RenderReport {

    private RenderReport() {
    }

    /**
     * {@code scene.txt -> scene.png (320x240, 2x2 AA, 1.25 s, 3.1 M rays/s: 1,200 camera, 0 shadow, 0 mirror rays)}:
     * {@code settings} the render's (resolved), {@code totalNanos} from the start to the image written,
     * {@code renderNanos} the render's share.
     */
    public static String summaryLine(String name, String target, Scene scene, RenderSettings settings, RayStats stats, long totalNanos,
                                     long renderNanos) {
        // plain concatenation, not printf: java.util.Formatter's first use loads locale data (~20 ms)
        return name + " -> " + target + " (" + scene.width + "x" + scene.height + ", " + settings.samples()
                + "x" + settings.samples() + " AA, " + Main.fixed(totalNanos, 2) + " s, "
                + SceneJob.raysPerSecond(stats.total(), renderNanos) + " rays/s: " + stats + ")";
    }

    /** The sampler's line under the summary (samples per pixel, estimated error), printed for every sampler but the grid. */
    public static void samplingLine(PrintStream out, RenderSummary summary) {
        SamplingOptions.report(out, summary);
    }

    /**
     * The {@code --stats} line: times of parsing, BVH build, rendering and writing, rays, peak memory,
     * BVH bytes per primitive (left out without primitives) and CPU time.
     */
    public static String statsLine(long parseNanos, long buildNanos, long renderNanos, long writeNanos, RayStats stats,
                                   long bvhBytes, long primitives, long peakRssBytes, long cpuNanos) {
        String bvh = primitives > 0 ? "; BVH " + Main.fixed(Math.round(1e9 * bvhBytes / primitives), 1) + " bytes/primitive" : "";
        return "  parse " + Main.fixed(parseNanos, 3) + " s, build " + Main.fixed(buildNanos, 3) + " s, render "
                + Main.fixed(renderNanos, 3) + " s, write " + Main.fixed(writeNanos, 3) + " s; " + stats
                + (peakRssBytes > 0 ? "; peak RSS " + (peakRssBytes >> 20) + " MiB" : "") + bvh + "; cpu " + Main.fixed(cpuNanos, 3) + " s";
    }

    /**
     * The {@code --stats --json} object (keys in docs/json.md). {@code t}: System.nanoTime() at start,
     * after parsing, after rendering and after writing.
     */
    public static String statsJson(String scenePath, String png, Scene scene, RenderSettings settings, RayStats stats, long[] t,
                                   long buildNanos, long bvhBytes, long primitives, long peakRssBytes, long cpuNanos) {
        return StatsJson.line(scenePath, png, scene, settings, stats, t, buildNanos, bvhBytes, primitives, peakRssBytes, cpuNanos);
    }

    /** This process's peak resident set size (0 where unknown). */
    public static long peakRssBytes() {
        return Main.peakRssBytes();
    }

    /** This process's CPU time so far (0 where unknown). */
    public static long processCpuNanos() {
        return Main.processCpuNanos();
    }

    /** A failure (most often a user's class throwing) in one line naming its class, message and method. */
    public static String failure(Throwable e) {
        return Failures.describe(e);
    }

    /** The message alone, for failures whose class says nothing (I/O). */
    public static String message(Throwable e) {
        return Failures.message(e);
    }

    /** {@code s} on one line whatever it holds. */
    public static String oneLine(String s) {
        return Main.oneLine(s);
    }

    /** Whether standard error is a terminal (progress lines go there only then). */
    public static boolean stderrIsTerminal() {
        return Terminal.stderr();
    }
}
