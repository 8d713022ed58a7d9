package ray.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * {@code gradle bench -PbenchArgs='--baseline OTHER/bin/raytracer'}: another build of this program (an
 * older commit's install, say) timed on the same scenes in the same rounds as this one, the two
 * alternating which goes first, so a change's cost is a ratio measured under the same load. Wall time,
 * and CPU time of all the process's threads (render, JIT compiler, GC) from the bench's own
 * {@code /proc/self/stat} children counters, which a loaded machine disturbs less than wall time.
 */
final class Baseline {

    private final String launcher;
    /** Per scene, per timed round: this build's wall and CPU seconds, then the baseline's. */
    private final Map<String, List<double[]>> rounds = new LinkedHashMap<>();

    Baseline(String launcher) {
        this.launcher = launcher;
    }

    /** The baseline's command for a scene: the options every version of the launcher has. */
    List<String> command(Path scene, Path png) {
        return List.of(launcher, "-q", scene.toAbsolutePath().toString(), "-o", png.toAbsolutePath().toString());
    }

    /** Whether round {@code r} runs the baseline first (every other round, so neither always goes first). */
    static boolean baselineFirst(int round) {
        return round % 2 == 0;
    }

    void record(String scene, double wall, double cpu, double baseWall, double baseCpu) {
        rounds.computeIfAbsent(scene, k -> new ArrayList<>()).add(new double[] {wall, cpu, baseWall, baseCpu});
    }

    void print(PrintStream out, List<String> scenes) {
        out.println("## Against the baseline `" + launcher + "` (same rounds, alternating which goes first)");
        out.println();
        out.println("| scene | rounds | raytracer wall s | baseline wall s | wall ratio, median [min–max] | raytracer cpu s | baseline cpu s | cpu ratio, median [min–max] |");
        out.println("|---|---:|---:|---:|---|---:|---:|---|");
        for (String s : scenes) {
            List<double[]> l = rounds.get(s);
            if (l == null || l.isEmpty()) {
                out.println("| " + s + " | 0 | failed |  |  |  |  |  |");
                continue;
            }
            out.println(String.format(Locale.ROOT, "| %s | %d | %.3f | %.3f | %s | %.2f | %.2f | %s |", s, l.size(),
                    median(l, 0), median(l, 2), ratios(l, 0, 2), median(l, 1), median(l, 3), ratios(l, 1, 3)));
        }
        out.println();
        out.println("ratio = this build / the baseline, per round (below 1: this build was faster). CPU seconds are counted");
        out.println("in clock ticks (10 ms) and are only available on Linux.");
        out.println();
    }

    /** Median of column {@code c}. */
    static double median(List<double[]> l, int c) {
        double[] v = new double[l.size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = l.get(i)[c];
        }
        return median(v);
    }

    /** "1.03 [0.98–1.10]": the per-round ratios of column {@code a} over column {@code b}. */
    static String ratios(List<double[]> l, int a, int b) {
        double[] r = new double[l.size()];
        for (int i = 0; i < r.length; i++) {
            r[i] = l.get(i)[a] / l.get(i)[b];
        }
        double[] sorted = r.clone();
        Arrays.sort(sorted);
        if (Double.isNaN(sorted[0]) || Double.isNaN(sorted[sorted.length - 1])) {
            return "n/a";
        }
        return String.format(Locale.ROOT, "%.2f [%.2f–%.2f]", median(r), sorted[0], sorted[sorted.length - 1]);
    }

    static double median(double[] v) {
        double[] a = v.clone();
        Arrays.sort(a);
        return a.length == 0 ? Double.NaN : a.length % 2 == 1 ? a[a.length / 2] : 0.5 * (a[a.length / 2 - 1] + a[a.length / 2]);
    }

    /**
     * CPU seconds (user + system) of this process's finished children so far: fields cutime and cstime
     * of {@code /proc/self/stat}, in clock ticks of 10 ms (USER_HZ is 100 on Linux); NaN elsewhere. The
     * difference across one {@code waitFor} is that child's CPU time, all its threads included.
     */
    static double childCpuSeconds() {
        try {
            String stat = new String(Files.readAllBytes(Path.of("/proc/self/stat")), StandardCharsets.US_ASCII);
            String[] f = stat.substring(stat.lastIndexOf(')') + 2).trim().split(" ");
            return (Long.parseLong(f[13]) + Long.parseLong(f[14])) / 100.0;   // fields 16 and 17 of the stat line
        } catch (IOException | RuntimeException e) {
            return Double.NaN;
        }
    }
}
