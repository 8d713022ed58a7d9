package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.plan.PlanFixture.assertWithinBound;

import java.util.SplittableRandom;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.Ray;
import ray.RayKind;

/**
 * The bound follows the tree of rays material by material, and charges a camera ray only for the
 * surfaces its pixel can see: tight where the plan can prove it, never below what a render casts.
 */
class PlanBoundTest {

    private static final int W = 16, H = 12;
    private static final long N = (long) W * H;

    private static String scene(String globals, String objects) {
        return "Width " + W + "\nHeight " + H + "\n" + globals + "\n\nCamera Camera\n\n" + objects;
    }

    /**
     * A pure mirror (no direct term) facing a Diffuse wall: a path of mirror hits ends in at most one
     * Diffuse hit, so at most one shadow ray per camera ray; the bound per level (before) was MaxDepth + 1.
     */
    @Test
    void aMirrorChainEndsInOneDiffuseHitsShadowRays() throws Exception {
        String text = scene("MaxDepth 6", "Material Glazed m\ndouble mirrorCoefficient 0.9\n\nMaterial Diffuse d\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\nVector3d v2 [0 100 0]\nref material m\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 10]\nVector3d v1 [0 100 10]\nVector3d v2 [100 -100 10]\nref material d\n\n"
                + "Light PointLight\nVector3d position [0 0 3]\n\n");
        PlanFixture r = PlanFixture.withPlan(text);
        assertEquals(N, r.plan.bound().get(RayKind.SHADOW));
        assertEquals(6 * N, r.plan.bound().get(RayKind.MIRROR));
        assertEquals(N, r.rays(RayKind.SHADOW), "every camera ray: mirror, then the Diffuse wall, then one shadow ray");
        assertWithinBound(r.stats, r.plan.bound(), "mirror chain");
    }

    /**
     * A glass ball small in the view: only the camera rays of the pixels its box projects to can grow a
     * tree (2^MaxDepth paths); every other camera ray sees the background and casts nothing more.
     */
    @Test
    void aSmallGlassBallChargesOnlyThePixelsThatSeeIt() throws Exception {
        String text = scene("MaxDepth 5", "Material Dielectric glass\n\n"
                + "Surface Sphere\nVector3d center [0 0 0]\ndouble radius 0.3\nref material glass\n\n");
        PlanFixture r = PlanFixture.withPlan(text);
        int[] px = r.scene.camera.pixelsSeeing(-0.3, -0.3, -0.3, 0.3, 0.3, 0.3, W, H);
        long seeing = (long) (px[2] - px[0]) * (px[3] - px[1]);
        assertTrue(seeing > 0 && seeing < N / 2, "the ball covers a few pixels: " + seeing);
        // per pixel that sees it: 2 + 4 + ... + 32 secondary rays (2^5 paths), half mirror and half refraction
        assertEquals(N + seeing * 62, r.plan.bound().total());
        assertEquals(seeing * 31, r.plan.bound().get(RayKind.MIRROR));
        assertWithinBound(r.stats, r.plan.bound(), "glass ball");
        assertTrue(r.rays(RayKind.REFRACTION) > 0);
    }

    /**
     * {@link Camera#pixelsSeeing}: for random cameras and boxes, every pixel with a sample (its corners
     * and a grid inside) whose camera ray meets the box lies in the rectangle returned.
     */
    @Test
    void theProjectedRectangleHoldsEveryPixelWhoseRaysMeetTheBox() {
        SplittableRandom rnd = new SplittableRandom(18);
        Ray ray = new Ray();
        int checked = 0;
        for (int c = 0; c < 300; c++) {
            Camera cam = new Camera();
            cam.eye = new Vector3d(rnd.nextDouble(-5, 5), rnd.nextDouble(-5, 5), rnd.nextDouble(-5, 5));
            cam.target = new Vector3d(rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1));
            cam.up = new Vector3d(rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1), rnd.nextDouble(-1, 1));
            cam.yFOV = rnd.nextDouble(10, 120);
            cam.aspect = rnd.nextBoolean() ? Double.NaN : rnd.nextDouble(0.5, 2);
            int w = 1 + rnd.nextInt(24), h = 1 + rnd.nextInt(18);
            try {
                cam.init();
            } catch (IllegalArgumentException e) {
                continue;   // up parallel to the view: not a camera
            }
            if (Double.isNaN(cam.aspect)) {
                cam.aspect = (double) w / h;   // as the scene's preparation sets it
                cam.recalculate();
            }
            double[] lo = {rnd.nextDouble(-2, 2), rnd.nextDouble(-2, 2), rnd.nextDouble(-2, 2)};
            double[] hi = {lo[0] + rnd.nextDouble(0, 1.5), lo[1] + rnd.nextDouble(0, 1.5), lo[2] + rnd.nextDouble(0, 1.5)};
            int[] r = cam.pixelsSeeing(lo[0], lo[1], lo[2], hi[0], hi[1], hi[2], w, h);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    for (int s = 0; s <= 4; s++) {
                        for (int t = 0; t <= 4; t++) {
                            cam.setRayThrough(ray, x + s / 4.0, y + t / 4.0, w, h);
                            if (meets(ray, lo, hi)) {
                                checked++;
                                assertTrue(x >= r[0] && x < r[2] && y >= r[1] && y < r[3], "camera " + cam + ", box "
                                        + java.util.Arrays.toString(lo) + java.util.Arrays.toString(hi) + ": pixel " + x + "," + y
                                        + " sees it, rectangle " + java.util.Arrays.toString(r));
                            }
                        }
                    }
                }
            }
        }
        assertTrue(checked > 10_000, "the property was exercised: " + checked);
    }

    /** Slab test: the ray (t >= 0) meets the closed box. */
    private static boolean meets(Ray ray, double[] lo, double[] hi) {
        double[] o = {ray.origin.x, ray.origin.y, ray.origin.z}, d = {ray.direction.x, ray.direction.y, ray.direction.z};
        double t0 = 0, t1 = Double.POSITIVE_INFINITY;
        for (int a = 0; a < 3; a++) {
            if (d[a] == 0) {
                if (o[a] < lo[a] || o[a] > hi[a]) {
                    return false;
                }
                continue;
            }
            double u = (lo[a] - o[a]) / d[a], v = (hi[a] - o[a]) / d[a];
            t0 = Math.max(t0, Math.min(u, v));
            t1 = Math.min(t1, Math.max(u, v));
        }
        return t0 <= t1;
    }
}
