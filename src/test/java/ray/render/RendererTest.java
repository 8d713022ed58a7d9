package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.material.Diffuse;
import ray.material.Material;
import ray.parse.Parser;
import ray.surface.Triangle;

/** Threads, tiles, layout, counters and cancelling of the tiled renderer. */
class RendererTest {

    /** Mirrors (with and without base), a shiny and a matte sphere, a floor, three lights, AA 3. */
    private static final String BUSY = """
            Width 70
            Height 40
            AASamples 3
            MaxDepth 4
            BGColor [0.1 0.2 0.3]
            AmbientLight [0.2 0.2 0.2]

            Camera Camera
            Vector3d eye [0 1.5 6]
            Vector3d target [0 0 0]
            double yFOV 50

            Material BlinnPhong shiny
            Vector3d ambientColor [0.1 0.1 0.1]
            Vector3d diffuseColor [0.6 0.3 0.2]
            Vector3d specularColor [0.8 0.8 0.8]
            double exponent 40

            Material Diffuse matte
            Vector3d ambientColor [0.2 0.2 0.2]
            Vector3d diffuseColor [0.3 0.6 0.3]

            Material GlazedMaterial mirror
            ref base matte
            double mirrorCoefficient 0.6

            Material Glazed chrome
            double mirrorCoefficient 0.9

            Surface Sphere
            Vector3d center [-1.5 0 0]
            double radius 1
            ref material shiny

            Surface Sphere
            Vector3d center [1.5 0 0]
            double radius 1
            ref material chrome

            Surface Sphere
            Vector3d center [0 0.3 -2]
            double radius 1.3
            ref material mirror

            Surface Triangle
            Vector3d v0 [-20 -1 -20]
            Vector3d v1 [-20 -1 20]
            Vector3d v2 [20 -1 20]
            ref material matte

            Surface Triangle
            Vector3d v0 [-20 -1 -20]
            Vector3d v1 [20 -1 20]
            Vector3d v2 [20 -1 -20]
            ref material matte

            Light PointLight
            Vector3d position [4 6 5]
            Vector3d intensity [30 30 30]

            Light PointLight
            Vector3d position [-5 3 2]
            Vector3d intensity [10 5 5]

            Light PointLight
            Vector3d position [0 8 -6]
            Vector3d intensity [20 20 40]
            """;

    private static Scene parse(String text) throws Exception {
        return Parser.parse(text, "renderer-test.txt", new ArrayList<>());
    }

    /** The camera at (0, 0, 5) looks at the origin; globals and objects are added around it. */
    private static String facing(String globals, String objects) {
        return "Width 12\nHeight 8\n" + globals + "\n\nCamera Camera\n\n" + objects;
    }

    /** A triangle in z = 0 facing +z, far wider than the view: every camera ray hits it. */
    private static final String WALL = """
            Surface Triangle
            Vector3d v0 [-100 -100 0]
            Vector3d v1 [100 -100 0]
            Vector3d v2 [0 100 0]
            ref material m

            """;

    @Test
    void imageIsBitIdenticalForAnyThreadCount() throws Exception {
        Image one = new Renderer(parse(BUSY)).threads(1).render();
        Set<Double> distinct = new HashSet<>();
        for (double v : one.rgb) {
            distinct.add(v);
        }
        assertTrue(distinct.size() > 500, "the scene is not trivial: " + distinct.size() + " distinct values");
        for (int n : new int[] {2, 3, 8}) {
            Image img = new Renderer(parse(BUSY)).threads(n).render();
            assertTrue(Arrays.equals(one.rgb, img.rgb), n + " threads differ from 1 thread");
        }
    }

    /** BUSY with {@code aa} samples and a field of 300 small spheres: a BVH deep enough for camera-ray packets. */
    private static Scene crowded(int aa) throws Exception {
        StringBuilder b = new StringBuilder(BUSY.replace("AASamples 3", "AASamples " + aa));
        java.util.Random r = new java.util.Random(20);
        for (int i = 0; i < 300; i++) {
            b.append("Surface Sphere\nVector3d center [").append(-4 + 8 * r.nextDouble()).append(' ')
                    .append(-1 + 2 * r.nextDouble()).append(' ').append(-4 + 4 * r.nextDouble())
                    .append("]\ndouble radius ").append(0.05 + 0.15 * r.nextDouble())
                    .append(i % 3 == 0 ? "\nref material mirror\n\n" : "\nref material shiny\n\n");
        }
        return parse(b.toString());
    }

