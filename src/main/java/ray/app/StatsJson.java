package ray.app;

import java.nio.file.Path;
import ray.RayKind;
import ray.RayStats;
import ray.Scene;
import ray.accel.Bvh;
import ray.plan.JsonLine;
import ray.settings.RenderSettings;

/** {@code --stats --json}: one render's numbers as one JSON object (keys in docs/json.md). */
final class StatsJson {

    private StatsJson() {
    }

    /** {@code settings}: the render's, resolved. {@code t} holds System.nanoTime() at start, after parsing, after rendering and after writing. */
    static String line(Path scenePath, Path png, Scene scene, RenderSettings settings, RayStats stats, long[] t) {
        long build = scene.accelerator() instanceof Bvh b ? b.buildNanos() : 0;
        long bytes = scene.accelerator() instanceof Bvh b ? b.memoryBytes() : 0;
        long primitives = scene.accelerator() instanceof Bvh b ? b.primitiveCount() : 0;
        return line(scenePath.toString(), png.toString(), scene, settings, stats, t, build, bytes, primitives, Main.peakRssBytes(),
                Main.processCpuNanos());
    }

    /** As {@link #line(Path, Path, Scene, RenderSettings, RayStats, long[])}, with the build time, BVH size and process figures given. */
    static String line(String scenePath, String png, Scene scene, RenderSettings settings, RayStats stats, long[] t, long build,
                       long bvhBytes, long primitives, long peakRss, long cpuNanos) {
        double bytes = primitives > 0 ? Math.round(10.0 * bvhBytes / primitives) / 10.0 : 0;
        JsonLine j = new JsonLine().put("scene", scenePath).put("output", png)
                .put("width", scene.width).put("height", scene.height)
                .put("samplesPerPixel", settings.samples() * settings.samples())
                .put("maxDepth", settings.maxDepth());
        j.open("seconds").put("parse", seconds(t[1] - t[0])).put("build", seconds(build)).put("render", seconds(t[2] - t[1] - build))
                .put("write", seconds(t[3] - t[2])).put("total", seconds(t[3] - t[0])).close();
        j.put("cpuSeconds", seconds(cpuNanos)).put("peakRssBytes", peakRss).put("bvhBytesPerPrimitive", bytes);
        j.open("rays");
        for (RayKind k : RayKind.values()) {
            j.put(k.key(), stats.get(k));
        }
        j.close().put("invalidSamples", stats.invalidSamples);
        return j.toString();
    }

    /** Nanoseconds as seconds, rounded to the microsecond. */
    private static double seconds(long nanos) {
        return Math.round(nanos / 1e3) / 1e6;
    }
}
