package ray.plan;

import java.util.function.Supplier;
import ray.Scene;

/**
 * Knows a render's cost before the first ray: refuses a scene whose bound on rays is absurd (over
 * {@link #MAX_RAYS}, hours on two cores at the rate of {@link RayEstimate#RAYS_PER_THREAD_SECOND})
 * unless the user allows it ({@code --allow-long}), and says up front when a render will likely take
 * long. The refusal reads the bound (a bound: the render cannot cast more); the notice reads an
 * estimate (a pilot render, {@link RayEstimate}), asked for only where the bound leaves room for a long
 * render, and says that it is an estimate. A bound that is unknown (a user class may trace any number
 * of rays) is never refused.
 */
public final class CostGate {

    /** Refused above this many rays (all kinds) unless allowed. */
    public static final double MAX_RAYS = 1e11;
    /** Renders whose estimate is above this many seconds are announced. */
    public static final double LONG_SECONDS = 60;
    /** The option that allows a refused render. */
    public static final String ALLOW = "--allow-long";

    private CostGate() {
    }

    /** {@link #check(String, RenderPlan, boolean, int, boolean, java.io.PrintStream, Supplier)} without a pilot: the notice reads the bound. */
    public static boolean check(String sceneName, RenderPlan plan, boolean allowed, int threads, boolean quiet, java.io.PrintStream err) {
        return check(sceneName, plan, allowed, threads, quiet, err, null);
    }

    /**
     * Before rendering with {@code plan} (the render's own: hand it to the renderer): prints the refusal
     * and returns false when its bound is absurd and not {@code allowed}; otherwise prints the long-render
     * notice (unless {@code quiet}) and returns true. {@code pilot} (may be null, may return null) gives
     * the estimate; it is called only when the bound allows a render longer than {@link #LONG_SECONDS}.
     */
    public static boolean check(String sceneName, RenderPlan plan, boolean allowed, int threads, boolean quiet, java.io.PrintStream err,
            Supplier<RayEstimate> pilot) {
        String refused = refusal(sceneName, plan);
        if (refused != null && !allowed) {
            err.println(refused);
            return false;
        }
        if (!quiet) {
            String note = warning(sceneName, plan, threads, pilot);
            if (note != null) {
                err.println(note);
            }
        }
        return true;
    }

    /** The one-line refusal for {@code plan}'s scene, or null when its bound is below {@link #MAX_RAYS} or unknown. */
    public static String refusal(String sceneName, RenderPlan plan) {
        RayCountBound b = plan.bound();
        if (!(b.atMost() > MAX_RAYS)) {
            return null;   // even the cheap bound is below the limit: no pass over the surfaces for this render
        }
        double total = b.total();
        if (!(total > MAX_RAYS) || !Double.isFinite(total)) {
            return null;
        }
        Scene s = plan.scene();
        return sceneName + ": refused: this render may cast up to " + PlanReport.count(total) + " rays (limit 1e11; "
                + atTheRate(total, Runtime.getRuntime().availableProcessors()) + "), mostly " + b.largest().key()
                + " rays from " + b.factors(s) + "; " + ALLOW + " renders it anyway (raytracer --plan shows the plan)";
    }

    /**
     * A one-line notice when the render will likely take longer than {@link #LONG_SECONDS}, or null: when
     * the bound allows that long, the pilot's estimate decides (without a pilot, the bound does).
     */
    public static String warning(String sceneName, RenderPlan plan, int threads, Supplier<RayEstimate> pilot) {
        double atMost = plan.bound().atMost();
        if (!Double.isFinite(atMost) || RayEstimate.seconds(atMost, threads) <= LONG_SECONDS) {
            return null;   // the cheap bound already says quick (or unknown): no pass over the surfaces
        }
        double total = plan.bound().total();
        if (!Double.isFinite(total) || RayEstimate.seconds(total, threads) <= LONG_SECONDS) {
            return null;   // even the bound's every ray would be quick
        }
        String bound = "the plan's bound: up to " + PlanReport.count(total) + " rays, " + plan.bound().largest().key() + " rays from "
                + plan.bound().factors(plan.scene());
        RayEstimate e = pilot == null ? null : pilot.get();
        if (e == null) {
            return sceneName + ": note: this render may take long: " + bound + " (" + atTheRate(total, threads) + ")";
        }
        if (e.seconds(threads) <= LONG_SECONDS) {
            return null;
        }
        return sceneName + ": note: this render will likely take long: " + e.line(threads) + "; " + bound;
    }

    /** "that many would take about 4 h on 2 threads at an estimated 4 M rays per thread-second" for a count of rays (an estimate of its time, said so). */
    public static String atTheRate(double rays, int threads) {
        if (!Double.isFinite(rays)) {
            return "time unknown: a user class may trace any number of rays";
        }
        String t = RayEstimate.duration(RayEstimate.seconds(rays, threads));
        return "that many would take " + (t == null ? "more than a million years" : "about " + t) + " on " + threads + " thread"
                + (threads == 1 ? "" : "s") + " at an estimated " + Math.round(RayEstimate.RAYS_PER_THREAD_SECOND / 1e6) + " M rays per thread-second";
    }
}
