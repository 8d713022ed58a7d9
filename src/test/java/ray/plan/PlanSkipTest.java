package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.plan.PlanFixture.assertSameImage;
import static ray.plan.PlanFixture.assertWithinBound;

import java.util.EnumSet;
import java.util.List;
import org.junit.jupiter.api.Test;
import ray.RayKind;

/**
 * Hand-computed ray counts with and without the plan's exact skips, and the same image either way.
 * The camera at (0, 0, 5) looks at the origin; a triangle in z = 0 far wider than the view is hit by
 * every camera ray, and every light sits in front of it with nothing between.
 */
class PlanSkipTest {

    private static final int W = 12, H = 8;
    private static final long N = (long) W * H;

    private static final String WALL = "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\n"
            + "Vector3d v2 [0 100 0]\nref material m\n\n";
    /** A second wall at z = 10 facing the first, behind the camera: mirror rays bounce between them. */
    private static final String BACK_WALL = "Surface Triangle\nVector3d v0 [-100 -100 10]\nVector3d v1 [0 100 10]\n"
            + "Vector3d v2 [100 -100 10]\nref material m\n\n";
    private static final String LIGHT = "Light PointLight\nVector3d position [0 0 3]\nVector3d intensity [9 9 9]\n\n";
    private static final String LIGHT2 = "Light PointLight\nVector3d position [1 -1 2]\nVector3d intensity [1 2 3]\n\n";
    private static final String DARK = "Light PointLight dark\nVector3d position [-1 1 2]\nVector3d intensity [0 0 0]\n\n";

    private static String scene(String globals, String objects) {
        return "Width " + W + "\nHeight " + H + "\nAmbientLight [0.1 0.2 0.3]\n" + globals + "\n\nCamera Camera\n\n" + objects;
    }

    /** Renders with every skip and with none: same image; returns both for the counts. */
    private static PlanFixture[] both(String text) throws Exception {
        PlanFixture with = PlanFixture.withPlan(text), without = PlanFixture.withoutPlan(text);
        assertSameImage(with.image, without.image, "with and without the plan's skips");
        assertWithinBound(with.stats, with.plan.bound(), "with the plan");
        for (Skip s : Skip.values()) {   // each skip alone changes nothing either
            PlanFixture one = PlanFixture.render(text, EnumSet.of(s));
            assertSameImage(with.image, one.image, "only " + s);
            PlanFixture allBut = PlanFixture.render(text, EnumSet.complementOf(EnumSet.of(s)));
            assertSameImage(with.image, allBut.image, "all but " + s);
        }
        return new PlanFixture[] {with, without};
    }

    @Test
    void shadowRaysAreLitPointsTimesLightsAndADarkLightIsSkipped() throws Exception {
        PlanFixture[] r = both(scene("", "Material BlinnPhong m\n\n" + WALL + LIGHT + DARK + LIGHT2));
        assertEquals(N, r[0].rays(RayKind.CAMERA));
        assertEquals(2 * N, r[0].rays(RayKind.SHADOW), "two lights seen from every point; the dark one skipped");
        assertEquals(3 * N, r[1].rays(RayKind.SHADOW), "without the plan the dark light costs a shadow ray per point");
        // nothing reflects: every hit is a camera hit, so the bound is exact
        assertEquals(2 * N, r[0].plan.bound().get(RayKind.SHADOW));
        // the saving shows in the bound: one shadow ray per camera ray fewer than without skipping the dark light
        assertEquals(List.of("light 2 (PointLight dark) has zero intensity: skipped; bound 96 rays lower (shadow 96)"),
                PlanReport.of("t", r[0].scene).saved());
    }

    @Test
    void aMaterialWithoutDirectTermEvaluatesNoLight() throws Exception {
        String black = "Material Diffuse m\nVector3d ambientColor [0.3 0.2 0.1]\nVector3d diffuseColor [0 0 0]\n\n";
        PlanFixture[] r = both(scene("", black + WALL + LIGHT + LIGHT2));
        assertEquals(0, r[0].rays(RayKind.SHADOW));
        assertEquals(2 * N, r[1].rays(RayKind.SHADOW));
        assertEquals(0, r[0].plan.bound().get(RayKind.SHADOW));
        // a highlight alone is a direct term: its shadow rays stay
        String shiny = "Material BlinnPhong m\nVector3d diffuseColor [0 0 0]\nVector3d specularColor [1 1 1]\n\n";
        assertEquals(2 * N, both(scene("", shiny + WALL + LIGHT + LIGHT2))[0].rays(RayKind.SHADOW));
        String dull = "Material BlinnPhong m\nVector3d diffuseColor [0 0 0]\nVector3d specularColor [0 0 0]\n\n";
        assertEquals(0, both(scene("", dull + WALL + LIGHT + LIGHT2))[0].rays(RayKind.SHADOW));
    }

    @Test
    void pureMirrorsCastNoShadowRays() throws Exception {
        PlanFixture[] r = both(scene("MaxDepth 3", "Material Glazed m\ndouble mirrorCoefficient 0.7\n\n" + WALL + LIGHT));
        assertEquals(0, r[0].rays(RayKind.SHADOW));
        assertEquals(N, r[0].rays(RayKind.MIRROR), "each reflection flies off into the background");
        assertEquals(0, r[0].plan.bound().get(RayKind.SHADOW));
        // no skip of the plan's does that (a pure mirror has no direct term to skip): nothing is named as saved
        PlanReport report = PlanReport.of("t", r[0].scene);
        assertEquals(List.of(), report.saved());
        assertEquals(List.of(), report.skipped());
        assertEquals(RenderPlan.derive(r[0].scene, RenderPlan.NO_SKIPS).bound().total(), r[0].plan.bound().total());
    }

