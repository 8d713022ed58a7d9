package ray.bench;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import ray.RayKind;
import ray.Scene;
import ray.parse.Parser;

/**
 * {@code raytracer --bench}: renders the benchmark scenes ({@code classic}, {@code mirrors},
 * {@code spheres10k}, {@code mesh100k} from the shared bench directory) as whole processes, the way a
 * user waits for them, and prints Markdown tables:
 * <ul>
 * <li>wall time (median of the timed runs, after one warm-up run), the process's CPU time, and the
 * parse / build / render / write split, rays cast by kind, render rays per second, peak RSS and BVH
 * bytes per primitive, as the child process reports them with {@code --stats};</li>
 * <li>rays per second by kind from the acceleration structure alone (in this process, one thread,
 * after warm-up; {@link Throughput});</li>
 * <li>with {@code --peers}: the installed peer renderers (POV-Ray, Tachyon, Sunflow, Mitsuba 3, as
 * {@code peers/run_peers.sh} runs them) timed in the same rounds, interleaved with this program, and
 * the ratio of this program's median to each peer's; and Embree's closest-hit and any-hit rates
 * ({@code peers/embree_rays.py}) next to this program's on the mesh100k camera rays.</li>
 * </ul>
 * Timings on a shared machine move by tens of percent; only the ratios measured in one run, with
 * the load and the two-process parallel check printed beside them, compare. Benchmarks are a
 * command, never a test.
 */
public final class Bench {

    public static final List<String> SCENES = List.of("classic", "mirrors", "spheres10k", "mesh100k");
    private static final List<String> PEERS = List.of("pov", "tachyon", "sunflow", "mitsuba_llvm");
    private static final Map<String, String> PEER_NAMES = Map.of(
            "pov", "POV-Ray 3.7", "tachyon", "Tachyon", "sunflow", "Sunflow (Java)", "mitsuba_llvm", "Mitsuba 3 (LLVM)");

    private final PrintStream out;
    private final PrintStream err;
    private final int runs;
    private final boolean withPeers;
    private final Path benchDir;
    private final Path work;
    private final List<String> scenes;
    /** The command that starts the installed program (its launcher). */
    private final List<String> self;
    /** Another build timed in the same rounds ({@code --baseline}), or null. */
    private Baseline baseline;

    public Bench(PrintStream out, PrintStream err, int runs, boolean withPeers, Path benchDir, Path work, List<String> scenes,
                 List<String> self) {
        this.out = out;
        this.err = err;
        this.runs = runs;
        this.withPeers = withPeers;
        this.benchDir = benchDir;
        this.work = work;
        this.scenes = scenes;
        this.self = self;
    }

    /**
     * {@code gradle bench}: {@code ray.bench.Bench --launcher PATH [--runs N] [--peers] [--baseline PATH]
     * [--bench-dir DIR] [--bench-scenes LIST] [--bench-work DIR]}; the launcher is the installed
     * {@code bin/raytracer}, the baseline another build's ({@link Baseline}).
     */
    public static void main(String[] args) {
        System.exit(run(System.out, System.err, args));
    }

