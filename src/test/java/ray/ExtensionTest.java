package ray;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.light.LightSample;
import ray.light.Sun;
import ray.parse.Parser;
import ray.plan.RenderPlan;
import ray.render.Image;
import ray.render.Renderer;

/**
 * The extension test of issue 16: a new primitive ({@code ray.surface.Quad}), a textured material
 * ({@code ray.material.CheckerDiffuse}, Diffuse's reflectance hook) and a directional light ({@code ray.light.Sun},
 * a light sample at infinity on {@code SampledLight}) are each one new file in test sources, found by the
 * parser by name and rendered, with no existing file changed and nothing copied. Checked against values
 * worked out by hand: k_d I cos on the lit floor, the checker's other colour one square over, shadow
 * under the occluder, and the plan bounding the rays.
 */
class ExtensionTest {

    /**
     * Looking straight down at a 4 x 4 floor quad at y = 0; a small quad at y = 1 over the middle; the sun
     * shining down at 45 degrees towards +x, so the small quad's shadow falls around (1, 0, 0), in view.
     */
    private static final String SCENE = """
            Width 40
            Height 40
            AmbientLight [0.1 0.1 0.1]

            Camera Camera
            Vector3d eye [0 10 0]
            Vector3d target [0 0 0]
            Vector3d up [0 0 -1]
            double yFOV 20

            Material CheckerDiffuse floor
            Vector3d ambientColor [1 1 1]
            Vector3d diffuseColor [0.8 0.6 0.4]
            Vector3d otherColor [0.2 0.2 0.2]

            Material Diffuse grey

            Surface Quad
            Vector3d corner [-2 0 -2]
            Vector3d edge1 [4 0 0]
            Vector3d edge2 [0 0 4]
            ref material floor

            Surface Quad
            Vector3d corner [-0.25 1 -0.25]
            Vector3d edge1 [0.5 0 0]
            Vector3d edge2 [0 0 0.5]
            ref material grey

            Light Sun
            Vector3d direction [1 -1 0]
            Vector3d intensity [1 1 1]
            """;

    private static Vector3d at(Image img, int x, int y) {
        return new Vector3d(img.rgb[3 * (y * img.width + x)], img.rgb[3 * (y * img.width + x) + 1], img.rgb[3 * (y * img.width + x) + 2]);
    }

    /** The pixel seeing floor point (x, 0, z): the camera looks down -y with up -z (image x is world x, image y is world z). */
    private static int[] pixel(Scene s, double x, double z) {
        double half = Math.tan(Math.toRadians(10)) * 10;
        return new int[] {(int) ((x / half + 1) / 2 * s.width), (int) ((z / half + 1) / 2 * s.height)};
    }

    @Test
    void aNewPrimitiveTexturedMaterialAndDirectionalLightRenderAsWorkedOutByHand() throws Exception {
        Scene s = Parser.parse(SCENE, "extension.txt", new ArrayList<>());
        Renderer r = new Renderer(s).threads(2);
        Image img = r.render();
        double cos = Math.sqrt(0.5);
        // lit floor, even square (x in [1, 2), z in [1, 2)): k_a I_a + k_d I cos 45
        Vector3d even = at(img, pixel(s, 1.5, 1.5)[0], pixel(s, 1.5, 1.5)[1]);
        assertEquals(0.1 + 0.8 * cos, even.x, 1e-12);
        assertEquals(0.1 + 0.6 * cos, even.y, 1e-12);
        assertEquals(0.1 + 0.4 * cos, even.z, 1e-12);
        // one square over: the checker's other colour
        Vector3d odd = at(img, pixel(s, 0.5, 1.5)[0], pixel(s, 0.5, 1.5)[1]);
        assertEquals(0.1 + 0.2 * cos, odd.x, 1e-12);
        // the small quad: its own Diffuse (k_d 0.5, k_a 0)
        Vector3d top = at(img, pixel(s, 0.05, 0.05)[0], pixel(s, 0.05, 0.05)[1]);
        assertEquals(0.5 * cos, top.x, 1e-12);
        // the floor in the small quad's shadow: ambient only, found by the shadow ray to infinity
        Vector3d shade = at(img, pixel(s, 1.0, 0.05)[0], pixel(s, 1.0, 0.05)[1]);
        assertEquals(0.1, shade.x, 1e-12, "in the shadow");
        RenderPlan p = r.plan();
        assertEquals(40 * 40, p.bound().get(RayKind.SHADOW), "one shadow ray per pixel from the sun, as declared");
        assertTrue(r.stats().get(RayKind.SHADOW) <= p.bound().get(RayKind.SHADOW));
        assertEquals(0, p.bound().get(RayKind.USER), "nothing the plan cannot see into");
    }

    @Test
    void theSunsShadowRayRunsToInfinity() throws Exception {
        Scene s = Parser.parse(SCENE, "extension.txt", new ArrayList<>());
        s.prepare();
        TraceContext ctx = TraceContext.current(s);
        Sun sun = (Sun) s.lights.get(0);
        IntersectionRecord under = new IntersectionRecord(), beside = new IntersectionRecord();
        under.location.set(1, 0, 0);
        under.normal.set(0, 1, 0);
        beside.location.set(1, 0, 1);
        beside.normal.set(0, 1, 0);
        LightSample ls = new LightSample(ctx.sample);
        assertTrue(sun.sample(under, s, 0, ls) && ls.atInfinity());
        assertTrue(s.occluded(under, ls, ctx), "the small quad lies between, however far the sun");
        sun.sample(beside, s, 0, ls);
        assertTrue(!s.occluded(beside, ls, ctx));
        assertEquals(0, sun.getIntensity(under, s).x, "the framework's getIntensity, for free: shadowed");
        assertEquals(1, sun.getIntensity(beside, s).x, "and lit");
    }
}
