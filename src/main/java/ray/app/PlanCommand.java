package ray.app;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.Failures;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Pilot;
import ray.plan.CostGate;
import ray.plan.PlanReport;
import ray.plan.RayEstimate;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * {@code raytracer --plan [--json] scene.txt ...}: prints each scene's render plan without rendering
 * (as text, or one JSON object per scene). Exit status 0 when every scene was read, 1 otherwise.
 */
final class PlanCommand {

    private PlanCommand() {
    }

    /**
     * Prints the plan of each scene rendered with {@code settings} (the command line's overrides,
     * resolved against each scene); the scene {@code -} is read from {@code in}. Whatever a scene's
     * own classes throw while it is read or planned (an Error, a StackOverflowError from a deep chain,
     * an exception whose message throws) is one line naming the scene; the next scene is still
     * planned. A plan that cannot be written to {@code out} (a closed pipe, a full disk) is a failure.
     * {@code quiet} (-q): the scenes' warnings are not printed, only failures.
     */
    static int run(List<Path> scenes, boolean json, boolean quiet, RenderSettings settings, java.io.InputStream in, PrintStream out,
            PrintStream err) {
        if (scenes.isEmpty()) {
            err.println("raytracer: --plan needs scene files");
            return 2;
        }
        int failed = 0;
        for (Path p : scenes) {
            boolean stdin = p.toString().equals("-");
            String name = Failures.oneLine(stdin ? "<stdin>" : p.toString());
            List<String> warnings = new ArrayList<>();
            ExitGuard.working(name, null, "planned");     // a user's class calling System.exit is named with the scene
            try {
                Scene scene = stdin ? Parser.parse(in, name, warnings) : Parser.parse(p, warnings);
                for (String w : quiet ? List.<String>of() : warnings) {
                    err.println(w);
                }
                PlanReport report = PlanReport.of(name, scene, settings);
                int threads = Runtime.getRuntime().availableProcessors();
                RayEstimate estimate;
                String noEstimate = null;
                try {
                    estimate = Pilot.estimate(scene, settings, threads);
                    if (estimate == null) {
                        noEstimate = Double.isFinite(report.plan().bound().total()) ? "no estimate: even a pilot of one pixel may cast too many rays"
                                : "no estimate: a user class may trace any number of rays";
                    }
                } catch (RuntimeException e) {   // a user's class failing in the pilot render
                    estimate = null;
                    noEstimate = "no estimate: the pilot render failed: " + Failures.describe(e);
                }
                if (json) {
                    out.println(report.json(estimate, threads));
                } else {
                    report.text().forEach(out::println);
                    RenderPlan plan = report.plan();
                    out.println("  " + (estimate != null ? estimate.line(threads) : noEstimate));
                    out.println("  " + (CostGate.refusal(name, plan) != null ? "a render would be refused (bound over 1e11 rays; "
                            + CostGate.ALLOW + " allows it)" : "a render would go ahead"));
                }
            } catch (SceneFormatException e) {
                err.println(Failures.oneLine(e.getMessage()));
                failed++;
            } catch (OutOfMemoryError e) {
                err.println(name + ": out of memory while planning the scene (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
                failed++;
            } catch (Throwable e) {   // a user's class failing in terms(), init(), ... whatever it throws
                err.println(name + ": cannot plan the scene: " + Failures.describe(e));
                failed++;
            }
            ExitGuard.idle();
            out.flush();
            if (out.checkError()) {
                return 1;    // the command line says so (Main.outputChecked); no use planning the rest
            }
        }
        return failed == 0 ? 0 : 1;
    }
}
