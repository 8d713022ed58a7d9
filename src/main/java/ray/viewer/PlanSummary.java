package ray.viewer;

import java.util.ArrayList;
import java.util.List;
import ray.plan.PlanReport;
import ray.plan.RenderPlan;

/**
 * The render plan's one line for the status bar: the effects the scene uses and the bound on the rays
 * it can cast, e.g. {@code plan: direct light, highlights, mirror reflection; at most 12,345,678 rays}.
 * The one place the viewer reads the plan ({@code raytracer --plan} prints the whole of it).
 */
final class PlanSummary {

    private PlanSummary() {
    }

    /**
     * The summary of a render's {@code plan} (call this once the render has started, so the plan is not
     * derived twice), or null if it cannot be had (a user's class failing while declaring itself is
     * reported by the render, not here).
     */
    static String of(RenderPlan plan) {
        if (plan == null) {
            return null;
        }
        try {
            PlanReport report = new PlanReport("", plan, RenderPlan.derive(plan.scene(), plan.settings(), RenderPlan.NO_SKIPS));
            List<String> on = new ArrayList<>();
            for (PlanReport.Effect e : report.effects()) {
                if (e.on && e.kind != ray.RayKind.CAMERA && !e.name.equals("geometry")) {
                    on.add(e.name);
                }
            }
            int saved = report.saved().size();
            double bound = plan.bound().total();
            return "plan: " + (on.isEmpty() ? "camera rays only" : String.join(", ", on))
                    + (Double.isFinite(bound) ? "; at most " + PlanReport.count(bound) + " rays" : "; rays unbounded (a user's class)")
                    + (saved == 0 ? "" : "; " + saved + (saved == 1 ? " skip" : " skips"));
        } catch (RuntimeException e) {
            return null;
        }
    }
}
