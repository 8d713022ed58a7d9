package ray.app;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import ray.RayKind;
import ray.light.Light;
import ray.plan.CostGate;
import ray.plan.RenderPlan;

/**
 * Which JIT compiler a render should run under, decided from its render plan before the first ray
 * (docs/performance.md, "The JIT policy").
 *
 * <p>{@code bin/raytracer} starts the JVM with C1 only ({@code -XX:TieredStopAtLevel=1}): a render of a
 * second or two is over before C2 would have paid for its compilations, and full tiered compilation
 * costs such a render 1.5-2.5x the CPU time. A render of tens of seconds is the other way round: C2's
 * code traces about 1.25x faster, and its compilations are a rounding error. A JVM's compilers are fixed
 * when it starts, so when the launcher allows it (it sets {@code RAYTRACER_RELAUNCH} to its own path
 * unless {@code RAYTRACER_JIT} or the user's JVM options choose the JIT) and the first scene of the
 * command line is long, this process runs the launcher again on the same command line with
 * {@code RAYTRACER_JIT=long} (full tiered compilation), passes its standard streams through and ends
 * with that process's exit status. Nothing has been printed or written by then; the cost is one more
 * JVM start and a second parse of the first scene (a few percent of a long render).
 */
final class JitPolicy {

    /**
     * Expected rays (camera rays and the shadow rays of their first hits) from which a render is long.
     * Measured (docs/performance.md): the classic scene with 9x9 samples (75 M such rays, 6.5 CPU s under
     * C1) is at parity, classichd (133 M, 11 CPU s) takes 0.8x the CPU under C2, and the 640x480 classic
     * scene (8 M) 2.1x.
     */
    static final double LONG_RAYS = 1e8;
    /** The environment variable the launcher sets to its own path when this process may start it again. */
    static final String RELAUNCH = "RAYTRACER_RELAUNCH";

    private JitPolicy() {
    }

    /** The launcher to start again for a long render, or null when this process may not. */
    static String launcher() {
        String l = System.getenv(RELAUNCH);
        return l == null || l.isEmpty() ? null : l;
    }

    /**
     * Camera rays and one shadow ray per light sample at each camera ray's hit: the work every render
     * of the scene does whatever its materials (mirror chains only add to it). A light that cannot say
     * how many shadow rays it casts counts as one.
     */
    static double expectedRays(RenderPlan plan) {
        double perPoint = 0;
        for (Light l : plan.lights()) {
            int n = l.plannedShadowRays();
            perPoint += n < 0 ? 1 : n;
        }
        return plan.bound().get(RayKind.CAMERA) * (1 + perPoint);
    }

    /**
     * Whether the render {@code plan} plans is long enough to want C2 (and not one the cost gate
     * refuses: that is reported here, without another process).
     */
    static boolean isLong(RenderPlan plan, String name, boolean allowLong) {
        return expectedRays(plan) >= LONG_RAYS && (allowLong || CostGate.refusal(name, plan) == null);
    }

    /**
     * Runs {@code launcher args} with {@code RAYTRACER_JIT=long}, this process's standard streams passed
     * through, and returns its exit status; -1 when it could not be started (the caller renders here).
     * A shutdown hook ends the child if this process is stopped first.
     */
    static int relaunch(String launcher, String[] args) {
        List<String> cmd = new ArrayList<>(args.length + 1);
        cmd.add(launcher);
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).inheritIO();
        pb.environment().put("RAYTRACER_JIT", "long");
        pb.environment().remove(RELAUNCH);
        Process p;
        try {
            p = pb.start();
        } catch (IOException | RuntimeException e) {
            return -1;
        }
        Thread stop = new Thread(p::destroy, "raytracer-relaunch-stop");
        Runtime.getRuntime().addShutdownHook(stop);
        try {
            while (true) {
                try {
                    return p.waitFor();
                } catch (InterruptedException e) {
                    p.destroy();   // this thread was asked to stop: so is the render it waits for
                }
            }
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(stop);
            } catch (IllegalStateException e) {
                // already shutting down: the hook runs
            }
        }
    }
}
