import javax.vecmath.Vector3d;

/**
 * A pinhole camera at {@code eye} looking at {@code target}.
 *
 * <pre>
 * Camera Camera
 * Vector3d eye [0 0 5]
 * Vector3d target [0 0 0]
 * Vector3d up [0 1 0]       # need not be perpendicular to the view direction
 * double yFOV 45            # vertical field of view in degrees
 * double aspect 1.3333      # width / height of the image plane (default: Width / Height)
 * </pre>
 */
public class Camera {

    public Vector3d eye = new Vector3d(0, 0, 5);
    public Vector3d target = new Vector3d();
    public Vector3d up = new Vector3d(0, 1, 0);
    public double yFOV = 45;
    /** Width / height of the image plane; the parser sets it to Width / Height when a scene does not. */
    public double aspect = 4.0 / 3;

    /** The camera frame, set by {@link #recalculate()}: unit vectors, u to the right, v up, w backwards. */
    public Vector3d u = new Vector3d(), v = new Vector3d(), w = new Vector3d();

    /**
     * Method 3 of 11. Sets the frame u, v, w from eye, target and up:
     * w = normalize(eye - target), u = normalize(up x w), v = w x u.
     * The framework calls it once after reading the scene (and again whenever the camera changes).
     */
    public void recalculate() {
        // BEGIN SOLUTION
        // STUB: // TODO: method 3 of 11
        w.sub(eye, target);
        w.normalize();
        u.cross(up, w);
        u.normalize();
        v.cross(w, u);
        // END SOLUTION
    }

    /**
     * Method 4 of 11. The ray from the eye through the point (x, y) of a width x height pixel grid, where
     * (0, 0) is the top-left corner of the image and (width, height) the bottom-right: the centre of
     * pixel (i, j) is (i + 0.5, j + 0.5).
     *
     * <p>The image plane lies at distance 1 in front of the eye (along -w). It spans
     * 2 tan(yFOV / 2) vertically (yFOV is in degrees) and aspect times that horizontally. Image x grows
     * along u (left to right); image y grows along -v, so the top row of the image is on the up side.
     * Return a new Ray starting at the eye with a unit-length direction, so that t is the distance
     * from the eye.
     */
    public Ray getRayThrough(double x, double y, double width, double height) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 4 of 11
        // STUB: return null;
        double halfHeight = Math.tan(Math.toRadians(yFOV) / 2);
        double halfWidth = aspect * halfHeight;
        double a = (2 * x / width - 1) * halfWidth;
        double b = (1 - 2 * y / height) * halfHeight;
        Vector3d direction = new Vector3d();
        direction.scale(a, u);
        direction.scaleAdd(b, v, direction);
        direction.sub(w);
        direction.normalize();
        return new Ray(eye, direction);
        // END SOLUTION
    }

    @Override
    public String toString() {
        return "Camera[eye " + eye + ", target " + target + ", up " + up + ", yFOV " + yFOV + ", aspect " + aspect + "]";
    }
}
