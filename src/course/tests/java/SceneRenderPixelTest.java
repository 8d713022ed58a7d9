import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** The camera and trace here are test stand-ins that remember where the samples went. */
@ExtendWith(NamesTheMethod.class)
@Order(10)
@Tag("method:Scene.renderPixel")
@DisplayName("10. Scene.renderPixel")
class SceneRenderPixelTest {

    static final String M = "Scene.renderPixel";

    /** A camera that remembers the points asked for and returns a ray whose origin is that point. */
    static final class RecordingCamera extends Camera {
        final List<double[]> asked = new ArrayList<>();

        @Override
        public Ray getRayThrough(double x, double y, double width, double height) {
            asked.add(new double[] {x, y, width, height});
            return new Ray(Expect.v(x, y, 0), Expect.v(0, 0, -1));
        }
    }

    /** A scene whose trace colours a sample by where it went: (x, y, 1) for the point (x, y). */
    static final class PositionScene extends Scene {
        @Override
        public Vector3d trace(Ray ray) {
            return new Vector3d(ray.origin.x, ray.origin.y, 1);
        }
    }

    static PositionScene scene(int samples) {
        PositionScene s = new PositionScene();
        s.width = 40;
        s.height = 30;
        s.samplesPerPixel = samples;
        s.camera = new RecordingCamera();
        return s;
    }

    @Test
    @DisplayName("one sample: through the pixel's centre (x + 0.5, y + 0.5)")
    void oneSample() {
        PositionScene s = scene(1);
        Vector3d c = s.renderPixel(7, 3);
        List<double[]> asked = ((RecordingCamera) s.camera).asked;
        Expect.that(asked.size() == 1, M, "with AASamples 1 it must ask camera.getRayThrough for exactly one ray", "asked for " + asked.size());
        double[] a = asked.get(0);
        Expect.that(a[0] == 7.5 && a[1] == 3.5 && a[2] == 40 && a[3] == 30, M,
                "pixel (7, 3) of a 40 x 30 image must ask for getRayThrough(7.5, 3.5, 40, 30), the pixel's centre",
                "asked for (" + Expect.num(a[0]) + ", " + Expect.num(a[1]) + ", " + Expect.num(a[2]) + ", " + Expect.num(a[3]) + ")");
        Expect.color(Expect.v(7.5, 3.5, 1), c, M, "pixel (7, 3) (the colour trace returned for its one sample)");
    }

    @Test
    @DisplayName("n_s x n_s samples at the centres of a grid over the pixel, averaged")
    void grid() {
        PositionScene s = scene(3);
        Vector3d c = s.renderPixel(2, 5);
        List<double[]> asked = ((RecordingCamera) s.camera).asked;
        Expect.that(asked.size() == 9, M, "with AASamples 3 it must trace 3 x 3 = 9 samples per pixel", "traced " + asked.size());
        boolean[] found = new boolean[9];
        for (double[] a : asked) {
            for (int k = 0; k < 9; k++) {
                double x = 2 + (k % 3 + 0.5) / 3, y = 5 + (k / 3 + 0.5) / 3;
                if (Math.abs(a[0] - x) < 1e-9 && Math.abs(a[1] - y) < 1e-9) {
                    found[k] = true;
                }
            }
        }
        for (int k = 0; k < 9; k++) {
            double x = 2 + (k % 3 + 0.5) / 3, y = 5 + (k / 3 + 0.5) / 3;
            Expect.that(found[k], M, "with AASamples 3, pixel (2, 5) must have a sample at (" + Expect.num(x) + ", " + Expect.num(y)
                    + "), the centre of one of its 3 x 3 cells", "has none there");
        }
        Expect.color(Expect.v(2.5, 5.5, 1), c, M, "pixel (2, 5) with AASamples 3 (the mean of its 9 samples)");
    }

    @Test
    @DisplayName("values are kept as they are: no clamping")
    void noClamping() {
        Scene s = new Scene() {
            @Override
            public Vector3d trace(Ray ray) {
                return new Vector3d(2, -1, 0.5);
            }
        };
        s.width = 4;
        s.height = 4;
        s.camera = new RecordingCamera();
        Expect.color(Expect.v(2, -1, 0.5), s.renderPixel(1, 1), M, "samples of colour (2, -1, 0.5) (the PNG writer clamps, not renderPixel)");
    }
}