    /**
     * Where the BVH says packets pay, the grid render casts a block of camera rays together
     * (Renderer.packetTile): the image is bit for bit the one single rays give (a camera making its own
     * rays is traced ray by ray), for any thread count, and every camera ray is counted once.
     */
    @Test
    void cameraRayPacketsGiveTheSingleRaysImage() throws Exception {
        for (int aa : new int[] {1, 2, 3}) {
            Scene s = crowded(aa);
            Renderer packets = new Renderer(s).threads(1);
            Image one = packets.render();
            assertTrue(s.accelerator().packetsPay(), "the scene's BVH is deep enough for packets");
            assertEquals(70L * 40 * aa * aa, packets.stats().get(RayKind.CAMERA), "camera rays counted once each");
            Image own = new Renderer(withCamera(crowded(aa), new OwnRays())).threads(1).render();
            assertTrue(Arrays.equals(one.rgb, own.rgb), "packets differ from single rays, AASamples " + aa);
            Image three = new Renderer(crowded(aa)).threads(3).render();
            assertTrue(Arrays.equals(one.rgb, three.rgb), "3 threads differ from 1, AASamples " + aa);
        }
    }

    /** A camera whose class makes its own rays (it overrides setRay) is rendered through them. */
    static class OwnRays extends Camera {
        @Override
        public void setRay(Ray r, double a, double b) {
            super.setRay(r, a, b);
        }
    }

    private static Scene withCamera(Scene s, Camera c) {
        c.eye = s.camera.eye;
        c.target = s.camera.target;
        c.up = s.camera.up;
        c.yFOV = s.camera.yFOV;
        c.aspect = s.camera.aspect;
        s.camera = c;
        return s;
    }

    /**
     * The grid render forms a plain camera's rays from per-column and per-row tables (Renderer.gridTile):
     * the image is bit for bit the one setRay's rays give, and a subclass's own setRay is still called.
     */
    @Test
    void gridCameraRaysFromTablesAreSetRaysBitForBit() throws Exception {
        Image tables = new Renderer(parse(BUSY)).threads(2).render();
        Image own = new Renderer(withCamera(parse(BUSY), new OwnRays())).threads(2).render();
        assertTrue(Arrays.equals(tables.rgb, own.rgb), "the tables' rays differ from setRay's");
        Image up = new Renderer(withCamera(parse(BUSY), new OwnRays() {
            @Override
            public void setRay(Ray r, double a, double b) {
                super.setRay(r, a, b);
                r.direction.set(0, 1, 0);   // straight up, past everything: the background colour
            }
        })).threads(2).render();
        for (int i = 0; i < up.rgb.length; i += 3) {
            assertArrayEquals(new double[] {0.1, 0.2, 0.3}, Arrays.copyOfRange(up.rgb, i, i + 3), 1e-15, "pixel " + i / 3);
        }
    }

    /** The framework's renderAll() is [x][y] with y down from the top row. */
    @Test
    void renderAllIsIndexedXThenYFromTop() throws Exception {
        // a triangle with its right angle at the origin covering x < 0, y > 0: the image's top-left
        // quadrant of the 6 x 4 image (columns 0-2, rows 0-1); k_a I_a = (0.5, 0.25, 1)
        Scene s = Parser.parse("""
                Width 6
                Height 4
                AmbientLight [1 1 1]
                BGColor [0 0 0]

                Camera Camera

                Material Diffuse m
                Vector3d ambientColor [0.5 0.25 1]

                Surface Triangle
                Vector3d v0 [0 0 0]
                Vector3d v1 [0 100 0]
                Vector3d v2 [-100 0 0]
                ref material m
                """, "layout.txt", new ArrayList<>());
        Vector3d[][] img = s.renderAll();
        assertEquals(6, img.length);
        assertEquals(4, img[0].length);
        for (int x = 0; x < 6; x++) {
            for (int y = 0; y < 4; y++) {
                Vector3d expected = x < 3 && y < 2 ? new Vector3d(0.5, 0.25, 1) : new Vector3d();
                assertEquals(expected, img[x][y], "pixel (" + x + ", " + y + ")");
                assertEquals(expected, s.renderPixel(x, y), "renderPixel(" + x + ", " + y + ")");
            }
        }
    }