    @Test
    void aZeroMirrorCoefficientCastsNoMirrorRay() throws Exception {
        String text = scene("MaxDepth 2", "Material Diffuse b\n\nMaterial Glazed m\nref base b\ndouble mirrorCoefficient 0\n\n"
                + WALL + BACK_WALL + LIGHT);
        PlanFixture[] r = both(text);
        assertEquals(0, r[0].rays(RayKind.MIRROR));
        assertEquals(2 * N, r[1].rays(RayKind.MIRROR), "without the plan: one ray per bounce to MaxDepth 2");
        assertEquals(0, r[0].plan.bound().get(RayKind.MIRROR));
    }

    /** Eight Glazed levels, each the base of the next, over a Diffuse base, between two walls. */
    static String chain(int levels, String globals) {
        StringBuilder s = new StringBuilder("Material Diffuse g0\nVector3d ambientColor [0.2 0.1 0.1]\nVector3d diffuseColor [0.3 0.5 0.2]\n\n");
        for (int i = 1; i <= levels; i++) {
            s.append("Material Glazed g").append(i).append("\nref base g").append(i - 1)
                    .append("\ndouble mirrorCoefficient ").append(0.05 + 0.01 * i).append("\n\n");
        }
        return scene(globals, s.toString().replace("Glazed g" + levels, "Glazed m") + WALL + BACK_WALL + LIGHT);
    }

    @Test
    void aNestedGlazedChainCostsOneMirrorRayPerHit() throws Exception {
        PlanFixture[] r = both(chain(8, "MaxDepth 2"));
        assertEquals(2 * N, r[0].rays(RayKind.MIRROR), "one mirror ray per hit, two bounces");
        assertEquals((8 + 64) * N, r[1].rays(RayKind.MIRROR), "unfolded: 8 rays per hit, 8^2 at the second bounce");
        assertEquals(3 * N, r[0].rays(RayKind.SHADOW), "one shadow ray per hit: camera hit and two bounces");
        assertEquals((1 + 8 + 64) * N, r[1].rays(RayKind.SHADOW));
        // folding saves 70 mirror and 70 shadow rays per camera ray in the bound: (8 + 64) - 2 and (1 + 8 + 64) - 3
        assertEquals(List.of("nested Glazed chain folded at m (8 levels): 1 mirror ray per hit instead of 8; bound "
                + String.format(java.util.Locale.ROOT, "%,d", 140 * N) + " rays lower (shadow 6,720, mirror 6,720)"),
                PlanReport.of("t", r[0].scene).saved());
    }

    @Test
    void foldingKeepsTheDefaultDepthChainBelowTheRefusalLimit() throws Exception {
        ray.Scene s = PlanFixture.parse(chain(8, ""));   // MaxDepth 10 by default
        RenderPlan folded = RenderPlan.derive(s, EnumSet.allOf(Skip.class)), unfolded = RenderPlan.derive(s, RenderPlan.NO_SKIPS);
        assertEquals(10 * N, folded.bound().get(RayKind.MIRROR));
        assertEquals(N * 8 * (Math.pow(8, 10) - 1) / 7, unfolded.bound().get(RayKind.MIRROR), 1, "8 + 64 + ... + 8^10 per camera ray");
        assertNull(CostGate.refusal("t", folded));
        assertNotNull(CostGate.refusal("t", unfolded), "8^10 paths per pixel: a day of rendering without folding");
    }

    /**
     * Derived once per render: the plan the command line's cost check derived is the one the render uses,
     * when it was derived for the settings the render resolves; for other settings the render derives its own.
     */
    @Test
    void thePlanCheckedBeforeRenderingIsTheOneTheRenderUses() throws Exception {
        ray.Scene s = PlanFixture.parse(scene("", "Material Diffuse m\n\n" + WALL + LIGHT));
        RenderPlan checked = RenderPlan.derive(s, new ray.settings.RenderSettings());
        ray.render.Renderer r = new ray.render.Renderer(s).plan(checked);
        r.render();
        org.junit.jupiter.api.Assertions.assertSame(checked, r.plan());
        new ray.render.Renderer(s).render();
        org.junit.jupiter.api.Assertions.assertSame(checked, r.plan(), "another renderer does not change this one's plan");
        ray.render.Renderer deeper = new ray.render.Renderer(s).settings(new ray.settings.RenderSettings().maxDepth(3)).plan(checked);
        deeper.render();
        org.junit.jupiter.api.Assertions.assertNotSame(checked, deeper.plan(), "a plan for other settings is not used");
        assertEquals(3, deeper.plan().settings().maxDepth());
        RenderPlan none = RenderPlan.derive(s, new ray.settings.RenderSettings(), RenderPlan.NO_SKIPS);
        ray.render.Renderer plain = new ray.render.Renderer(s).plan(none);
        plain.render();
        assertTrue(plain.plan().skips().isEmpty());
    }
}
