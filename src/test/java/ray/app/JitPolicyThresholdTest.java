package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * Where the JIT policy puts the line between a short render (C1) and a long one (C2), at the renders it
 * was measured on (docs/performance.md, session 30): a 640x480 scene lit by two lights is long at 9x9
 * samples (75 M expected rays, C2 0.91-0.97x C1's CPU) and short at 8x8 (59 M, C2 1.03x).
 */
class JitPolicyThresholdTest {

    private static RenderPlan plan(int samples) throws Exception {
        Scene s = Parser.parse("Width 640\nHeight 480\nAASamples " + samples + "\n\nCamera Camera\nVector3d eye [0 2 8]\n"
                + "Vector3d target [0 0 0]\n\nLight PointLight\nVector3d position [5 8 6]\nVector3d intensity [60 60 60]\n\n"
                + "Light PointLight\nVector3d position [-6 5 2]\nVector3d intensity [20 20 20]\n\n"
                + "Material Diffuse m\n\nSurface Sphere\nVector3d center [0 0 0]\ndouble radius 1\nref material m\n",
                "t.txt", new ArrayList<>());
        return RenderPlan.derive(s, new RenderSettings().resolve(s));
    }

    @Test
    void nineByNineSamplesOf640x480AreLongAndEightByEightShort() throws Exception {
        RenderPlan nine = plan(9), eight = plan(8);
        assertEquals(640 * 480 * 81 * 3.0, JitPolicy.expectedRays(nine), "camera rays and a shadow ray per light");
        assertTrue(JitPolicy.isLong(nine, "t.txt", false), "75 M expected rays");
        assertFalse(JitPolicy.isLong(eight, "t.txt", false), "59 M expected rays");
    }
}
