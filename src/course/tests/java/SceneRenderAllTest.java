import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** renderPixel here is a test stand-in that colours pixel (x, y) with (x, y, 0). */
@ExtendWith(NamesTheMethod.class)
@Order(11)
@Tag("method:Scene.renderAll")
@DisplayName("11. Scene.renderAll")
class SceneRenderAllTest {

    static final String M = "Scene.renderAll";

    static final class PixelScene extends Scene {
        int calls;

        @Override
        public Vector3d renderPixel(int x, int y) {
            calls++;
            return new Vector3d(x, y, 0);
        }
    }

    @Test
    @DisplayName("image[x][y] is renderPixel(x, y), width by height, row 0 at the top")
    void everyPixel() {
        PixelScene s = new PixelScene();
        s.width = 5;
        s.height = 3;
        Vector3d[][] image = s.renderAll();
        Expect.that(image != null, M, "it must return the image as a new Vector3d[width][height]", "returned null");
        Expect.that(image.length == 5, M, "a 5 x 3 image must be returned as image[x][y] with 5 columns (image.length == width)",
                "has " + image.length);
        for (int x = 0; x < 5; x++) {
            Expect.that(image[x] != null && image[x].length == 3, M, "column " + x + " must have 3 entries (height)",
                    "has " + (image[x] == null ? "null" : String.valueOf(image[x].length)));
            for (int y = 0; y < 3; y++) {
                Vector3d c = image[x][y];
                String hint = c != null && c.x == x && c.y == 2 - y ? " (yours is upside down: y = 0 is the top row, as renderPixel has it)"
                        : c != null && c.x == y && c.y == x ? " (yours swapped x and y)" : "";
                Expect.color(Expect.v(x, y, 0), c, M, "image[" + x + "][" + y + "], which must be renderPixel(" + x + ", " + y + ")" + hint);
            }
        }
        Expect.that(s.calls == 15, M, "it must call renderPixel once per pixel (15 for 5 x 3)", "called it " + s.calls + " times");
    }
}
