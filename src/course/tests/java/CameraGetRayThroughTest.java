import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** The camera's frame is set by hand here, so these tests do not depend on your recalculate. */
@ExtendWith(NamesTheMethod.class)
@Order(4)
@Tag("method:Camera.getRayThrough")
@DisplayName("4. Camera.getRayThrough")
class CameraGetRayThroughTest {

    static final String M = "Camera.getRayThrough";

    /** A camera at (0, 0, 5) looking down -z, frame set by hand. */
    static Camera camera(double yFOV, double aspect) {
        Camera c = new Camera();
        c.eye = Expect.v(0, 0, 5);
        c.target = Expect.v(0, 0, 0);
        c.up = Expect.v(0, 1, 0);
        c.yFOV = yFOV;
        c.aspect = aspect;
        c.u = Expect.v(1, 0, 0);
        c.v = Expect.v(0, 1, 0);
        c.w = Expect.v(0, 0, 1);
        return c;
    }

    static Ray ray(Camera c, double x, double y, double w, double h) {
        Ray r = c.getRayThrough(x, y, w, h);
        Expect.that(r != null, M, "it must return a new Ray for the point (" + Expect.num(x) + ", " + Expect.num(y) + ")", "returned null");
        Expect.that(r.origin != null && r.direction != null, M, "the ray's origin and direction must not be null", "left one null");
        return r;
    }

    @Test
    @DisplayName("the centre of the image looks straight ahead, from the eye")
    void centre() {
        Ray r = ray(camera(90, 2), 100, 50, 200, 100);
        Expect.near(Expect.v(0, 0, 5), r.origin, M, "the origin of the ray through the centre (it starts at the eye)");
        Expect.near(Expect.v(0, 0, -1), r.direction, M, "the direction through the centre (100, 50) of a 200 x 100 image (straight along -w)");
    }

    @Test
    @DisplayName("the top-left corner (0, 0) is up and to the left; y grows downwards")
    void corners() {
        Camera c = camera(90, 2);
        Expect.near(Expect.unit(-2, 1, -1), ray(c, 0, 0, 200, 100).direction, M,
                "the direction through the top-left corner (0, 0), yFOV 90, aspect 2 (image plane x in [-2, 2], y in [-1, 1])");
        Expect.near(Expect.unit(2, -1, -1), ray(c, 200, 100, 200, 100).direction, M,
                "the direction through the bottom-right corner (200, 100): row 0 is the top of the image, so larger y goes down");
        Expect.near(Expect.unit(2, 1, -1), ray(c, 200, 0, 200, 100).direction, M,
                "the direction through the top-right corner (200, 0)");
    }

    @Test
    @DisplayName("the direction has unit length (so t is the distance from the eye)")
    void unitLength() {
        Ray r = ray(camera(60, 1.5), 3, 7, 30, 20);
        Expect.near(1, r.direction.length(), M, "the length of the ray's direction");
    }

    @Test
    @DisplayName("yFOV is in degrees and spans the whole height")
    void fieldOfView() {
        double t = Math.tan(Math.toRadians(30) / 2);
        Expect.near(Expect.unit(0, t, -1), ray(camera(30, 1), 50, 0, 100, 100).direction, M,
                "the direction through the middle of the top edge for yFOV 30 (degrees: tan(15 degrees) up for each 1 ahead)");
    }

    @Test
    @DisplayName("aspect sets the width of the image plane, whatever the pixel counts")
    void aspect() {
        Expect.near(Expect.unit(-3, 0, -1), ray(camera(90, 3), 0, 50, 100, 100).direction, M,
                "the direction through the middle of the left edge for aspect 3 on a 100 x 100 grid (x spans aspect times the height)");
    }

    @Test
    @DisplayName("the ray follows the camera's frame u, v, w")
    void usesTheFrame() {
        Camera c = camera(90, 1);
        c.eye = Expect.v(1, 2, 3);
        c.u = Expect.v(0, 0, -1);
        c.v = Expect.v(0, 1, 0);
        c.w = Expect.v(1, 0, 0);
        Ray r = ray(c, 0, 0, 10, 10);
        Expect.near(Expect.v(1, 2, 3), r.origin, M, "the origin for a camera at (1, 2, 3)");
        Expect.near(Expect.unit(-1, 1, 1), r.direction, M,
                "the direction through (0, 0) for u = (0, 0, -1), v = (0, 1, 0), w = (1, 0, 0) (direction = x u + y v - w)");
    }

    @Test
    @DisplayName("pixel (i, j)'s centre is (i + 0.5, j + 0.5)")
    void pixelCentre() {
        Ray r = ray(camera(90, 1), 0.5, 0.5, 2, 2);
        Expect.near(Expect.unit(-0.5, 0.5, -1), r.direction, M,
                "the direction through (0.5, 0.5) of a 2 x 2 grid, the centre of its top-left pixel");
    }
}
