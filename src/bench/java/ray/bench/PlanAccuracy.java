package ray.bench;

import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * {@code gradle planAccuracy}: how close the render plan's numbers come to real renders, for every scene
 * in scenes/: the installed launcher plans each scene ({@code --plan --json}: the bound and the pilot's
 * estimate) and renders it ({@code --stats --json}: rays cast, seconds), and a Markdown table compares
 * them: bound / rays cast (at least 1: it is a bound), estimated / cast rays, and the render's
 * seconds (parse to PNG written, without the JVM's start) over the estimated seconds, with the
 * distributions (worst, median) last. docs/plan.md keeps a run of it. Timings move with the machine's
 * load: the table prints the load beside them. A command, never a test.
 *
 * <pre>
 * PlanAccuracy --launcher build/install/raytracer/bin/raytracer --scenes scenes --work build/plan-accuracy [--runs 3]
 * </pre>
 */
public final class PlanAccuracy {

    private PlanAccuracy() {
    }

    public static void main(String[] args) throws Exception {
        Path launcher = null, scenes = Path.of("scenes"), work = Path.of("build", "plan-accuracy");
        int runs = 1;
        for (int i = 0; i + 1 < args.length; i += 2) {
            switch (args[i]) {
                case "--launcher" -> launcher = Path.of(args[i + 1]);
                case "--scenes" -> scenes = Path.of(args[i + 1]);
                case "--work" -> work = Path.of(args[i + 1]);
                case "--runs" -> runs = Integer.parseInt(args[i + 1]);
                default -> throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        if (launcher == null) {
            throw new IllegalArgumentException("--launcher PATH is needed");
        }
        Files.createDirectories(work);
        System.exit(run(launcher, scenes, work, runs, System.out));
    }

    static int run(Path launcher, Path scenes, Path work, int runs, PrintStream out) throws IOException, InterruptedException {
        List<Path> list = new ArrayList<>();
        try (var s = Files.list(scenes)) {
            s.filter(p -> p.toString().endsWith(".txt")).sorted().forEach(list::add);
        }
        out.println("| scene | bound (rays) | rays cast | bound / cast | estimated rays | estimated / cast | estimated s | render s | render / estimated | process wall s | process cpu s | estimated cpu s | cpu / estimated |");
        out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        List<Double> boundRatio = new ArrayList<>(), rayRatio = new ArrayList<>(), timeRatio = new ArrayList<>(), cpuRatio = new ArrayList<>();
        int failed = 0;
        for (Path scene : list) {
            String name = scene.getFileName().toString().replace(".txt", "");
            JsonObject plan = json(launcher, work, "--plan", "--json", scene.toString());
            List<Double> render = new ArrayList<>(), wall = new ArrayList<>(), cpu = new ArrayList<>();
            double cast = -1;
            for (int r = 0; r < runs; r++) {
                long t0 = System.nanoTime();
                JsonObject stats = json(launcher, work, "-q", "--stats", "--json", "-o", work.resolve(name + ".png").toString(), scene.toString());
                double w = (System.nanoTime() - t0) / 1e9;
                if (stats == null) {
                    break;
                }
                render.add(stats.getAsJsonObject("seconds").get("total").getAsDouble());
                cpu.add(stats.get("cpuSeconds").getAsDouble());
                wall.add(w);
                cast = 0;
                for (var e : stats.getAsJsonObject("rays").entrySet()) {
                    cast += e.getValue().getAsDouble();
                }
            }
            if (plan == null || cast < 0) {
                out.println("| " + name + " | failed |  |  |  |  |  |  |  |  |  |  |  |");
                failed++;
                continue;
            }
            double bound = plan.get("totalBound").getAsDouble();
            JsonElement est = plan.get("estimate");
            double estRays = Double.NaN, estSeconds = Double.NaN, estCpu = Double.NaN;
            if (est != null && est.isJsonObject()) {
                estRays = 0;
                for (ray.RayKind k : ray.RayKind.values()) {
                    estRays += est.getAsJsonObject().get(k.key()).getAsDouble();
                }
                estSeconds = est.getAsJsonObject().get("seconds").getAsDouble();
                estCpu = est.getAsJsonObject().get("cpuSeconds").getAsDouble();
            }
            double renderS = Bench.median(render);
            boundRatio.add(bound / cast);
            rayRatio.add(estRays / cast);
            timeRatio.add(renderS / estSeconds);
            double cpuS = Bench.median(cpu);
            cpuRatio.add(cpuS / estCpu);
            out.println(String.format(Locale.ROOT, "| %s | %,.0f | %,.0f | %.2f | %,.0f | %.3f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f | %.2f |", name, bound,
                    cast, bound / cast, estRays, estRays / cast, estSeconds, renderS, renderS / estSeconds, Bench.median(wall), cpuS, estCpu,
                    cpuS / estCpu));
        }
        out.println();
        out.println(summary("bound / rays cast", boundRatio));
        out.println(summary("estimated rays / rays cast", rayRatio));
        out.println(summary("render seconds / estimated seconds", timeRatio));
        out.println(summary("process cpu seconds / estimated cpu seconds", cpuRatio));
        out.println(String.format(Locale.ROOT, "%d scenes, %d run%s each (medians), load average %s, %d cores", list.size(), runs,
                runs == 1 ? "" : "s", load(), Runtime.getRuntime().availableProcessors()));
        return failed == 0 ? 0 : 1;
    }

    /** "name: worst low 0.91, median 1.00, worst high 1.20 (n)" over the finite values. */
    static String summary(String name, List<Double> v) {
        List<Double> f = new ArrayList<>();
        for (double d : v) {
            if (Double.isFinite(d)) {
                f.add(d);
            }
        }
        f.sort(null);
        if (f.isEmpty()) {
            return name + ": no values";
        }
        return String.format(Locale.ROOT, "%s: lowest %.3f, median %.3f, highest %.3f (%d scenes)", name, f.get(0), Bench.median(f),
                f.get(f.size() - 1), f.size());
    }

    private static String load() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).split(" ")[0];
        } catch (IOException e) {
            return "unknown";
        }
    }

    /** The JSON object the launcher prints with {@code args}, or null when it failed. */
    private static JsonObject json(Path launcher, Path work, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(launcher.toAbsolutePath().toString());
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectError(work.resolve("stderr.log").toFile()).start();
        String text = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.waitFor() != 0) {
            return null;
        }
        for (String line : text.split("\n")) {
            if (line.startsWith("{")) {
                return JsonParser.parseString(line).getAsJsonObject();
            }
        }
        return null;
    }
}
