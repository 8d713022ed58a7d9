package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.Set;
import ray.RayKind;
import ray.RayStats;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.Renderer;
import ray.settings.RenderSettings;

/** Renders scene text with a chosen set of the plan's skips, keeping the image and the rays counted. */
final class PlanFixture {

    final Scene scene;
    final Image image;
    final RayStats stats;
    /** The plan the render followed. */
    final RenderPlan plan;

    private PlanFixture(Scene scene, Image image, RayStats stats, RenderPlan plan) {
        this.scene = scene;
        this.image = image;
        this.stats = stats;
        this.plan = plan;
    }

    static Scene parse(String text) throws SceneFormatException {
        return Parser.parse(text, "plan-test.txt", new ArrayList<>());
    }

    static PlanFixture render(String text, Set<Skip> skips) throws SceneFormatException {
        return render(parse(text), skips);
    }

    static PlanFixture render(Scene scene, Set<Skip> skips) {
        return render(scene, new RenderSettings(), skips);
    }

    static PlanFixture render(Scene scene, RenderSettings settings, Set<Skip> skips) {
        Renderer r = new Renderer(scene).threads(2).settings(settings).plan(RenderPlan.derive(scene, settings, skips));
        Image image = r.render();
        assertEquals(0, r.stats().invalidSamples);
        return new PlanFixture(scene, image, r.stats(), r.plan());
    }

    static PlanFixture withPlan(String text) throws SceneFormatException {
        return render(text, EnumSet.allOf(Skip.class));
    }

    static PlanFixture withoutPlan(String text) throws SceneFormatException {
        return render(text, RenderPlan.NO_SKIPS);
    }

    long rays(RayKind k) {
        return stats.get(k);
    }

    /** Same linear values in every pixel and channel (== : +0 and -0 count as the same, as in the PNG). */
    static void assertSameImage(Image a, Image b, String what) {
        assertEquals(a.rgb.length, b.rgb.length, what);
        for (int i = 0; i < a.rgb.length; i++) {
            if (!(a.rgb[i] == b.rgb[i])) {
                throw new AssertionError(what + ": pixel " + (i / 3 % a.width) + "," + (i / 3 / a.width) + " channel " + i % 3
                        + ": " + a.rgb[i] + " != " + b.rgb[i]);
            }
        }
    }

    /** Every kind's count within the plan's bound, and 0 where the plan's bound is 0. */
    static void assertWithinBound(RayStats stats, RayCountBound bound, String what) {
        for (RayKind k : RayKind.values()) {
            long n = stats.get(k);
            assertTrue(n <= bound.get(k), what + ": " + n + " " + k.key() + " rays counted, bound " + bound.get(k));
        }
    }
}
