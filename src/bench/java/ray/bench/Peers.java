package ray.bench;

import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The peer renderers of the shared bench directory (POV-Ray, Tachyon, Sunflow, Mitsuba 3), run the way
 * {@code peers/run_peers.sh} runs them (on mesh1m: the bench's own translations, {@link Mesh1mPeers}), and
 * the ratio table of {@code gradle bench --peers}.
 */
final class Peers {

    static final List<String> ALL = List.of("pov", "tachyon", "sunflow", "mitsuba_llvm");
    static final Map<String, String> NAMES = Map.of(
            "pov", "POV-Ray 3.7", "tachyon", "Tachyon", "sunflow", "Sunflow (Java)", "mitsuba_llvm", "Mitsuba 3 (LLVM)");

    private final Path benchDir;
    private final Path work;
    private final List<String> scenes;

    Peers(Path benchDir, Path work, List<String> scenes) {
        this.benchDir = benchDir;
        this.work = work;
        this.scenes = scenes;
    }

    /** The Python of the peers' venv ($VENV, default peers/.venv in the bench directory). */
    Path venvPython() {
        String v = System.getenv("VENV");
        Path venv = v != null && !v.isEmpty() ? Path.of(v) : benchDir.resolve("peers/.venv");
        if (!venv.isAbsolute()) {
            venv = benchDir.resolve(venv);
        }
        return venv.resolve("bin/python");
    }

    /** Where peer {@code p}'s translation of mesh1m is: beside the scene, in the work directory ({@link Mesh1mPeers}). */
    private Path mesh1m(String p, String ext) {
        return Mesh1mPeers.dir(LongScenes.dir(work), p).resolve(LongScenes.MESH1M + ext).toAbsolutePath();
    }

    /** The bench's Whitted script with area lights, beside its Mitsuba translation of mesh1m. */
    private Path mitsubaScript() {
        return Mesh1mPeers.dir(LongScenes.dir(work), "mitsuba_llvm").resolve(Mesh1mPeers.MITSUBA_SCRIPT).toAbsolutePath();
    }

    /** Why peer {@code p} can never render scene {@code s} (the table says it), or null. */
    static String reason(String p, String s) {
        return p.equals("tachyon") && s.equals(LongScenes.MESH1M) ? Mesh1mPeers.NO_AREA_LIGHT : null;
    }

    /** Whether peer {@code p} is installed and scene {@code s} translated for it. */
    boolean available(String p, String s) {
        if (reason(p, s) != null) {
            return false;
        }
        if (s.equals(LongScenes.MESH1M)) {
            switch (p) {
                case "pov":
                    return onPath("povray") && Files.isRegularFile(mesh1m(p, ".pov"));
                case "sunflow":
                    return Files.isRegularFile(Path.of("/usr/share/java/sunflow.jar"))
                            && Files.isRegularFile(benchDir.resolve("peers/sunflow/SunflowRender.class"))
                            && Files.isRegularFile(mesh1m(p, ".sc"));
                default:
                    return Files.isExecutable(venvPython()) && Files.isRegularFile(mesh1m(p, ".xml"))
                            && Files.isRegularFile(mitsubaScript());
            }
        }
        switch (p) {
            case "pov":
                return onPath("povray") && Files.isRegularFile(benchDir.resolve("peers/build/pov/" + s + ".pov"));
            case "tachyon":
                return onPath("tachyon-nox") && Files.isRegularFile(benchDir.resolve("peers/build/tachyon/" + s + ".dat"));
            case "sunflow":
                return Files.isRegularFile(Path.of("/usr/share/java/sunflow.jar"))
                        && Files.isRegularFile(benchDir.resolve("peers/sunflow/SunflowRender.class"))
                        && Files.isRegularFile(benchDir.resolve("peers/build/sunflow/" + s + ".sc"));
            default:
                return Files.isExecutable(venvPython()) && Files.isRegularFile(benchDir.resolve("peers/build/mitsuba/" + s + ".xml"));
        }
    }

    /** The command line run_peers.sh uses for a peer (run in the bench directory). */
    List<String> command(String p, String s) {
        String png = work.resolve("peer_" + p + ".png").toAbsolutePath().toString();
        if (s.equals(LongScenes.MESH1M)) {   // translated by Mesh1mPeers into the work directory
            switch (p) {
                case "pov":
                    return List.of("povray", mesh1m(p, ".ini").toString(), "+I" + mesh1m(p, ".pov"), "+O" + png);
                case "sunflow":
                    return List.of("java", "-cp", "/usr/share/java/sunflow.jar:peers/sunflow", "SunflowRender", mesh1m(p, ".sc").toString(), png);
                default:
                    return List.of(venvPython().toString(), mitsubaScript().toString(), "llvm_ad_rgb",
                            mesh1m(p, ".xml").toString(), png);
            }
        }
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

    /**
     * The ratio tables: this program's median wall and CPU time over each peer's, scene by scene (n/a where
     * the peer has no translation of the scene).
     */
    void printTable(PrintStream out, int runs, Map<String, Map<String, List<Double>>> times,
                    Map<String, Map<String, List<Double>>> cpus, java.util.Set<String> peers) {
        out.println("## Against the peers (whole process, median of " + runs + ", interleaved in the same rounds)");
        out.println();
        out.println("Wall time, then CPU time (user + system of all the process's threads, from the bench's own "
                + "/proc/self/stat children counters, in 10 ms ticks).");
        out.println();
        for (boolean cpu : new boolean[] {false, true}) {
            String unit = cpu ? "cpu s" : "wall s";
            StringBuilder h = new StringBuilder("| scene | raytracer " + unit + " |");
            StringBuilder sep = new StringBuilder("|---|---:|");
            for (String p : peers) {
                h.append(' ').append(NAMES.get(p)).append(' ').append(unit).append(" | ratio |");
                sep.append("---:|---:|");
            }
            out.println(h);
            out.println(sep);
            Map<String, Map<String, List<Double>>> m = cpu ? cpus : times;
            for (String s : scenes) {
                Map<String, List<Double>> t = m.get(s);
                if (t == null) {
                    continue;
                }
                double ours = Bench.median(t.getOrDefault("raytracer", List.of()));
                StringBuilder row = new StringBuilder(String.format(Locale.ROOT, "| %s | %.2f |", s, ours));
                for (String p : peers) {
                    List<Double> l = t.get(p);
                    if (l == null || l.isEmpty()) {
                        String why = reason(p, s);
                        row.append(why == null ? " n/a | n/a |" : " n/a (" + why + ") | n/a |");
                        continue;
                    }
                    double theirs = Bench.median(l);
                    row.append(String.format(Locale.ROOT, " %.2f | %.2f |", theirs, ours / theirs));
                }
                out.println(row);
            }
            out.println();
        }
        out.println("ratio = raytracer's median / the peer's median: below 1 the raytracer was faster.");
        out.println();
    }
}
