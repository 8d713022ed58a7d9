package ray.viewer;

import ray.Scene;

/**
 * The render plan's one-line summary for the status bar. The render plan (what a scene's materials
 * and lights need, computed once) is not on main yet; until it is, there is no summary and the status
 * bar shows none. This is the one place the viewer asks for it.
 */
final class PlanSummary {

    private PlanSummary() {
    }

    /** The summary for {@code scene}, or null where there is none. Called on the background thread. */
    static String of(Scene scene) {
        return null;
    }
}
