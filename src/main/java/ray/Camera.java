package ray;

import javax.vecmath.Vector3d;

/**
 * A pinhole camera. Frame: w = normalize(eye - target), u = normalize(up x w), v = w x u. The image
 * plane sits at distance 1 along -w, spans 2 tan(yFOV / 2) vertically and {@code aspect} times that
 * horizontally; image x grows along u and image y along -v, so row 0 is the {@code up} side.
 *
 * <pre>
 * Camera Camera
 * Vector3d eye [0 0 5]      # default [0 0 5]
 * Vector3d target [0 0 0]   # default [0 0 0]
 * Vector3d up [0 1 0]       # default [0 1 0]; need not be perpendicular to the view direction
 * double yFOV 45            # vertical field of view in degrees, default 45
 * double aspect 1.3333      # width / height of the image plane, default Width / Height
 * </pre>
 */
public class Camera implements SceneObject {

    public Vector3d eye = new Vector3d(0, 0, 5);
    public Vector3d target = new Vector3d();
    public Vector3d up = new Vector3d(0, 1, 0);
    public double yFOV = 45;
    /** Width / height of the image plane; NaN (the default) means the scene's Width / Height. */
    public double aspect = Double.NaN;

    /** The camera frame, set by {@link #recalculate()}. */
    public Vector3d u = new Vector3d(), v = new Vector3d(), w = new Vector3d();

    private double halfHeight, halfWidth;

    @Override
    public void init() {
        for (Vector3d p : new Vector3d[] {eye, target, up}) {
            if (!Double.isFinite(p.x) || !Double.isFinite(p.y) || !Double.isFinite(p.z)) {
                throw new IllegalArgumentException("camera eye, target and up must be finite, got " + p);
            }
        }
        if (!(yFOV > 0 && yFOV < 180)) {
            throw new IllegalArgumentException("yFOV must be between 0 and 180 degrees (exclusive), got " + yFOV);
        }
        if (!Double.isNaN(aspect) && !(aspect > 0 && Double.isFinite(aspect))) {
            throw new IllegalArgumentException("aspect must be a positive number, got " + aspect);
        }
        recalculate();
    }

    /** Computes u, v, w and the image-plane size from eye, target, up, yFOV and aspect. */
    public void recalculate() {
        double wx = eye.x - target.x, wy = eye.y - target.y, wz = eye.z - target.z;
        // lengths scaled by the largest component first: an eye at [1e308 1e308 1e308] is far, not "the same point"
        double wm = Math.max(Math.abs(wx), Math.max(Math.abs(wy), Math.abs(wz)));
        if (!Double.isFinite(wm)) {
            throw new IllegalArgumentException("camera eye " + eye + " and target " + target + " are too far apart: their difference "
                    + "overflows a double (expected coordinates within about +-8.9e307)");
        }
        if (!(wm > 0)) {
            throw new IllegalArgumentException("camera eye and target are the same point " + eye + "; the view direction is undefined");
        }
        wx /= wm;
        wy /= wm;
        wz /= wm;
        double wl = Math.sqrt(wx * wx + wy * wy + wz * wz);
        w.set(wx / wl, wy / wl, wz / wl);
        double um = Math.max(Math.abs(up.x), Math.max(Math.abs(up.y), Math.abs(up.z)));
        double sx = um > 0 && Double.isFinite(um) ? up.x / um : up.x, sy = um > 0 && Double.isFinite(um) ? up.y / um : up.y,
                sz = um > 0 && Double.isFinite(um) ? up.z / um : up.z;
        double ux = sy * w.z - sz * w.y, uy = sz * w.x - sx * w.z, uz = sx * w.y - sy * w.x;
        double ul = Math.sqrt(ux * ux + uy * uy + uz * uz);
        double upl = Math.sqrt(sx * sx + sy * sy + sz * sz);
        if (!(ul > 1e-12 * upl)) {
            throw new IllegalArgumentException("camera up " + up + " is zero or parallel to the view direction (eye - target)");
        }
        u.set(ux / ul, uy / ul, uz / ul);
        v.cross(w, u);
        halfHeight = Math.tan(Math.toRadians(yFOV) / 2);
        halfWidth = (Double.isNaN(aspect) ? 1 : aspect) * halfHeight;
    }

    /**
     * The ray from the eye through point (x, y) of a {@code width} x {@code height} pixel grid, (0, 0)
     * being the top-left corner: (i + 0.5, j + 0.5) is the centre of pixel (i, j). The direction has
     * unit length, so t is the distance from the eye.
     */
    public Ray getRayThrough(double x, double y, double width, double height) {
        Ray r = new Ray();
        setRayThrough(r, x, y, width, height);
        return r;
    }

    /** Allocation-free {@link #getRayThrough}: fills {@code r} as a camera ray (depth 0, t from 0). */
    public void setRayThrough(Ray r, double x, double y, double width, double height) {
        setRay(r, planeX(x, width), planeY(y, height));
    }

    /** Where image x (of {@code width} pixels) lies on the image plane, along u. */
    public double planeX(double x, double width) {
        return (2 * x / width - 1) * halfWidth;
    }

    /** Where image y (of {@code height} pixels, down from the top) lies on the image plane, along v. */
    public double planeY(double y, double height) {
        return (1 - 2 * y / height) * halfHeight;
    }

    /**
     * The camera ray through the image-plane point {@code a} u + {@code b} v - w (from {@link #planeX}
     * and {@link #planeY}; a renderer can compute those once per sample column and row).
     */
    public void setRay(Ray r, double a, double b) {
        double dx = a * u.x + b * v.x - w.x, dy = a * u.y + b * v.y - w.y, dz = a * u.z + b * v.z - w.z;
        double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        r.set(eye.x, eye.y, eye.z, dx / len, dy / len, dz / len, 0, Double.POSITIVE_INFINITY, 0);
    }

    @Override
    public String toString() {
        return "Camera[eye " + eye + ", target " + target + ", up " + up + ", yFOV " + yFOV + ", aspect " + aspect + "]";
    }
}
