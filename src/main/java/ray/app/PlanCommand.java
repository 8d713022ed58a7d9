package ray.app;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.plan.CostGate;
import ray.plan.PlanReport;
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
     * resolved against each scene).
     */
    static int run(List<Path> scenes, boolean json, RenderSettings settings, PrintStream out, PrintStream err) {
        if (scenes.isEmpty()) {
            err.println("raytracer: --plan needs scene files");
            return 2;
        }
        int failed = 0;
        for (Path p : scenes) {
            String name = p.toString();
            List<String> warnings = new ArrayList<>();
            try {
                Scene scene = Parser.parse(p, warnings);
                for (String w : warnings) {
                    err.println(w);
                }
                PlanReport report = PlanReport.of(name, scene, settings);
                if (json) {
                    out.println(report.json());
                } else {
                    report.text().forEach(out::println);
                    RenderPlan plan = report.plan();
                    String verdict = CostGate.refusal(name, plan) != null
                            ? "a render would be refused (" + CostGate.ALLOW + " allows it)" : "a render would go ahead";
                    out.println("  " + verdict + "; estimate from the bound: "
                            + CostGate.estimate(plan.bound().total(), Runtime.getRuntime().availableProcessors()));
                }
            } catch (SceneFormatException e) {
                err.println(e.getMessage());
                failed++;
            } catch (RuntimeException | LinkageError e) {   // a user's class failing in terms() or init()
                err.println((name + ": cannot plan the scene: " + e).replaceAll("[\\p{Cntrl}\u2028\u2029]+", " "));
                failed++;
            }
        }
        return failed == 0 ? 0 : 1;
    }
}