    /** A scene built in code, never prepared: renderPixel must still set up the camera first. */
    @Test
    void renderPixelWorksOnAHandBuiltScene() {
        Scene s = new Scene();
        s.width = 4;
        s.height = 4;
        s.camera = new Camera();
        s.ambientLight = new Vector3d(1, 1, 1);
        s.backgroundColor = new Vector3d(0, 0, 1);
        Diffuse m = new Diffuse();
        m.ambientColor = new Vector3d(1, 0, 0);
        Triangle t = new Triangle();     // covers x < 0, y > 0 as above: the top-left 2 x 2 pixels
        t.v1 = new Vector3d(0, 100, 0);
        t.v2 = new Vector3d(-100, 0, 0);
        t.material = m;
        s.surfaces.add(t);
        assertEquals(new Vector3d(1, 0, 0), s.renderPixel(0, 0));
        assertEquals(new Vector3d(0, 0, 1), s.renderPixel(3, 3));
        assertEquals(new Vector3d(1, 0, 0), s.renderAll()[1][1]);
    }

    @Test
    void listenerSeesEveryTileOnceAndEveryPixelIsCovered() throws Exception {
        Scene scene = parse(BUSY);
        int w = scene.width, h = scene.height;
        int size = Renderer.tileSize(w, h, 3);
        int tiles = ((w + size - 1) / size) * ((h + size - 1) / size);
        List<int[]> calls = new ArrayList<>();
        List<double[]> snapshots = new ArrayList<>();
        Image[] seen = new Image[1];
        Renderer r = new Renderer(scene).threads(3).listener(new ProgressListener() {
            @Override
            public synchronized void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                seen[0] = image;
                calls.add(new int[] {x0, y0, x1, y1, done, total});
                double[] copy = new double[3 * (x1 - x0) * (y1 - y0)];
                int k = 0;
                for (int y = y0; y < y1; y++) {
                    for (int x = x0; x < x1; x++) {
                        for (int c = 0; c < 3; c++) {
                            copy[k++] = image.rgb[3 * (y * w + x) + c];
                        }
                    }
                }
                snapshots.add(copy);
            }
        });
        Image img = r.render();
        assertSame(img, seen[0]);
        assertEquals(tiles, calls.size(), "one call per tile");
        int[] coverage = new int[w * h];
        Set<Integer> dones = new HashSet<>();
        for (int i = 0; i < calls.size(); i++) {
            int[] c = calls.get(i);
            assertEquals(tiles, c[5], "total");
            dones.add(c[4]);
            assertTrue(c[2] - c[0] <= size && c[3] - c[1] <= size, "tile size");
            int k = 0;
            for (int y = c[1]; y < c[3]; y++) {
                for (int x = c[0]; x < c[2]; x++) {
                    coverage[y * w + x]++;
                    for (int ch = 0; ch < 3; ch++) {
                        assertEquals(img.rgb[3 * (y * w + x) + ch], snapshots.get(i)[k++],
                                "pixel (" + x + ", " + y + ") was final when its tile was reported");
                    }
                }
            }
        }
        for (int i = 1; i <= tiles; i++) {
            assertTrue(dones.contains(i), "done count " + i + " reported");
        }
        for (int p = 0; p < w * h; p++) {
            assertEquals(1, coverage[p], "pixel (" + p % w + ", " + p / w + ") in exactly one tile");
        }
    }

    @Test
    void cameraRaysAreWidthTimesHeightTimesSamplesSquared() throws Exception {
        Renderer r = new Renderer(parse(BUSY)).threads(3);
        r.render();
        assertEquals(70L * 40 * 9, r.stats().get(RayKind.CAMERA));
        assertTrue(r.stats().get(RayKind.SHADOW) > 0 && r.stats().get(RayKind.MIRROR) > 0, r.stats().toString());
        assertEquals(0, r.stats().invalidSamples);
    }

    /** A shadow ray is cast only where the light is in front (n.l > 0): never for a light behind. */
    @Test
    void shadowRaysOnlyWhereLightIsInFront() throws Exception {
        String matte = "Material Diffuse m\n\n";
        String front = "Light PointLight\nVector3d position [0 0 3]\nVector3d intensity [9 9 9]\n\n";
        String behind = "Light PointLight\nVector3d position [1 2 -3]\nVector3d intensity [9 9 9]\n\n";
        long camera = 12 * 8 * 4;

        Renderer r = new Renderer(parse(facing("AASamples 2", matte + WALL + front))).threads(2);
        r.render();
        assertEquals(camera, r.stats().get(RayKind.CAMERA));
        assertEquals(camera, r.stats().get(RayKind.SHADOW), "one shadow ray per hit for a light in front");

        r = new Renderer(parse(facing("AASamples 2", matte + WALL + behind))).threads(2);
        r.render();
        assertEquals(0, r.stats().get(RayKind.SHADOW), "none for a light behind the wall");

        r = new Renderer(parse(facing("AASamples 2", matte + WALL + front + behind))).threads(2);
        r.render();
        assertEquals(camera, r.stats().get(RayKind.SHADOW), "one light in front, one behind");
        assertEquals(0, r.stats().get(RayKind.MIRROR));
    }

    @Test
    void mirrorRaysAreCountedAndBoundedByMaxDepth() throws Exception {
        String glazed = "Material Glazed m\ndouble mirrorCoefficient 0.5\n\n";
        Renderer r = new Renderer(parse(facing("MaxDepth 3", glazed + WALL))).threads(2);
        r.render();
        assertEquals(12 * 8, r.stats().get(RayKind.MIRROR), "one mirror ray per pixel: it flies off into the sky");

        r = new Renderer(parse(facing("MaxDepth 0", glazed + WALL))).threads(2);
        r.render();
        assertEquals(0, r.stats().get(RayKind.MIRROR), "MaxDepth 0 follows no mirror ray");
    }

    @Test
    void cancelFromListenerStopsRender() throws Exception {
        int[] calls = {0};
        Renderer[] self = new Renderer[1];
        self[0] = new Renderer(parse(BUSY)).threads(1).listener(new ProgressListener() {
            @Override
            public void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                calls[0]++;
                self[0].cancel();
            }
        });
        assertThrows(RenderCancelledException.class, () -> self[0].render());
        assertEquals(1, calls[0], "no tile is started after cancel()");

        Renderer many = new Renderer(parse(BUSY)).threads(3);
        many.listener(new ProgressListener() {
            @Override
            public void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                many.cancel();
            }
        });
        assertThrows(RenderCancelledException.class, many::render);
    }

    /** A bug in a user's material surfaces as its own exception from render(), not a hang or a NaN image. */
    @Test
    void exceptionInMaterialEndsRender() throws Exception {
        Scene s = parse(facing("", "Material Diffuse m\n\n" + WALL));
        s.surfaces.get(0).material = new Material() {
            @Override
            public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
                throw new ArithmeticException("student bug");
            }
        };
        ArithmeticException e = assertThrows(ArithmeticException.class, () -> new Renderer(s).threads(3).render());
        assertEquals("student bug", e.getMessage());
    }

    @Test
    void threadCountBelowOneIsRejected() throws Exception {
        assertThrows(IllegalArgumentException.class, () -> new Renderer(new Scene()).threads(0));
    }

    /** The samples are the centres of an n x n grid of sub-pixels, read as (dx, dy) row by row. */
    @Test
    void gridPatternIsSubPixelCentres() {
        double[] out = new double[8];
        for (int s = 0; s < 4; s++) {
            out[2 * s] = GridSampler.gridValue(2, s, 0);
            out[2 * s + 1] = GridSampler.gridValue(2, s, 1);
        }
        assertArrayEquals(new double[] {0.25, 0.25, 0.75, 0.25, 0.25, 0.75, 0.75, 0.75}, out);
    }
}