    static int run(PrintStream out, PrintStream err, String... args) {
        int runs = 3;
        boolean peers = false;
        Path benchDir = null, work = defaultWork();
        String list = null, launcher = null, base = null;
        try {
            for (int i = 0; i < args.length; i++) {
                String a = args[i];
                if (a.equals("--peers")) {
                    peers = true;
                    continue;
                }
                if (i + 1 >= args.length) {
                    throw new IllegalArgumentException("unknown option or missing value: " + a);
                }
                String v = args[++i];
                switch (a) {
                    case "--runs" -> runs = Integer.parseInt(v);
                    case "--bench-dir" -> benchDir = Path.of(v);
                    case "--bench-scenes" -> list = v;
                    case "--bench-work" -> work = Path.of(v);
                    case "--launcher" -> launcher = v;
                    case "--baseline" -> base = v;
                    default -> throw new IllegalArgumentException("unknown option " + a);
                }
            }
            if (runs < 1) {
                throw new IllegalArgumentException("--runs must be at least 1");
            }
            if (launcher == null || !Files.isExecutable(Path.of(launcher))) {
                throw new IllegalArgumentException("--launcher must name the installed bin/raytracer (gradle bench does)");
            }
            if (base != null && !Files.isExecutable(Path.of(base))) {
                throw new IllegalArgumentException("--baseline must name another build's bin/raytracer, not " + base);
            }
            Bench b = new Bench(out, err, runs, peers, findBenchDir(benchDir), work, sceneList(list), List.of(launcher));
            b.baseline = base == null ? null : new Baseline(base);
            return b.run();
        } catch (IllegalArgumentException e) {
            err.println("bench: " + e.getMessage());
            return 2;
        } catch (IOException e) {
            err.println("bench: " + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 1;
        }
    }

    /** The bench directory to use: the option, $RAYTRACER_BENCH_DIR, or ../shared/bench or shared/bench from here. */
    public static Path findBenchDir(Path option) {
        if (option != null) {
            return option;
        }
        String env = System.getenv("RAYTRACER_BENCH_DIR");
        if (env != null && !env.isEmpty()) {
            return Path.of(env);
        }
        for (String c : new String[] {"../shared/bench", "shared/bench", "bench"}) {
            if (Files.isDirectory(Path.of(c, "gen")) || Files.isDirectory(Path.of(c, "scenes"))) {
                return Path.of(c);
            }
        }
        return Path.of("../shared/bench");
    }

    /**
     * Runs the benchmark; returns the exit status (0, or 1 when a scene could not be rendered). The
     * report also goes to {@code bench.md} in the work directory.
     */
    public int run() throws IOException, InterruptedException {
        Files.createDirectories(work);
        try (java.io.OutputStream file = Files.newOutputStream(work.resolve("bench.md"))) {
            PrintStream console = out;
            PrintStream both = new PrintStream(new java.io.OutputStream() {
                @Override
                public void write(int b) throws IOException {
                    console.write(b);
                    file.write(b);
                }

                @Override
                public void write(byte[] b, int off, int len) throws IOException {
                    console.write(b, off, len);
                    file.write(b, off, len);
                }

                @Override
                public void flush() throws IOException {
                    console.flush();
                    file.flush();
                }
            }, true, StandardCharsets.UTF_8);
            Bench b = new Bench(both, err, runs, withPeers, benchDir, work, scenes, self);
            b.baseline = baseline;
            return b.report();
        }
    }

    private int report() throws IOException, InterruptedException {
        Path sceneDir = sceneDirectory();
        out.println("# gradle bench");
        out.println();
        out.println("- command: `" + String.join(" ", self) + " -q --stats --json SCENE -o PNG`");
        out.println("- scenes: " + sceneDir.toAbsolutePath().normalize());
        out.println("- machine: " + Runtime.getRuntime().availableProcessors() + " cores, " + cpuName() + "; "
                + System.getProperty("java.vm.name") + " " + System.getProperty("java.version"));
        out.println("- load average before: " + loadAverage() + "; parallel check (2 processes' wall / 1; 1.0 = two free cores): "
                + String.format(Locale.ROOT, "%.2f", parallelCheck()));

        Map<String, List<String>> peerCmds = new LinkedHashMap<>();
        if (withPeers) {
            for (String p : PEERS) {
                if (peerAvailable(p)) {
                    peerCmds.put(p, null);
                } else {
                    out.println("- peer " + PEER_NAMES.get(p) + ": not installed or not translated in " + benchDir
                            + " (bash peers/run_peers.sh install scenes translate), left out");
                }
            }
        }
        out.println("- rounds: 1 warm-up + " + runs + " timed; in each round every scene runs once with this program"
                + (baseline == null ? "" : " and with the baseline (alternating which goes first)")
                + (peerCmds.isEmpty() ? "" : " and then each peer, one after the other (interleaved)"));
        out.println();

        Map<String, Map<String, List<Double>>> times = new LinkedHashMap<>();
        Map<String, List<Stats>> stats = new LinkedHashMap<>();
        int failures = 0;
        for (int round = 0; round <= runs; round++) {
            for (String s : scenes) {
                Path scene = sceneDir.resolve(s + ".txt");
                List<String> cmd = new ArrayList<>(self);
                cmd.addAll(List.of("-q", "--stats", "--json", scene.toAbsolutePath().toString(), "-o", work.resolve(s + ".png").toAbsolutePath().toString()));
                Path log = work.resolve(s + ".log");
                double[] base = null;
                if (baseline != null && Baseline.baselineFirst(round)) {
                    base = timeBaseline(s, scene);
                }
                double cpu0 = Baseline.childCpuSeconds();
                double t = time(cmd, work, log);
                double cpu = Baseline.childCpuSeconds() - cpu0;
                if (baseline != null && base == null) {
                    base = timeBaseline(s, scene);
                }
                String text = Files.readString(log, StandardCharsets.UTF_8);
                Stats st = Stats.parse(text);
                if (t < 0 || st == null) {
                    err.println("bench: " + s + ": the render failed:\n" + text);
                    failures++;
                    continue;
                }
                if (round > 0) {
                    times.computeIfAbsent(s, k -> new LinkedHashMap<>()).computeIfAbsent("raytracer", k -> new ArrayList<>()).add(t);
                    stats.computeIfAbsent(s, k -> new ArrayList<>()).add(st);
                    if (base != null && base[0] >= 0) {
                        baseline.record(s, t, cpu, base[0], base[1]);
                    }
                }
                for (String p : peerCmds.keySet()) {
                    double pt = time(peerCommand(p, s), benchDir, work.resolve(s + "_" + p + ".log"));
                    if (round > 0 && pt >= 0) {
                        times.get(s).computeIfAbsent(p, k -> new ArrayList<>()).add(pt);
                    }
                }
            }
        }
        out.println("- load average after: " + loadAverage() + "; parallel check: " + String.format(Locale.ROOT, "%.2f", parallelCheck()));
        out.println();
        printProcessTable(times, stats);
        if (baseline != null) {
            baseline.print(out, scenes);
        }
        if (!peerCmds.isEmpty()) {
            printPeerTable(times, peerCmds.keySet());
        }
        printKindTable(sceneDir);
        return failures == 0 ? 0 : 1;
    }

    // ---- scenes ----

    private Path sceneDirectory() throws IOException, InterruptedException {
        return sceneDirectory(benchDir, work, scenes, out);
    }

    /** The default work directory: raytracer-bench in the temporary directory. */
    public static Path defaultWork() {
        return Path.of(System.getProperty("java.io.tmpdir"), "raytracer-bench");
    }

    /**
     * The directory holding the named benchmark scenes: the bench directory's scenes/, or {@code work}/scenes,
     * where they are generated with the bench's gen/make_scenes.py (mesh100k.txt is not kept in the
     * repository) when missing.
     */
    public static Path sceneDirectory(Path benchDir, Path work, List<String> scenes, PrintStream out)
            throws IOException, InterruptedException {
        Path shared = benchDir.resolve("scenes");
        if (scenes.stream().allMatch(s -> Files.isRegularFile(shared.resolve(s + ".txt")))) {
            return shared;
        }
        Path generated = work.resolve("scenes");
        if (scenes.stream().allMatch(s -> Files.isRegularFile(generated.resolve(s + ".txt")))) {
            return generated;
        }
        Path gen = benchDir.resolve("gen/make_scenes.py");
        if (!Files.isRegularFile(gen)) {
            throw new IOException("no benchmark scenes in " + shared + " and no generator " + gen
                    + " (give the bench directory with --bench-dir)");
        }
        // the generator writes next to itself (../scenes): run a copy in the work directory
        Path genCopy = work.resolve("gen/make_scenes.py");
        Files.createDirectories(genCopy.getParent());
        Files.copy(gen, genCopy, StandardCopyOption.REPLACE_EXISTING);
        out.println("- generating the benchmark scenes (mesh100k.txt is 15 MB, not kept in the repository) with " + gen);
        Process p = new ProcessBuilder("python3", genCopy.toAbsolutePath().toString()).directory(work.toFile())
                .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        if (p.waitFor() != 0) {
            throw new IOException("python3 " + gen + " failed");
        }
        return generated;
    }

    // ---- processes ----


    /** Wall seconds of one run of {@code cmd} (stdout and stderr to {@code log}); -1 when it failed. */
    private static double time(List<String> cmd, Path dir, Path log) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        long t0 = System.nanoTime();
        Process p = pb.start();
        int rc = p.waitFor();
        long t1 = System.nanoTime();
        return rc == 0 ? (t1 - t0) / 1e9 : -1;
    }

