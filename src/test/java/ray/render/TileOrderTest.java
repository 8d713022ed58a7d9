package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;
import ray.parse.Parser;

/**
 * Issue 11 class 3 and issue 10's honest progress: a small image still uses every render thread, and
 * tiles are handed out spread over the image, so the share of pixels done tracks the share of work.
 */
class TileOrderTest {

    /** Records which threads shade, and takes a moment doing it (a costly user material). */
    public static class SlowRecorder extends Material {
        static final Set<String> THREADS = ConcurrentHashMap.newKeySet();

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            THREADS.add(Thread.currentThread().getName());
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return new Vector3d(1, 0, 0);
        }
    }

    private static Scene scene(int w, int h, String material) throws Exception {
        return Parser.parse("Width " + w + "\nHeight " + h + "\n\nCamera Camera\nVector3d eye [0 0 3]\nVector3d target [0 0 0]\n"
                + "double yFOV 90\n\nMaterial " + material + " m\n\nSurface Sphere\nVector3d center [0 0 0]\ndouble radius 10\nref material m\n",
                "t.txt", new ArrayList<>());
    }

    /** One 16 x 16 tile's worth of image, costly pixels, two threads: both threads render. */
    @Test
    void aOneTileImageUsesEveryThread() throws Exception {
        SlowRecorder.THREADS.clear();
        Image img = new Renderer(scene(16, 16, "ray.render.TileOrderTest$SlowRecorder")).threads(2).render();
        assertEquals(1.0, img.get(15, 15).x, 0);
        assertEquals(2, SlowRecorder.THREADS.size(), "threads that shaded: " + SlowRecorder.THREADS);
    }

    @Test
    void tilesShrinkOnlyForSmallImages() {
        assertEquals(Renderer.TILE, Renderer.tileSize(640, 480, 2));
        assertEquals(Renderer.TILE, Renderer.tileSize(64, 32, 2), "8 tiles for 2 threads");
        assertEquals(4, Renderer.tileSize(16, 16, 2), "16 tiles of 4 x 4");
        assertEquals(1, Renderer.tileSize(1, 1, 8), "a single pixel");
        for (int total = 1; total < 2000; total++) {
            long s = Renderer.spreadStride(total);
            boolean[] seen = new boolean[total];
            for (int k = 0; k < total; k++) {
                int t = (int) (k * s % total);
                assertTrue(!seen[t], "stride " + s + " repeats tile " + t + " of " + total);
                seen[t] = true;
            }
        }
    }

    /**
     * Whatever the work's layout, the first half of the tiles handed out covers the top and the bottom
     * halves of the image about equally (in scan order it was all top: an empty sky made the progress
     * race to 50% and then crawl).
     */
    @Test
    void theFirstHalfOfTheTilesIsSpreadOverTheImage() throws Exception {
        Scene s = scene(320, 240, "Diffuse");
        List<int[]> order = new ArrayList<>();
        new Renderer(s).threads(1).listener(new ProgressListener() {
            @Override
            public synchronized void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                order.add(new int[] {x0, y0, x1, y1});
            }
        }).render();
        long top = 0, bottom = 0;
        for (int[] t : order.subList(0, order.size() / 2)) {
            long area = (long) (t[2] - t[0]) * (t[3] - t[1]);
            if (t[1] < 120) {
                top += area;
            } else {
                bottom += area;
            }
        }
        double share = (double) top / (top + bottom);
        assertTrue(share > 0.4 && share < 0.6, "share of the first half's pixels in the top half: " + share);
    }
}
