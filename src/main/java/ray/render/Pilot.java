package ray.render;

import ray.RayKind;
import ray.Scene;
import ray.plan.RayEstimate;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * A pilot render for the plan's estimate ({@link RayEstimate}): the scene at a fraction of its pixels
 * (each side divided by k >= 8, the view and aspect kept; samples, MaxDepth and plan as the render's),
 * its rays scaled back up by the pixels' ratio. k grows until the pilot's own bound is at most
 * {@link #PILOT_RAYS}, so the pilot takes at most a few seconds whatever the scene; no pilot (null) where
 * the bound is unknown (a user's class may trace any number of rays) or even one pixel may cast more.
 * The scene is restored afterwards (size, aspect, camera frame); a render after it prepares it again.
 */
public final class Pilot {

    /** The most rays the pilot's own bound may allow. */
    static final double PILOT_RAYS = 4e6;
    /** The least the pilot divides each side by. */
    static final int MIN_DIVISOR = 8;

    private Pilot() {
    }

    /** The estimate for rendering {@code scene} with {@code settings} on {@code threads} threads, or null (see the class). */
    public static RayEstimate estimate(Scene scene, RenderSettings settings, int threads) {
        int w = scene.width, h = scene.height;
        if (w <= 0 || h <= 0 || scene.camera == null) {
            return null;
        }
        double full = RenderPlan.derive(scene, settings).bound().total();
        if (!Double.isFinite(full)) {
            return null;
        }
        double aspect = scene.camera.aspect;
        int k = Math.max(MIN_DIVISOR, (int) Math.ceil(Math.sqrt(full / PILOT_RAYS)));
        int pw = Math.max(1, (int) Math.ceil((double) w / k)), ph = Math.max(1, (int) Math.ceil((double) h / k));
        try {
            if (Double.isNaN(aspect)) {
                scene.camera.aspect = (double) w / h;   // the full image's view
            }
            scene.width = pw;
            scene.height = ph;
            RenderPlan plan = RenderPlan.derive(scene, settings);
            if (!(plan.bound().total() <= 10 * PILOT_RAYS)) {
                return null;   // one pixel's tree alone is too large to try
            }
            long t0 = System.nanoTime();
            Renderer r = new Renderer(scene).threads(threads).settings(settings).plan(plan);
            r.render();
            double seconds = (System.nanoTime() - t0) / 1e9;
            double fraction = (double) pw * ph / ((double) w * h);
            double[] rays = new double[RayKind.values().length];
            for (RayKind kind : RayKind.values()) {
                rays[kind.ordinal()] = r.stats().get(kind) / fraction;
            }
            return new RayEstimate(rays, fraction, seconds);
        } finally {
            scene.width = w;
            scene.height = h;
            scene.camera.aspect = aspect;
            scene.camera.recalculate();
        }
    }
}
