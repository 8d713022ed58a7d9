package ray;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import ray.parse.Parser;
import ray.render.Renderer;

/**
 * Rays by kind, computed by hand for small scenes. The camera at (0, 0, 5) looks at the origin; a
 * triangle in z = 0 far wider than the view is hit by every camera ray.
 */
class RayCountTest {

    private static final int W = 12, H = 8;

    private static final String WALL = """
            Surface Triangle
            Vector3d v0 [-100 -100 0]
            Vector3d v1 [100 -100 0]
            Vector3d v2 [0 100 0]
            ref material m

            """;

    /** A second wall at z = 10 facing -z (towards the first), behind the camera. */
    private static final String BACK_WALL = """
            Surface Triangle
            Vector3d v0 [-100 -100 10]
            Vector3d v1 [0 100 10]
            Vector3d v2 [100 -100 10]
            ref material m

            """;

    private static final String LIGHT = "Light PointLight\nVector3d position [0 0 3]\nVector3d intensity [9 9 9]\n\n";
    private static final String LIGHT2 = "Light PointLight\nVector3d position [1 -1 2]\nVector3d intensity [1 2 3]\n\n";

    private static RayStats render(String globals, String objects) throws Exception {
        String text = "Width " + W + "\nHeight " + H + "\n" + globals + "\n\nCamera Camera\n\n" + objects;
        Renderer r = new Renderer(Parser.parse(text, "ray-count-test.txt", new ArrayList<>())).threads(2);
        r.render();
        assertEquals(0, r.stats().invalidSamples);
        return r.stats();
    }

    private static void assertCounts(RayStats s, long camera, long shadow, long mirror, long user) {
        String all = s.toString();
        assertEquals(camera, s.get(RayKind.CAMERA), "camera rays: " + all);
        assertEquals(shadow, s.get(RayKind.SHADOW), "shadow rays: " + all);
        assertEquals(mirror, s.get(RayKind.MIRROR), "mirror rays: " + all);
        assertEquals(0, s.get(RayKind.REFRACTION), "refraction rays: " + all);
        assertEquals(user, s.get(RayKind.USER), "user rays: " + all);
        assertEquals(camera + shadow + mirror + user, s.total(), all);
    }

    @Test
    void exactlyOneCameraRayPerSampleAndNothingElseWithoutLightsOrMirrors() throws Exception {
        for (int ns = 1; ns <= 3; ns++) {
            assertCounts(render("AASamples " + ns, "Material Diffuse m\n\n" + WALL), (long) W * H * ns * ns, 0, 0, 0);
            // a shiny material without lights casts no shadow ray either
            assertCounts(render("AASamples " + ns, "Material BlinnPhong m\n\n" + WALL), (long) W * H * ns * ns, 0, 0, 0);
        }
    }

    /** Every point sees every light: shadow rays = lit shading points x lights. */
    @Test
    void shadowRaysAreShadingPointsTimesLights() throws Exception {
        long camera = (long) W * H * 4;
        assertCounts(render("AASamples 2", "Material Diffuse m\n\n" + WALL + LIGHT), camera, camera, 0, 0);
        assertCounts(render("AASamples 2", "Material BlinnPhong m\n\n" + WALL + LIGHT + LIGHT2), camera, 2 * camera, 0, 0);
    }

    /** Two facing glazed walls: every camera ray bounces between them until MaxDepth. */
    @Test
    void mirrorRaysFollowMaxDepthBetweenFacingMirrors() throws Exception {
        String glazed = "Material Glazed m\ndouble mirrorCoefficient 0.5\n\n";
        long camera = (long) W * H;
        for (int depth = 0; depth <= 4; depth++) {
            assertCounts(render("MaxDepth " + depth, glazed + WALL + BACK_WALL), camera, 0, depth * camera, 0);
        }
        // no base, no lights: a pure mirror casts no shadow ray even with a light in the scene
        assertCounts(render("MaxDepth 2", glazed + WALL + BACK_WALL + LIGHT), camera, 0, 2 * camera, 0);
        // k_m = 0 reflects nothing: no mirror ray
        assertCounts(render("MaxDepth 2", "Material Glazed m\ndouble mirrorCoefficient 0\n\n" + WALL + BACK_WALL),
                camera, 0, 0, 0);
    }

    /** A student's mirror material (Metal) traces through Scene.trace: its rays are user rays. */
    @Test
    void studentMirrorRaysAreCountedAsUser() throws Exception {
        long camera = (long) W * H;
        String metal = "Material Metal m\n\n";
        // one wall: each reflection flies off into the sky; the light is seen from every point (one shadow ray each)
        assertCounts(render("MaxDepth 3", metal + WALL + LIGHT), camera, camera, 0, camera);
        // two facing walls without light: the reflections bounce until MaxDepth, one user ray per bounce
        assertCounts(render("MaxDepth 3", metal + WALL + BACK_WALL), camera, 0, 0, 3 * camera);
    }

    @Test
    void statsTextShowsTheClassicKindsAlwaysAndTheOthersWhenCast() throws Exception {
        assertEquals("96 camera, 0 shadow, 0 mirror rays", render("", "Material Diffuse m\n\n" + WALL).toString());
        assertEquals("96 camera, 0 shadow, 0 mirror, 96 user rays", render("MaxDepth 1", "Material Metal m\n\n" + WALL).toString());
    }
}
