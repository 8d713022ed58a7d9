package ray.plan;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;

/**
 * {@code raytracer --plan [--json] scene.txt ...}: prints each scene's render plan without rendering
 * (as text, or one JSON object per scene). Exit status 0 when every scene was read, 1 otherwise.
 */
public final class PlanCommand {

    private PlanCommand() {
    }

    public static int run(List<Path> scenes, boolean json, PrintStream out, PrintStream err) {
        return run(scenes, json, s -> { }, out, err);
    }

    /**
     * {@link #run(List, boolean, PrintStream, PrintStream)} with the command line's overrides applied to
     * each scene before it is planned (samples, sampler, the inexact cut of faint paths).
     */
    public static int run(List<Path> scenes, boolean json, java.util.function.Consumer<Scene> overrides, PrintStream out, PrintStream err) {
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
                overrides.accept(scene);
                for (String w : warnings) {
                    err.println(w);
                }
                PlanReport report = report(name, scene);
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

    /** The plan of {@code scene} with every exact skip, beside the same scene planned without them. */
    public static PlanReport report(String name, Scene scene) {
        return new PlanReport(name, RenderPlan.derive(scene, EnumSet.allOf(Skip.class), scene.cutsFaintPaths()),
                RenderPlan.derive(scene, RenderPlan.NO_SKIPS));
    }
}