    /** Wall and CPU seconds of the baseline build rendering {@code scene} (wall -1: it failed). */
    private double[] timeBaseline(String s, Path scene) throws IOException, InterruptedException {
        double cpu0 = Baseline.childCpuSeconds();
        double t = time(baseline.command(scene, work.resolve(s + "_baseline.png")), work, work.resolve(s + "_baseline.log"));
        double cpu = Baseline.childCpuSeconds() - cpu0;
        if (t < 0) {
            err.println("bench: " + s + ": the baseline failed (see " + work.resolve(s + "_baseline.log") + ")");
        }
        return new double[] {t, cpu};
    }

    private Path venvPython() {
        String v = System.getenv("VENV");
        Path venv = v != null && !v.isEmpty() ? Path.of(v) : benchDir.resolve("peers/.venv");
        if (!venv.isAbsolute()) {
            venv = benchDir.resolve(venv);
        }
        return venv.resolve("bin/python");
    }

    private boolean peerAvailable(String p) {
        String first = scenes.get(0);
        switch (p) {
            case "pov":
                return onPath("povray") && Files.isRegularFile(benchDir.resolve("peers/build/pov/" + first + ".pov"));
            case "tachyon":
                return onPath("tachyon-nox") && Files.isRegularFile(benchDir.resolve("peers/build/tachyon/" + first + ".dat"));
            case "sunflow":
                return Files.isRegularFile(Path.of("/usr/share/java/sunflow.jar"))
                        && Files.isRegularFile(benchDir.resolve("peers/sunflow/SunflowRender.class"))
                        && Files.isRegularFile(benchDir.resolve("peers/build/sunflow/" + first + ".sc"));
            default:
                return Files.isExecutable(venvPython()) && Files.isRegularFile(benchDir.resolve("peers/build/mitsuba/" + first + ".xml"));
        }
    }

