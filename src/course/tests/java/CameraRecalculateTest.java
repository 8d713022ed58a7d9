import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

@ExtendWith(NamesTheMethod.class)
@Order(3)
@Tag("method:Camera.recalculate")
@DisplayName("3. Camera.recalculate")
class CameraRecalculateTest {

    static final String M = "Camera.recalculate";

    static Camera camera(Vector3d eye, Vector3d target, Vector3d up) {
        Camera c = new Camera();
        c.eye = eye;
        c.target = target;
        c.up = up;
        c.recalculate();
        return c;
    }

    static void frame(Camera c, Vector3d u, Vector3d v, Vector3d w, String which) {
        Expect.near(w, c.w, M, "w for " + which + " (w = normalize(eye - target))");
        Expect.near(u, c.u, M, "u for " + which + " (u = normalize(up x w))");
        Expect.near(v, c.v, M, "v for " + which + " (v = w x u)");
    }

    @Test
    @DisplayName("the default camera: eye (0, 0, 5), target (0, 0, 0), up (0, 1, 0)")
    void defaultCamera() {
        frame(camera(Expect.v(0, 0, 5), Expect.v(0, 0, 0), Expect.v(0, 1, 0)), Expect.v(1, 0, 0), Expect.v(0, 1, 0),
                Expect.v(0, 0, 1), "eye (0, 0, 5), target (0, 0, 0), up (0, 1, 0)");
    }

    @Test
    @DisplayName("up need not be perpendicular to the view direction")
    void upNotPerpendicular() {
        frame(camera(Expect.v(0, 0, 5), Expect.v(0, 0, 0), Expect.v(0, 1, 1)), Expect.v(1, 0, 0), Expect.v(0, 1, 0),
                Expect.v(0, 0, 1), "eye (0, 0, 5), target (0, 0, 0), up (0, 1, 1)");
    }

    @Test
    @DisplayName("looking along -x from (5, 0, 0)")
    void sideways() {
        frame(camera(Expect.v(5, 0, 0), Expect.v(0, 0, 0), Expect.v(0, 1, 0)), Expect.v(0, 0, -1), Expect.v(0, 1, 0),
                Expect.v(1, 0, 0), "eye (5, 0, 0), target (0, 0, 0), up (0, 1, 0)");
    }

    @Test
    @DisplayName("a rolled camera: up (1, 1, 0)")
    void rolled() {
        double h = Math.sqrt(0.5);
        frame(camera(Expect.v(0, 0, 3), Expect.v(0, 0, 0), Expect.v(1, 1, 0)), Expect.v(h, -h, 0), Expect.v(h, h, 0),
                Expect.v(0, 0, 1), "eye (0, 0, 3), target (0, 0, 0), up (1, 1, 0)");
    }

    @Test
    @DisplayName("any camera: u, v, w unit length, perpendicular and right-handed (u x v = w)")
    void orthonormal() {
        Random r = new Random(465);
        for (int i = 0; i < 20; i++) {
            Vector3d eye = Expect.v(r.nextGaussian() * 5, r.nextGaussian() * 5, r.nextGaussian() * 5);
            Vector3d target = Expect.v(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
            Vector3d up = Expect.v(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
            Camera c = camera(eye, target, up);
            String which = "eye " + Expect.show(eye) + ", target " + Expect.show(target) + ", up " + Expect.show(up);
            Expect.near(1, c.u.length(), M, "the length of u for " + which);
            Expect.near(1, c.v.length(), M, "the length of v for " + which);
            Expect.near(1, c.w.length(), M, "the length of w for " + which);
            Vector3d uxv = new Vector3d();
            uxv.cross(c.u, c.v);
            Expect.near(c.w, uxv, M, "u x v (it must equal w: a right-handed frame) for " + which);
            Vector3d back = new Vector3d();
            back.sub(eye, target);
            back.normalize();
            Expect.near(back, c.w, M, "w (pointing from the target back to the eye) for " + which);
        }
    }
}
