package ray.plan;

import ray.Scene;

/**
 * Knows a render's cost before the first ray: refuses a scene whose bound on rays is absurd (over
 * {@link #MAX_RAYS}, about three hours on two cores at the speeds measured in docs/performance.md)
 * unless the user allows it ({@code --allow-long}), and says up front when a render may take long.
 * A bound that is unknown (a user class may trace any number of rays) is never refused.
 */
public final class CostGate {

    /** Refused above this many rays (all kinds) unless allowed. */
    public static final double MAX_RAYS = 1e11;
    /** Renders whose estimate is above this many seconds are announced. */
    public static final double LONG_SECONDS = 60;
    /** Rays per second one render thread casts and shades, for the estimate (the mirrors bench scene, C1 JIT). */
    static final double RAYS_PER_THREAD_SECOND = 5e6;
    /** The option that allows a refused render. */
    public static final String ALLOW = "--allow-long";

    private CostGate() {
    }

    /**
     * Before rendering with {@code plan} (the render's own: hand it to the renderer): prints the refusal
     * and returns false when its bound is absurd and not {@code allowed}; otherwise prints the long-render
     * notice (unless {@code quiet}) and returns true.
     */
    public static boolean check(String sceneName, RenderPlan plan, boolean allowed, int threads, boolean quiet, java.io.PrintStream err) {
        String refused = refusal(sceneName, plan);
        if (refused != null && !allowed) {
            err.println(refused);
            return false;
        }
        String note = warning(sceneName, plan, threads);
        if (note != null && !quiet) {
            err.println(note);
        }
        return true;
    }

    /** The one-line refusal for {@code plan}'s scene, or null when its bound is below {@link #MAX_RAYS} or unknown. */
    public static String refusal(String sceneName, RenderPlan plan) {
        RayCountBound b = plan.bound();
        double total = b.total();
        if (!(total > MAX_RAYS) || !Double.isFinite(total)) {
            return null;
        }
        Scene s = plan.scene();
        return sceneName + ": refused: this render may cast up to " + PlanReport.count(total) + " rays (limit 1e11; "
                + estimate(total, Runtime.getRuntime().availableProcessors()) + "), mostly " + b.largest().key()
                + " rays from " + b.factors(s) + "; " + ALLOW + " renders it anyway (raytracer --plan shows the plan)";
    }

    /** A one-line notice when the render may take longer than {@link #LONG_SECONDS}, or null. */
    public static String warning(String sceneName, RenderPlan plan, int threads) {
        double total = plan.bound().total();
        if (!Double.isFinite(total) || total / (RAYS_PER_THREAD_SECOND * Math.max(1, threads)) <= LONG_SECONDS) {
            return null;
        }
        return sceneName + ": note: this render may cast up to " + PlanReport.count(total) + " rays ("
                + plan.bound().largest().key() + " rays from " + plan.bound().factors(plan.scene()) + "): " + estimate(total, threads);
    }

    /** "up to about 3 h on 2 threads" from a ray count. */
    public static String estimate(double rays, int threads) {
        if (!Double.isFinite(rays)) {
            return "unknown: a user class may trace any number of rays";
        }
        double s = rays / (RAYS_PER_THREAD_SECOND * Math.max(1, threads));
        double year = 365.25 * 86400;
        String t = s < 1 ? "a second" : s < 90 ? Math.round(s) + " s" : s < 5400 ? Math.round(s / 60) + " min" : s < 3 * 86400 ? Math.round(s / 3600) + " h"
                : s < 3 * year ? Math.round(s / 86400) + " days" : s < 1e6 * year ? Math.round(s / year) + " years" : null;
        // never Math.round's Long.MAX_VALUE of days
        return (t == null ? "more than a million years" : "up to about " + t) + " on " + threads + " thread" + (threads == 1 ? "" : "s");
    }
}
