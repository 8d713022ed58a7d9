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
import ray.RayKind;

/**
 * {@code gradle bench}: renders the benchmark scenes ({@code classic}, {@code mirrors},
 * {@code spheres10k}, {@code mesh100k} and the long {@code classichd} from the shared bench directory, and
 * the long {@code mesh1m} it generates, {@link LongScenes}) as whole processes, the way a user waits for
 * them, and prints Markdown tables:
 * <ul>
 * <li>wall time (median of the timed runs, after one warm-up run), the process's CPU time, and the
 * parse / build / render / write split, rays cast by kind, render rays per second, peak RSS and BVH
 * bytes per primitive, as the child process reports them with {@code --stats};</li>
 * <li>rays per second by kind from the acceleration structure alone (in this process, one thread,
 * after warm-up; {@link Throughput});</li>
 * <li>with {@code --peers}: the installed peer renderers (POV-Ray, Tachyon, Sunflow, Mitsuba 3, as
 * {@code peers/run_peers.sh} runs them) timed in the same rounds, interleaved with this program, and
 * the ratio of this program's median wall and CPU time to each peer's, on every scene the peers' translator
 * has translated (run_peers.sh translate), and on mesh1m, which the bench translates itself for the peers
 * with area lights ({@link Mesh1mPeers}; Tachyon has none); and Embree's closest-hit and any-hit rates
 * ({@code peers/embree_rays.py}) next to this program's on the mesh100k camera rays.</li>
 * </ul>
 * Timings on a shared machine move by tens of percent; only the ratios measured in one run, with
 * the load and the two-process parallel check printed beside them, compare. Benchmarks are a
 * command, never a test.
 */
public final class Bench {

    /** The peers' four benchmark scenes: renders of about a second, where start-up counts. */
    public static final List<String> SHORT_SCENES = List.of("classic", "mirrors", "spheres10k", "mesh100k");
    /**
     * The long renders, where the steady state counts: classichd (the bench directory's classic scene at
     * 1920x1440, 4x4 samples) and mesh1m ({@link LongScenes}, generated into the work directory).
     */
    public static final List<String> LONG_SCENES = List.of("classichd", LongScenes.MESH1M);
    public static final List<String> SCENES = List.of("classic", "mirrors", "spheres10k", "mesh100k", "classichd", LongScenes.MESH1M);

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
    private final Peers peers;

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
        this.peers = new Peers(benchDir, work, scenes);
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
        Map<String, Path> scenePaths = scenePaths();
        out.println("# gradle bench");
        out.println();
        out.println("- command: `" + String.join(" ", self) + " -q --stats --json SCENE -o PNG`");
        java.util.Set<Path> dirs = new java.util.LinkedHashSet<>();
        for (Path p : scenePaths.values()) {
            dirs.add(p.toAbsolutePath().normalize().getParent());
        }
        out.println("- scenes: " + String.join(", ", scenes) + " in " + dirs.stream().map(Path::toString).collect(java.util.stream.Collectors.joining(", ")));
        out.println("- machine: " + Runtime.getRuntime().availableProcessors() + " cores, " + Machine.cpuName() + "; "
                + System.getProperty("java.vm.name") + " " + System.getProperty("java.version"));
        out.println("- load average before: " + Machine.loadAverage() + "; parallel check (2 processes' wall / 1; 1.0 = two free cores): "
                + String.format(Locale.ROOT, "%.2f", Machine.parallelCheck()));

        Map<String, List<String>> peerCmds = new LinkedHashMap<>();
        if (withPeers) {
            for (String p : Peers.ALL) {
                List<String> missing = new ArrayList<>();
                List<String> never = new ArrayList<>();
                for (String s : scenes) {
                    if (Peers.reason(p, s) != null) {
                        never.add(s + " (" + Peers.reason(p, s) + ")");
                    } else if (!peers.available(p, s)) {
                        missing.add(s);
                    }
                }
                if (missing.size() < scenes.size()) {
                    peerCmds.put(p, null);   // (a peer that cannot render a scene still gets its column, saying why)
                }
                if (!never.isEmpty()) {
                    out.println("- peer " + Peers.NAMES.get(p) + ": cannot render " + String.join(", ", never));
                }
                if (!missing.isEmpty()) {
                    out.println("- peer " + Peers.NAMES.get(p) + ": not installed or not translated in " + benchDir
                            + " for " + String.join(", ", missing) + " (in the bench directory: bash peers/run_peers.sh install scenes,"
                            + " then SCENES='classic mirrors spheres10k mesh100k classichd' bash peers/run_peers.sh translate;"
                            + " mesh1m is translated by the bench itself, ray.bench.Mesh1mPeers), left out there");
                }
            }
        }
        out.println("- rounds: 1 warm-up + " + runs + " timed; in each round every scene runs once with this program"
                + (baseline == null ? "" : " and with the baseline (alternating which goes first)")
                + (peerCmds.isEmpty() ? "" : " and then each peer, one after the other (interleaved)"));
        out.println();