    /** The command line run_peers.sh uses for a peer (run in the bench directory). */
    private List<String> peerCommand(String p, String s) {
        String png = work.resolve("peer_" + p + ".png").toAbsolutePath().toString();
        switch (p) {
            case "pov":
                return List.of("povray", "peers/build/pov/" + s + ".ini", "+Ipeers/build/pov/" + s + ".pov", "+O" + png);
            case "tachyon":
                return List.of("tachyon-nox", "peers/build/tachyon/" + s + ".dat", "-format", "PNG", "-o", png);
            case "sunflow":
                return List.of("java", "-cp", "/usr/share/java/sunflow.jar:peers/sunflow", "SunflowRender",
                        "peers/build/sunflow/" + s + ".sc", png);
            default:
                return List.of(venvPython().toString(), "peers/mitsuba_whitted.py", "llvm_ad_rgb", "peers/build/mitsuba/" + s + ".xml", png);
        }
    }

    private static boolean onPath(String exe) {
        String path = System.getenv("PATH");
        if (path == null) {
            return false;
        }
        for (String d : path.split(":")) {
            if (!d.isEmpty() && Files.isExecutable(Path.of(d, exe))) {
                return true;
            }
        }
        return false;
    }

    // ---- the child's --stats line ----

    /** What one render reported with --stats. (Not a record: Gradle 4.4.1's class reader calls those malformed.) */
    /**
     * One render's numbers, read from the JSON object the launcher prints with {@code --stats --json}
     * (keys in docs/json.md; rays by {@link RayKind#key()}).
     */
    static final class Stats {
        final double parse, build, render, write, bvhBytes, cpu;
        final long peakMiB;
        final long[] rays = new long[RayKind.values().length];

        private Stats(JsonObject o) {
            JsonObject sec = o.getAsJsonObject("seconds");
            parse = sec.get("parse").getAsDouble();
            build = sec.get("build").getAsDouble();
            render = sec.get("render").getAsDouble();
            write = sec.get("write").getAsDouble();
            cpu = o.get("cpuSeconds").getAsDouble();
            peakMiB = o.get("peakRssBytes").getAsLong() >> 20;
            bvhBytes = o.get("bvhBytesPerPrimitive").getAsDouble();
            JsonObject r = o.getAsJsonObject("rays");
            for (RayKind k : RayKind.values()) {
                rays[k.ordinal()] = r.get(k.key()).getAsLong();
            }
        }

        /** The stats object in a child's output (the line that is a JSON object), or null. */
        static Stats parse(String text) {
            for (String line : text.split("\n")) {
                if (line.startsWith("{")) {
                    try {
                        return new Stats(JsonParser.parseString(line).getAsJsonObject());
                    } catch (RuntimeException e) {   // malformed or a key missing: not the stats line
                        return null;
                    }
                }
            }
            return null;
        }

        long rays(RayKind k) {
            return rays[k.ordinal()];
        }

