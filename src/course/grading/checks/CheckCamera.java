import javax.vecmath.Vector3d;

/** Camera.recalculate (method 3) and Camera.getRayThrough (method 4), each alone. */
public final class CheckCamera {

    static final String R = "Camera.recalculate";
    static final String G = "Camera.getRayThrough";

    public static void frameLookingDownZ() {
        Camera c = new Camera();
        c.eye = GraderSupport.v(0, 0, 5);
        c.target = GraderSupport.v(0, 0, 0);
        c.up = GraderSupport.v(0, 1, 0);
        String situation = "eye (0, 0, 5), target (0, 0, 0), up (0, 1, 0)";
        GraderSupport.run(R, situation, c::recalculate);
        GraderSupport.expectVector(R, situation, "u", c.u, GraderSupport.v(1, 0, 0), 1e-9);
        GraderSupport.expectVector(R, situation, "v", c.v, GraderSupport.v(0, 1, 0), 1e-9);
        GraderSupport.expectVector(R, situation, "w (pointing backwards, from target to eye)", c.w, GraderSupport.v(0, 0, 1), 1e-9);
    }

    public static void frameWithTiltedUp() {
        Camera c = new Camera();
        c.eye = GraderSupport.v(4, 0, 0);
        c.target = GraderSupport.v(0, 0, 0);
        c.up = GraderSupport.v(1, 2, 0);
        String situation = "eye (4, 0, 0), target (0, 0, 0), up (1, 2, 0) (not perpendicular to the view, not unit length)";
        GraderSupport.run(R, situation, c::recalculate);
        GraderSupport.expectVector(R, situation, "w", c.w, GraderSupport.v(1, 0, 0), 1e-9);
        GraderSupport.expectVector(R, situation, "u", c.u, GraderSupport.v(0, 0, -1), 1e-9);
        GraderSupport.expectVector(R, situation, "v (unit, perpendicular to u and w)", c.v, GraderSupport.v(0, 1, 0), 1e-9);
    }

    /** A camera whose frame is set by hand (so recalculate is not involved). */
    static Camera framed() {
        Camera c = new Camera();
        c.eye = GraderSupport.v(1, 2, 3);
        c.target = GraderSupport.v(1, 2, 0);
        c.up = GraderSupport.v(0, 1, 0);
        c.u = GraderSupport.v(1, 0, 0);
        c.v = GraderSupport.v(0, 1, 0);
        c.w = GraderSupport.v(0, 0, 1);
        c.yFOV = 90;
        c.aspect = 2;
        return c;
    }

    static void ray(double x, double y, Vector3d want, String where) {
        Camera c = framed();
        String situation = "a camera at (1, 2, 3) looking down -z, yFOV 90, aspect 2, 200 x 100 pixels, point (" + GraderSupport.str(x)
                + ", " + GraderSupport.str(y) + ") (" + where + ")";
        Ray r = GraderSupport.call(G, situation, () -> c.getRayThrough(x, y, 200, 100));
        if (r == null) {
            throw GraderSupport.fail(G + ": " + situation + ": returned null instead of a Ray");
        }
        GraderSupport.expectVector(G, situation, "the ray's origin (the eye)", r.origin, GraderSupport.v(1, 2, 3), 1e-9);
        Vector3d d = new Vector3d(want);
        d.normalize();
        GraderSupport.expectVector(G, situation, "the ray's direction (unit length)", r.direction, d, 1e-6);
    }

    public static void centreRay() {
        ray(100, 50, GraderSupport.v(0, 0, -1), "the image centre");
    }

    public static void cornerRays() {
        ray(0, 0, GraderSupport.v(-2, 1, -1), "the top-left corner: y = 0 is the TOP row, on the up side");
        ray(200, 100, GraderSupport.v(2, -1, -1), "the bottom-right corner");
        ray(150, 25, GraderSupport.v(1, 0.5, -1), "a quarter in from the top-right");
    }
}
