package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicLong;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.material.Diffuse;
import ray.parse.Parser;

/**
 * A long render's warm-up ({@link Renderer#WARM_UP}): pixels spread over the image rendered before the
 * tiles, so that the JIT's profiles are the whole image's. It must change nothing a user sees: the image
 * is bit for bit the one without it, for any thread count, on each of the grid render's paths (camera
 * packets, camera rays from the tables, a camera making its own rays), for the film renders (the other
 * samplers, progressive passes) and for a window; the rays counted and the tiles reported are the same;
 * and yet the warm-up pixels are rendered (a material counts its calls).
 */
class WarmUpTest {

    /** A diffuse material that counts the camera-ray hits it shades. */
    public static class Counting extends Diffuse {
        static final AtomicLong CALLS = new AtomicLong();

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            CALLS.incrementAndGet();
            return super.shade(ray, record, scene);
        }
    }

    /** A camera whose class makes its own rays: the grid render's per-pixel path. */
    public static class OwnRays extends Camera {
        @Override
        public void setRay(Ray r, double a, double b) {
            super.setRay(r, a, b);
        }
    }

    /**
     * {@code n} x {@code n} spheres (with n = 24, a tree of more than 64 inner nodes: camera packets) of
     * three materials, a mirror among them, two lights, 160 x 120 pixels (18 warm-up pixels) at 2 x 2 samples.
     */
    private static Scene spheres(int n, String camera) throws Exception {
        StringBuilder b = new StringBuilder("Width 160\nHeight 120\nAASamples 2\nBGColor [0.2 0.3 0.5]\n\n")
                .append("Camera ").append(camera).append("\nVector3d eye [0 4 9]\nVector3d target [0 0 0]\ndouble yFOV 50\n\n")
                .append("Light PointLight\nVector3d position [5 8 6]\nVector3d intensity [60 60 60]\n\n")
                .append("Light PointLight\nVector3d position [-6 5 2]\nVector3d intensity [20 20 20]\n\n")
                .append("Material Diffuse red\nVector3d diffuseColor [0.8 0.1 0.1]\n\n")
                .append("Material BlinnPhong blue\nVector3d diffuseColor [0.1 0.2 0.8]\nVector3d specularColor [0.8 0.8 0.8]\n\n")
                .append("Material GlazedMaterial glass\nref base red\ndouble mirrorCoefficient 0.5\n\n")
                .append("Surface Triangle\nVector3d v0 [-20 -0.5 20]\nVector3d v1 [20 -0.5 20]\nVector3d v2 [20 -0.5 -20]\nref material blue\n\n");
        String[] m = {"red", "blue", "glass"};
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                b.append("Surface Sphere\nVector3d center [").append(-4 + 8.0 * i / Math.max(1, n - 1)).append(" 0 ")
                        .append(-4 + 8.0 * j / Math.max(1, n - 1)).append("]\ndouble radius ").append(2.5 / Math.max(1, n))
                        .append("\nref material ").append(m[(i + 2 * j) % 3]).append("\n\n");
            }
        }
        return Parser.parse(b.toString(), "warm.txt", new ArrayList<>());
    }

    /** The image, the rays counted and the tiles reported of one render. */
    private static final class Result {
        final double[] rgb;
        final long[] rays = new long[RayKind.values().length];
        final List<String> tiles = new ArrayList<>();

        Result(Scene s, boolean warm, int threads) {
            this(new Renderer(s).threads(threads).warmUp(warm));
        }

        Result(Renderer r) {
            r.listener(new ProgressListener() {
                @Override
                public synchronized void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                    tiles.add(x0 + "," + y0 + "," + x1 + "," + y1 + "/" + total);
                }
            });
            rgb = r.render().rgb;
            for (RayKind k : RayKind.values()) {
                rays[k.ordinal()] = r.stats().get(k);
            }
            java.util.Collections.sort(tiles);
        }
    }

    @Test
    void theImageTheRaysAndTheTilesAreThoseWithoutTheWarmUp() throws Exception {
        String[][] cases = {{"24", "Camera"}, {"3", "Camera"}, {"24", "ray.render.WarmUpTest$OwnRays"}};
        for (String[] c : cases) {
            Scene s = spheres(Integer.parseInt(c[0]), c[1]);
            Result plain = new Result(s, false, 2);
            // the path tested: packets (a large tree, the standard camera), the tables (a small tree), the camera's own rays
            assertEquals(c[0].equals("24"), s.accelerator().packetsPay(), "a large tree: " + c[0]);
            assertEquals(c[1].equals("Camera"), s.camera.standardRays(), c[1]);
            for (int threads : new int[] {1, 2, 3}) {
                Result warm = new Result(s, true, threads);
                String what = c[0] + " spheres, " + c[1] + ", " + threads + " threads";
                assertArrayEquals(plain.rgb, warm.rgb, what);
                assertArrayEquals(plain.rays, warm.rays, "rays counted: " + what);
                assertEquals(plain.tiles, warm.tiles, "tiles reported: " + what);
            }
        }
    }

    /**
     * The film renders (the other samplers, progressive passes): their warm-up traces samples and drops
     * them, so the film, the image, the rays and the tiles are those without it, and the warm-up's
     * samples are traced (the counting material's calls).
     */
    @Test
    void filmRendersDropTheirWarmUpSamples() throws Exception {
        Scene s = spheres(24, "Camera");
        Object[][] cases = {{"jittered", 3, false}, {"sobol", 2, false}, {"adaptive", 3, false}, {"grid", 3, true},
            {"sobol", 4, true}};
        for (Object[] c : cases) {
            String what = c[0] + " " + c[1] + "x" + c[1] + (Boolean.TRUE.equals(c[2]) ? " progressive" : "");
            Result plain = new Result(film(s, false, c));
            for (int threads : new int[] {1, 2}) {
                Result warm = new Result(film(s, true, c).threads(threads));
                assertArrayEquals(plain.rgb, warm.rgb, what + ", " + threads + " threads");
                assertArrayEquals(plain.rays, warm.rays, "rays counted: " + what);
                assertEquals(plain.tiles, warm.tiles, "tiles reported: " + what);
            }
        }
        Scene counted = counting();
        Counting.CALLS.set(0);
        new Renderer(counted).threads(2).warmUp(false).settings(new ray.settings.RenderSettings().sampler("jittered").samples(5)).render();
        assertEquals(128 * 128 * 25, Counting.CALLS.get());
        Counting.CALLS.set(0);
        new Renderer(counted).threads(2).warmUp(true).settings(new ray.settings.RenderSettings().sampler("jittered").samples(5)).render();
        assertEquals(128 * 128 * 25 + 16 * 16, Counting.CALLS.get(), "16 pixels' first 16 samples, dropped");
    }

    private static Renderer film(Scene s, boolean warm, Object[] c) {
        return new Renderer(s).threads(2).warmUp(warm).settings(new ray.settings.RenderSettings().sampler((String) c[0])
                .samples((Integer) c[1]).progressive((Boolean) c[2]).targetError(1));
    }

    /**
     * A window of the image (how SplitRender's tasks render): its warm-up pixels lie in the window (image
     * coordinates from the window's corner), and its image is the window's without the warm-up.
     */
    @Test
    void aWindowWarmsUpInsideItself() throws Exception {
        Scene s = spheres(24, "Camera");
        Result plain = new Result(new Renderer(s).threads(2).warmUp(false).window(37, 21, 150, 117));
        Result warm = new Result(new Renderer(s).threads(2).warmUp(true).window(37, 21, 150, 117));
        assertTrue(Renderer.warmUpPixels(150 - 37, 117 - 21) > 0);
        assertArrayEquals(plain.rgb, warm.rgb);
        assertArrayEquals(plain.rays, warm.rays);
        assertEquals(plain.tiles, warm.tiles);
        double[] whole = new Result(s, false, 2).rgb;
        assertEquals(whole[3 * (50 * 160 + 60)], warm.rgb[3 * ((50 - 21) * (150 - 37) + 60 - 37)], 0, "the window is the image's");
    }

    /** Every camera ray of a 128 x 128 image hits the material; the warm-up adds 16 pixels' 4 samples each. */
    @Test
    void theWarmUpPixelsAreRendered() throws Exception {
        Scene s = counting();
        Counting.CALLS.set(0);
        new Renderer(s).threads(2).warmUp(false).render();
        assertEquals(128 * 128 * 4, Counting.CALLS.get());
        Counting.CALLS.set(0);
        new Renderer(s).threads(2).warmUp(true).render();
        assertEquals(16, Renderer.warmUpPixels(128, 128));
        assertEquals(128 * 128 * 4 + 16 * 4, Counting.CALLS.get());
    }

    /** A 128 x 128 image at 2 x 2 samples whose every camera ray hits the counting material. */
    private static Scene counting() throws Exception {
        return Parser.parse("Width 128\nHeight 128\nAASamples 2\n\nCamera Camera\nVector3d eye [0 0 3]\nVector3d target [0 0 0]\n"
                + "double yFOV 90\n\nMaterial ray.render.WarmUpTest$Counting m\n\nSurface Sphere\nVector3d center [0 0 0]\n"
                + "double radius 10\nref material m\n", "w.txt", new ArrayList<>());
    }

    /**
     * The warm-up pixels are distinct, inside the image, and spread: from 32 of them on (images of 32 K
     * pixels and more), every cell of a 4 x 4 grid over the image holds one. Few at most: 128, and no more
     * than one pixel in 1024.
     */
    @Test
    void theWarmUpPixelsAreFewAndSpreadOverTheImage() {
        int[][] sizes = {{1920, 1440}, {1920, 1080}, {640, 480}, {33, 1000}, {1000, 33}, {182, 182}};
        for (int[] wh : sizes) {
            int w = wh[0], h = wh[1], n = Renderer.warmUpPixels(w, h);
            assertTrue(n >= 32 && n <= 128 && n <= (long) w * h / 1024, w + "x" + h + ": " + n);
            Set<Integer> seen = new HashSet<>();
            Set<Integer> cells = new HashSet<>();
            for (int k = 0; k < n; k++) {
                int p = Renderer.warmUpPixel(k, w, h);
                assertTrue(p >= 0 && p < w * h, w + "x" + h + " pixel " + k + ": " + p);
                assertTrue(seen.add(p), w + "x" + h + ": pixel " + p + " twice");
                cells.add((p % w) * 4 / w * 4 + (p / w) * 4 / h);
            }
            assertEquals(16, cells.size(), w + "x" + h + ": cells of a 4 x 4 grid reached");
        }
        assertEquals(128, Renderer.warmUpPixels(4000, 4000));
        assertEquals(0, Renderer.warmUpPixels(31, 33));
        assertEquals(1, Renderer.warmUpPixels(32, 32));
    }
}
