package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import ray.settings.RenderSettings;

/** Progress counts pixels done, not tiles; the time left is extrapolated from that. */
class WorkProgressTest {

    @Test
    void countsPixelsNotTiles() {
        WorkProgress p = new WorkProgress(20, 10, new int[] {1}, 0, ProgressListener.NONE);
        assertEquals(-1, p.remainingNanos(5), "no estimate before any work is done");
        p.tileDone(null, 0, 0, 16, 10, 1, 2);          // 160 of 200 pixels in one of two tiles
        assertEquals(0.8, p.fraction(), 1e-12);
        assertEquals(250, p.remainingNanos(1000), "1000 ns for 80%: 250 ns left");
        p.tileDone(null, 16, 0, 20, 10, 2, 2);
        assertEquals(1.0, p.fraction());
        assertEquals(0, p.remainingNanos(2000));
        assertEquals(2000, p.elapsedNanos(2000));
    }

    @Test
    void passesEveryReportOn() {
        int[] seen = new int[1];
        WorkProgress p = new WorkProgress(4, 4, new ProgressListener() {
            @Override
            public void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                seen[0] += (x1 - x0) * (y1 - y0);
            }
        });
        p.tileDone(null, 0, 0, 4, 4, 1, 1);
        assertEquals(16, seen[0]);
    }

    @Test
    void passesCountBySamples() {
        // passes of 1, 3 and 5 samples per pixel on 10 pixels: 90 pixel-samples in all
        WorkProgress p = new WorkProgress(5, 2, new int[] {1, 3, 5}, 0, ProgressListener.NONE);
        p.tileDone(null, 0, 0, 5, 2, 1, 1);
        assertEquals(10.0 / 90, p.fraction(), 1e-12, "the first look is cheap");
        p.passDone(null, 0, 3);
        assertEquals(1, p.pass());
        p.tileDone(null, 0, 0, 5, 2, 1, 1);
        assertEquals(40.0 / 90, p.fraction(), 1e-12);
        p.passDone(null, 1, 3);
        p.tileDone(null, 0, 0, 5, 1, 1, 2);
        assertEquals(65.0 / 90, p.fraction(), 1e-12);
        p.tileDone(null, 0, 1, 5, 2, 2, 2);
        p.passDone(null, 2, 3);
        assertEquals(1.0, p.fraction());
        assertEquals(2, p.pass(), "stays at the last pass");
    }

    @Test
    void progressiveRenderEndsAtExactlyOne() throws Exception {
        String text = "Width 30\nHeight 20\nAASamples 5\n\nCamera Camera\nVector3d eye [0 0 5]\n\n"
                + "Material Diffuse m\n\nSurface Sphere\nref material m\n\nLight PointLight\nVector3d position [3 3 3]\n";
        ray.Scene scene = ray.parse.Parser.parse(text, "s.txt", new java.util.ArrayList<>());
        RenderSettings s = new RenderSettings().progressive(true);
        WorkProgress p = WorkProgress.of(scene, s, ProgressListener.NONE);
        assertEquals(4, p.passes(), "1, 4, 16 and 25 samples per pixel: passes of 1, 3, 12, 9");
        new Renderer(scene).threads(2).settings(s).listener(p).render();
        assertEquals(1.0, p.fraction(), 1e-12, "every pixel-sample counted once");
    }
}
