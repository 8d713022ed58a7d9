package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;

/** {@link Renderer#raysSoFar()}: a live count while the render runs (the viewer's rays/s), exact at the end. */
class LiveRayCountTest {

    @Test
    void countsWhileRenderingAndEqualsTheTotalAtTheEnd() throws Exception {
        Scene scene = Parser.parse("""
                Width 64
                Height 48
                AASamples 2
                Camera Camera
                Vector3d eye [0 0 5]
                Material Diffuse grey
                Light PointLight
                Vector3d position [3 3 3]
                Surface Sphere
                ref material grey
                """, "live.txt", new ArrayList<>());
        Renderer r = new Renderer(scene).threads(2);
        List<Long> seen = new ArrayList<>();
        r.listener(new ProgressListener() {
            @Override
            public void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                synchronized (seen) {
                    seen.add(r.raysSoFar());
                }
            }
        });
        r.render();
        long total = r.stats().total();
        assertEquals(total, r.raysSoFar());
        assertTrue(total > 64 * 48 * 4, "camera and shadow rays: " + total);
        // during the render the live count has grown past zero and never passed the final total
        assertTrue(seen.stream().anyMatch(n -> n > 0), seen.toString());
        assertTrue(seen.stream().allMatch(n -> n <= total), seen.toString());
        assertTrue(seen.stream().anyMatch(n -> n < total), "some tile reported before the last rays: " + seen);
    }
}
