package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import org.junit.jupiter.api.Test;
import ray.RayKind;
import ray.Scene;
import ray.render.Image;
import ray.settings.RenderSettings;

/**
 * The one inexact skip, opt-in: cutting mirror paths whose weight (product of k_m) is below half an
 * 8-bit step. Its effect is measured here: rays saved, pixels changed and by how much.
 */
class CutFaintTest {

    private static final int W = 24, H = 16;
    private static final long N = (long) W * H;

    /** Two facing glazed walls (k_m 0.5 over a Diffuse base) lit from between, MaxDepth 30. */
    private static final String SCENE = "Width " + W + "\nHeight " + H + "\nMaxDepth 30\nAmbientLight [0.2 0.2 0.2]\n\nCamera Camera\n\n"
            + "Material Diffuse d\nVector3d ambientColor [0.3 0.2 0.1]\nVector3d diffuseColor [0.4 0.3 0.5]\n\n"
            + "Material Glazed m\nref base d\ndouble mirrorCoefficient 0.5\n\n"
            + "Surface Triangle\nVector3d v0 [-1e4 -1e4 0]\nVector3d v1 [1e4 -1e4 0]\nVector3d v2 [0 1e4 0]\nref material m\n\n"
            + "Surface Triangle\nVector3d v0 [-1e4 -1e4 10]\nVector3d v1 [0 1e4 10]\nVector3d v2 [1e4 -1e4 10]\nref material m\n\n"
            + "Light PointLight\nVector3d position [0.5 0.3 3]\nVector3d intensity [2 2 2]\n\n";

    private static PlanFixture render(boolean cut) throws Exception {
        Scene s = PlanFixture.parse(SCENE);
        return PlanFixture.render(s, new RenderSettings().cutFaint(cut), EnumSet.allOf(Skip.class));
    }

    @Test
    void cuttingFaintPathsStopsAtTheDepthWhereTheWeightFallsBelowHalfAStep() throws Exception {
        PlanFixture exact = render(false), cut = render(true);
        // 0.5^8 = 1/256 >= 1/510 > 0.5^9: eight bounces of the thirty are followed
        assertEquals(30 * N, exact.rays(RayKind.MIRROR));
        assertEquals(8 * N, cut.rays(RayKind.MIRROR));
        assertEquals(8 * N, cut.plan.bound().get(RayKind.MIRROR), "the plan's bound knows the cut");
        assertEquals(8, cut.plan.bound().reachableDepth());
        assertTrue(PlanReport.of("t", cut.scene, new RenderSettings().cutFaint(true)).text().stream().anyMatch(l -> l.startsWith("  faint paths cut     on   inexact")));
        // measured: how many 8-bit values change, and by how much (pinned: 45 of 1,152 by one step; the
        // light seen after the 9th bounce is bright enough to tip a rounding, as the option warns)
        int changed = 0, worst = 0;
        for (int i = 0; i < exact.image.rgb.length; i++) {
            int d = Math.abs(Image.toByte(exact.image.rgb[i]) - Image.toByte(cut.image.rgb[i]));
            changed += d > 0 ? 1 : 0;
            worst = Math.max(worst, d);
        }
        assertTrue(worst <= 1, "at most one 8-bit step: " + worst);
        assertEquals(45, changed, changed + " of " + exact.image.rgb.length + " channel values changed, by at most " + worst);
    }

    @Test
    void nothingIsCutUnlessAsked() throws Exception {
        Scene s = PlanFixture.parse(SCENE);
        assertEquals(30 * N, RenderPlan.derive(s, EnumSet.allOf(Skip.class)).bound().get(RayKind.MIRROR));
        assertTrue(PlanReport.of("t", s).effects().stream().noneMatch(e -> e.name.equals("faint paths cut")));
    }
}