        long rays() {
            long n = 0;
            for (long r : rays) {
                n += r;
            }
            return n;
        }
    }

    // ---- tables ----

    private static double median(List<Double> v) {
        double[] a = v.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        return a.length == 0 ? Double.NaN : a.length % 2 == 1 ? a[a.length / 2] : 0.5 * (a[a.length / 2 - 1] + a[a.length / 2]);
    }

    private static double medianOf(List<Stats> l, java.util.function.ToDoubleFunction<Stats> f) {
        List<Double> v = new ArrayList<>();
        for (Stats s : l) {
            v.add(f.applyAsDouble(s));
        }
        return median(v);
    }

    /** "camera 1.23, shadow 0.40, mirror 0.00" (millions), every kind but those no run cast. */
    private static String raysByKind(Stats a) {
        StringBuilder b = new StringBuilder();
        for (RayKind k : RayKind.values()) {
            if (a.rays(k) != 0 || k.ordinal() <= RayKind.MIRROR.ordinal()) {
                b.append(b.length() == 0 ? "" : ", ").append(k.key()).append(' ')
                        .append(String.format(Locale.ROOT, "%.2f", a.rays(k) / 1e6));
            }
        }
        return b.toString();
    }

    private void printProcessTable(Map<String, Map<String, List<Double>>> times, Map<String, List<Stats>> stats) {
        out.println("## Whole process (median of " + runs + "; the split and memory as the process reports them)");
        out.println();
        out.println("| scene | wall s | cpu s | parse s | build s | render s | write s | rays by kind (M) | render Mrays/s (all threads) | peak RSS MiB | BVH bytes/primitive |");
        out.println("|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|");
        for (String s : scenes) {
            List<Stats> l = stats.get(s);
            if (l == null || l.isEmpty()) {
                out.println("| " + s + " | failed |  |  |  |  |  |  |  |  |  |");
                continue;
            }
            Stats a = l.get(0);
            double render = medianOf(l, x -> x.render);
            out.println(String.format(Locale.ROOT, "| %s | %.2f | %.2f | %.3f | %.3f | %.3f | %.3f | %s | %.1f | %.0f | %.1f |",
                    s, median(times.get(s).get("raytracer")), medianOf(l, x -> x.cpu), medianOf(l, x -> x.parse),
                    medianOf(l, x -> x.build), render, medianOf(l, x -> x.write), raysByKind(a),
                    a.rays() / render / 1e6, medianOf(l, x -> x.peakMiB), a.bvhBytes));
        }
        out.println();
    }

