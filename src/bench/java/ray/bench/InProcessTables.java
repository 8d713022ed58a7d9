package ray.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The benchmark's in-process tables, each measured in a fresh JVM running {@link Throughput}: rays
 * per second by kind from the acceleration structure alone (C1 as the launcher runs it, and C2), bytes
 * allocated per ray, and this program's traversal against Embree's ({@code peers/embree_rays.py}).
 */
final class InProcessTables {

    private final PrintStream out;
    private final Path work;
    private final Path benchDir;
    private final List<String> scenes;
    private final boolean withPeers;
    private final Peers peers;

    InProcessTables(PrintStream out, Path work, Path benchDir, List<String> scenes, boolean withPeers, Peers peers) {
        this.out = out;
        this.work = work;
        this.benchDir = benchDir;
        this.scenes = scenes;
        this.withPeers = withPeers;
        this.peers = peers;
    }

    /** The installed launcher's JVM options, as build.gradle hands them to this JVM (ray.bench.launcherJvmArgs). */
    private static List<String> launcherJvmArgs() {
        String a = System.getProperty("ray.bench.launcherJvmArgs", "-XX:+UseParallelGC -XX:TieredStopAtLevel=1").trim();
        return List.of(a.split("\\s+"));
    }

    /** A JVM like this one (its class path), running {@code ray.bench.Throughput} with the given JIT. */
    private static List<String> throughputCommand(boolean fullJit, String... args) {
        List<String> cmd = new ArrayList<>(List.of(ProcessHandle.current().info().command().orElse("java")));
        cmd.addAll(launcherJvmArgs());
        if (args.length > 0 && args[0].equals("--alloc")) {
            // every thread's allocation, the render threads' included (the renderer starts its own, even for
            // one): a collector that never collects and no thread-local buffers, so the heap's growth is
            // every byte any thread allocated (Throughput.allocationLine); the launcher's collector removed
            cmd.remove("-XX:+UseParallelGC");
            cmd.addAll(List.of("-XX:+UnlockExperimentalVMOptions", "-XX:+UseEpsilonGC", "-XX:-UseTLAB", "-Xms64m", "-Xmx12g",
                    "-Xlog:gc+init=off"));   // (Epsilon's advice on start-up, not for a measurement)
        }
        if (fullJit) {
            cmd.add("-XX:TieredStopAtLevel=4");   // the last one wins
            // as the launcher starts a long render of a large scene (RAYTRACER_SIMD=1): a tree of 1,024 inner
            // nodes or more traversed four boxes at a time (ray.accel.Wide4); the JVM's notice of the
            // incubator module is the log's first line
            cmd.addAll(List.of("--add-modules=jdk.incubator.vector", "-Dray.bvh.wide=true", "-XX:CompileCommand=quiet",
                    "-XX:CompileCommand=inline,ray.accel.Wide4::enter", "-XX:CompileCommand=inline,ray.accel.Wide4::planes",
                    "-XX:CompileCommand=inline,ray.accel.Wide4::sortEntered", "-XX:CompileCommand=dontinline,ray.accel.Wide4::*Hit*"));
        }
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "ray.bench.Throughput"));
        cmd.addAll(List.of(args));
        return cmd;
    }

    /** The rays-by-kind and allocation tables, and (with the peers' venv) the Embree comparison. */
    void print(java.util.Map<String, Path> scenePaths) throws IOException, InterruptedException {
        out.println("## Rays per second by kind, acceleration structure alone (1 thread, after warm-up)");
        out.println();
        out.println("Camera rays at pixel centres (closest hit with the hit record filled in) and every ray a render of "
                + "them casts, recorded by kind (shadow rays: any hit; the others: closest hit); median of 7 "
                + "passes, Mrays/s, each scene in a fresh JVM. C1: the launcher's JVM options (" + String.join(" ", launcherJvmArgs())
                + "); C2: the full JIT, for the steady state of a long render.");
        out.println();
        StringBuilder head = new StringBuilder("| scene, JIT |"), rule = new StringBuilder("|---|");
        for (ray.RayKind k : ray.RayKind.values()) {
            head.append(' ').append(k.key()).append(" |");
            rule.append("---:|");
        }
        out.println(head + " camera rays, any hit |");
        out.println(rule + "---:|");
        for (String s : scenes) {
            for (boolean c2 : new boolean[] {false, true}) {
                Path log = work.resolve("throughput.log");
                String name = s + ", " + (c2 ? "C2" : "C1");
                double t = Bench.time(throughputCommand(c2, "--row", name, scenePaths.get(s).toAbsolutePath().toString()), work, log);
                String row = null;
                for (String l : Files.readAllLines(log, StandardCharsets.UTF_8)) {
                    row = l.startsWith("|") ? l : row;
                }
                out.println(t >= 0 && row != null ? row : "| " + name + " | failed |  |  |  |");
            }
        }
        out.println();
        out.println("## Allocation on the hot path (a whole render on one thread, the launcher's JIT, after a warm-up render)");
        out.println();
        out.println("Heap bytes every thread allocated during the render (the render thread's included: Epsilon GC, which never "
                + "collects, and no thread-local allocation buffers, so the heap's growth is every byte), less the BVH "
                + "build's (measured alone the same way) and the image itself (24 bytes per pixel, allocated once). "
                + "C1 has no escape analysis, so nothing here is removed by the JIT. What is left is made once a render, "
                + "not once a ray: the camera's tables (32 bytes per image column and row for each of n_s), the thread's "
                + "context and packet.");
        out.println();
        out.println("| scene | rays | bytes allocated besides the image | bytes per ray |");
        out.println("|---|---:|---:|---:|");
        for (String s : scenes) {
            Path log = work.resolve("alloc.log");
            double t = Bench.time(throughputCommand(false, "--alloc", scenePaths.get(s).toAbsolutePath().toString()), work, log);
            String[] f = {};
            for (String l : Files.readAllLines(log, StandardCharsets.UTF_8)) {
                f = l.startsWith("alloc ") ? l.trim().split(" ") : f;
            }
            if (t < 0 || f.length != 5 || !f[0].equals("alloc")) {
                out.println("| " + s + " | failed |  |  |");
                continue;
            }
            out.println(String.format(Locale.ROOT, "| %s | %,d | %,d | %s |", s, Long.parseLong(f[2]),
                    Long.parseLong(f[3]) - Long.parseLong(f[4]), f[1]));
        }
        out.println();
        if (scenes.contains("mesh100k")) {
            embreeComparison(scenePaths.get("mesh100k"));
        }
    }

    /** Closest-hit and any-hit camera-ray rates {median, best} of this program in a fresh JVM with the full JIT. */
    private double[] ourCameraRates(Path scene) throws IOException, InterruptedException {
        Path log = work.resolve("camera.log");
        if (Bench.time(throughputCommand(true, "--camera", scene.toAbsolutePath().toString()), work, log) < 0) {
            return null;
        }
        double[] r = new double[4];
        for (String l : Files.readAllLines(log)) {
            String[] f = l.trim().split(" ");
            if (f.length == 3 && (f[0].equals("closest") || f[0].equals("any"))) {
                int o = f[0].equals("closest") ? 0 : 2;
                r[o] = Double.parseDouble(f[1]);
                r[o + 1] = Double.parseDouble(f[2]);
            }
        }
        return r;
    }

    private void embreeComparison(Path meshScene) {
        Path py = peers.venvPython(), script = benchDir.resolve("peers/embree_rays.py");
        if (!withPeers || !Files.isExecutable(py) || !Files.isRegularFile(script)) {
            return;
        }
        out.println("## Traversal against Embree (mesh100k camera rays, 1 thread, same session)");
        out.println();
        try {
            Path log = work.resolve("embree.log");
            double[] before = ourCameraRates(meshScene);
            double t = Bench.time(List.of(py.toString(), script.toAbsolutePath().toString(), meshScene.toAbsolutePath().toString()), benchDir, log);
            double[] after = ourCameraRates(meshScene);
            String text = Files.readString(log, StandardCharsets.UTF_8);
            double ec = embreeRate(text, "INTERSECT"), eo = embreeRate(text, "OCCLUDED");
            if (t < 0 || Double.isNaN(ec) || before == null || after == null) {
                out.println("embree_rays.py or the raytracer's measurement failed:\n```\n" + text + "```\n");
                return;
            }
            out.println("This program in a fresh JVM with the full JIT (C2), median of 9 passes after at least 5 warm-up passes (more, up to 40, while the JIT is still compiling), "
                    + "measured just before and just after Embree's run; Embree's median of 7 from embree_rays.py.");
            out.println();
            out.println("| query | raytracer Mrays/s (before / after) | Embree 4 Mrays/s | raytracer / Embree |");
            out.println("|---|---:|---:|---:|");
            out.println(String.format(Locale.ROOT, "| closest hit | %.2f / %.2f | %.2f | %.0f%% |", before[0], after[0], ec,
                    100 * 0.5 * (before[0] + after[0]) / ec));
            out.println(String.format(Locale.ROOT, "| any hit | %.2f / %.2f | %.2f | %.0f%% |", before[2], after[2], eo,
                    100 * 0.5 * (before[2] + after[2]) / eo));
            out.println();
            out.println("Embree's output:");
            out.println("```");
            out.print(text);
            out.println("```");
            out.println();
        } catch (IOException | InterruptedException e) {
            out.println("embree_rays.py could not be run: " + e);
        }
    }

    private static double embreeRate(String text, String query) {
        Matcher m = Pattern.compile(query + " +1 thread *: median [0-9.]+ s = ([0-9.]+) Mrays/s").matcher(text);
        return m.find() ? Double.parseDouble(m.group(1)) : Double.NaN;
    }
}
