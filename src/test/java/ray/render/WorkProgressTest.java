package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** Progress counts pixels done, not tiles; the time left is extrapolated from that. */
class WorkProgressTest {

    @Test
    void countsPixelsNotTiles() {
        WorkProgress p = new WorkProgress(20, 10, 0, ProgressListener.NONE);
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
}