    private void printPeerTable(Map<String, Map<String, List<Double>>> times, java.util.Set<String> peers) {
        out.println("## Against the peers (whole process, median of " + runs + ", interleaved in the same rounds)");
        out.println();
        StringBuilder h = new StringBuilder("| scene | raytracer s |");
        StringBuilder sep = new StringBuilder("|---|---:|");
        for (String p : peers) {
            h.append(' ').append(PEER_NAMES.get(p)).append(" s | ratio |");
            sep.append("---:|---:|");
        }
        out.println(h);
        out.println(sep);
        for (String s : scenes) {
            Map<String, List<Double>> t = times.get(s);
            if (t == null) {
                continue;
            }
            double ours = median(t.getOrDefault("raytracer", List.of()));
            StringBuilder row = new StringBuilder(String.format(Locale.ROOT, "| %s | %.2f |", s, ours));
            for (String p : peers) {
                double theirs = median(t.getOrDefault(p, List.of()));
                row.append(String.format(Locale.ROOT, " %.2f | %.2f |", theirs, ours / theirs));
            }
            out.println(row);
        }
        out.println();
        out.println("ratio = raytracer's median / the peer's median: below 1 the raytracer was faster.");
        out.println();
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
        if (fullJit) {
            cmd.add("-XX:TieredStopAtLevel=4");   // the last one wins
        }
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), "ray.bench.Throughput"));
        cmd.addAll(List.of(args));
        return cmd;
    }

    private void printKindTable(Path sceneDir) throws IOException, InterruptedException {
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
                double t = time(throughputCommand(c2, "--row", name, sceneDir.resolve(s + ".txt").toAbsolutePath().toString()), work, log);
                String text = Files.readString(log, StandardCharsets.UTF_8).trim();
                out.println(t >= 0 && text.startsWith("|") ? text : "| " + name + " | failed |  |  |  |");
            }
        }
        out.println();
        out.println("## Allocation on the hot path (a whole render on one thread, the launcher's JIT, after a warm-up render)");
        out.println();
        out.println("Heap bytes the render thread allocated (com.sun.management.ThreadMXBean), less the image itself "
                + "(24 bytes per pixel, allocated once). C1 has no escape analysis, so nothing here is removed by the JIT.");
        out.println();
        out.println("| scene | rays | bytes allocated besides the image | bytes per ray |");
        out.println("|---|---:|---:|---:|");
        for (String s : scenes) {
            Path log = work.resolve("alloc.log");
            double t = time(throughputCommand(false, "--alloc", sceneDir.resolve(s + ".txt").toAbsolutePath().toString()), work, log);
            String[] f = Files.readString(log, StandardCharsets.UTF_8).trim().split(" ");
            if (t < 0 || f.length != 5 || !f[0].equals("alloc")) {
                out.println("| " + s + " | failed |  |  |");
                continue;
            }
            out.println(String.format(Locale.ROOT, "| %s | %,d | %,d | %s |", s, Long.parseLong(f[2]),
                    Long.parseLong(f[3]) - Long.parseLong(f[4]), f[1]));
        }
        out.println();
        if (scenes.contains("mesh100k")) {
            embreeComparison(sceneDir.resolve("mesh100k.txt"));
        }
    }

    /** Closest-hit and any-hit camera-ray rates {median, best} of this program in a fresh JVM with the full JIT. */
    private double[] ourCameraRates(Path scene) throws IOException, InterruptedException {
        Path log = work.resolve("camera.log");
        if (time(throughputCommand(true, "--camera", scene.toAbsolutePath().toString()), work, log) < 0) {
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
        Path py = venvPython(), script = benchDir.resolve("peers/embree_rays.py");
        if (!withPeers || !Files.isExecutable(py) || !Files.isRegularFile(script)) {
            return;
        }
        out.println("## Traversal against Embree (mesh100k camera rays, 1 thread, same session)");
        out.println();
        try {
            Path log = work.resolve("embree.log");
            double[] before = ourCameraRates(meshScene);
            double t = time(List.of(py.toString(), script.toAbsolutePath().toString(), meshScene.toAbsolutePath().toString()), benchDir, log);
            double[] after = ourCameraRates(meshScene);
            String text = Files.readString(log, StandardCharsets.UTF_8);
            double ec = embreeRate(text, "INTERSECT"), eo = embreeRate(text, "OCCLUDED");
            if (t < 0 || Double.isNaN(ec) || before == null || after == null) {
                out.println("embree_rays.py or the raytracer's measurement failed:\n```\n" + text + "```\n");
                return;
            }
            out.println("This program in a fresh JVM with the full JIT (C2), median of 9 passes after 5 warm-up passes, "
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

    // ---- the machine ----

    private static String loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).trim().split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }

    private static String cpuName() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (l.startsWith("model name")) {
                    return l.substring(l.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux
        }
        return System.getProperty("os.arch");
    }

    /**
     * How many cores' worth of throughput the machine gives right now, like run_peers.sh's parcheck:
     * the wall time of two threads each spinning a fixed loop, over the time of one (1.0: two free
     * cores; 2.0: one).
     */
    static double parallelCheck() throws InterruptedException {
        spin(20_000_000);   // compile it first
        long t0 = System.nanoTime();
        spin(200_000_000);
        long t1 = System.nanoTime();
        Thread a = new Thread(() -> spin(200_000_000)), b = new Thread(() -> spin(200_000_000));
        a.start();
        b.start();
        a.join();
        b.join();
        long t2 = System.nanoTime();
        return (double) (t2 - t1) / (t1 - t0);
    }

    private static volatile long sink;

    private static void spin(long n) {
        long x = 1;
        for (long i = 0; i < n; i++) {
            x = x * 6364136223846793005L + 1442695040888963407L;
        }
        sink = x;
    }

    /** Scenes from a comma list, checked against {@link #SCENES}. */
    public static List<String> sceneList(String list) {
        if (list == null || list.isEmpty()) {
            return SCENES;
        }
        List<String> l = Arrays.asList(list.split(","));
        for (String s : l) {
            if (!SCENES.contains(s)) {
                throw new IllegalArgumentException("unknown benchmark scene '" + s + "' (expected some of " + String.join(", ", SCENES) + ")");
            }
        }
        return l;
    }
}