        Map<String, Map<String, List<Double>>> times = new LinkedHashMap<>();
        Map<String, Map<String, List<Double>>> cpus = new LinkedHashMap<>();
        Map<String, List<Stats>> stats = new LinkedHashMap<>();
        int failures = 0;
        for (int round = 0; round <= runs; round++) {
            for (String s : scenes) {
                Path scene = scenePaths.get(s);
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
                    cpus.computeIfAbsent(s, k -> new LinkedHashMap<>()).computeIfAbsent("raytracer", k -> new ArrayList<>()).add(cpu);
                    stats.computeIfAbsent(s, k -> new ArrayList<>()).add(st);
                    if (base != null && base[0] >= 0) {
                        baseline.record(s, t, cpu, base[0], base[1]);
                    }
                }
                for (String p : peerCmds.keySet()) {
                    if (!peers.available(p, s)) {
                        continue;
                    }
                    double pcpu0 = Baseline.childCpuSeconds();
                    double pt = time(peers.command(p, s), benchDir, work.resolve(s + "_" + p + ".log"));
                    double pcpu = Baseline.childCpuSeconds() - pcpu0;
                    if (round > 0 && pt >= 0) {
                        times.get(s).computeIfAbsent(p, k -> new ArrayList<>()).add(pt);
                        cpus.get(s).computeIfAbsent(p, k -> new ArrayList<>()).add(pcpu);
                    }
                }
            }
        }
        out.println("- load average after: " + Machine.loadAverage() + "; parallel check: " + String.format(Locale.ROOT, "%.2f", Machine.parallelCheck()));
        out.println();
        printProcessTable(times, stats);
        if (baseline != null) {
            baseline.print(out, scenes);
        }
        if (!peerCmds.isEmpty()) {
            peers.printTable(out, runs, times, cpus, peerCmds.keySet());
        }
        List<String> inProcess = new ArrayList<>(scenes);
        inProcess.removeAll(LONG_SCENES);   // (their rays per kind are the short scenes' own: classichd is classic)
        if (!inProcess.isEmpty()) {
            new InProcessTables(out, work, benchDir, inProcess, withPeers, peers).print(scenePaths);
        }
        return failures == 0 ? 0 : 1;
    }

    // ---- scenes ----

    /**
     * Each benchmark scene's file: the short ones and classichd from the bench directory (or generated,
     * {@link #sceneDirectory}), mesh1m written into the work directory ({@link LongScenes}).
     */
    private Map<String, Path> scenePaths() throws IOException, InterruptedException {
        List<String> fromBench = new ArrayList<>(scenes);
        fromBench.remove(LongScenes.MESH1M);
        Map<String, Path> paths = new LinkedHashMap<>();
        Path dir = fromBench.isEmpty() ? null : sceneDirectory(benchDir, work, fromBench, out);
        for (String s : scenes) {
            paths.put(s, s.equals(LongScenes.MESH1M) ? LongScenes.mesh1m(LongScenes.dir(work), out) : dir.resolve(s + ".txt"));
        }
        if (withPeers && paths.containsKey(LongScenes.MESH1M)) {
            Mesh1mPeers.write(paths.get(LongScenes.MESH1M), out);
        }
        return paths;
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
        Files.createDirectories(generated);
        for (String s : scenes) {   // those the bench directory keeps (classichd), beside those generated
            if (Files.isRegularFile(shared.resolve(s + ".txt"))) {
                Files.copy(shared.resolve(s + ".txt"), generated.resolve(s + ".txt"), StandardCopyOption.REPLACE_EXISTING);
            }
        }
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
    static double time(List<String> cmd, Path dir, Path log) throws IOException, InterruptedException {
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

    static double median(List<Double> v) {
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
        out.println("## Whole process (median of " + runs + "; cpu: all the process's threads, JIT and GC included;"
                + " the split and memory as the process reports them)");
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
