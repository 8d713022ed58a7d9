package ray;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.parse.Parser;

class SmokeTest {

    /** Nothing in the scene: every pixel is the background colour. */
    @Test
    void emptySceneIsBackground() throws Exception {
        Scene s = Parser.parse("Width 4\nHeight 3\nBGColor [0.25 0.5 1]\n\nCamera Camera\n", "empty.txt", new ArrayList<>());
        Vector3d[][] img = s.renderAll();
        assertEquals(4, img.length);
        assertEquals(3, img[0].length);
        assertEquals(new Vector3d(0.25, 0.5, 1), img[3][2]);
    }
}
