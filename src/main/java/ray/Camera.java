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
        frame(u, v, w);
        halfHeight = Math.tan(Math.toRadians(yFOV) / 2);
        halfWidth = (Double.isNaN(aspect) ? 1 : aspect) * halfHeight;
    }

    /** The camera frame from eye, target and up into {@code u}, {@code v}, {@code w}. */
    private void frame(Vector3d u, Vector3d v, Vector3d w) {
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
        // the fields written here rather than by Ray.set: C1 does not inline that call (71 bytes)
        Vector3d o = r.origin, d = r.direction;
        o.x = eye.x;
        o.y = eye.y;
        o.z = eye.z;
        d.x = dx / len;
        d.y = dy / len;
        d.z = dz / len;
        r.tMin = 0;
        r.tMax = Double.POSITIVE_INFINITY;
        r.depth = 0;
    }

    /**
     * True when this camera's rays are {@link #setRay}'s as written here (its class overrides no ray
     * method): a renderer may then form them from {@link #rayTerms} tables, bit for bit the same.
     */
    public final boolean standardRays() {
        return !OWN_RAYS.get(getClass());
    }

    /**
     * {@link #setRay}'s products, once per image-plane coordinate: a u for each {@code a[k]} into
     * {@code au[3k..3k+2]}, b v for each {@code b[k]} into {@code bv[3k..3k+2]}. The ray through (a, b)
     * is then (a u + b v - w) normalised, which is {@code setRay(r, a, b)}'s direction.
     */
    public final void rayTerms(double[] a, double[] au, double[] b, double[] bv) {
        for (int k = 0; k < a.length; k++) {
            au[3 * k] = a[k] * u.x;
            au[3 * k + 1] = a[k] * u.y;
            au[3 * k + 2] = a[k] * u.z;
        }
        for (int k = 0; k < b.length; k++) {
            bv[3 * k] = b[k] * v.x;
            bv[3 * k + 1] = b[k] * v.y;
            bv[3 * k + 2] = b[k] * v.z;
        }
    }

    /** True for a class that makes its camera rays its own way (overrides a ray method): nothing is projected for it. */
    private static final ClassValue<Boolean> OWN_RAYS = Overrides.overridesAny(Camera.class,
            new String[] {"setRay", "setRayThrough", "getRayThrough", "planeX", "planeY", "recalculate"},
            new Class<?>[][] {{Ray.class, double.class, double.class},
                              {Ray.class, double.class, double.class, double.class, double.class},
                              {double.class, double.class, double.class, double.class},
                              {double.class, double.class}, {double.class, double.class}, {}});

    /**
     * The pixels of a {@code width} x {@code height} image whose camera rays (any sample within the pixel)
     * can meet the box [min, max]: {x0, y0, x1, y1}, x0 <= x < x1, y0 <= y < y1 (empty when x0 == x1),
     * with a pixel's margin for rounding; the whole image where it cannot be narrowed (a corner of the box
     * at or behind the eye's plane, an infinite box, or a subclass making its own rays). The
     * render plan uses it to know which camera rays can see a surface.
     */
    public int[] pixelsSeeing(double minX, double minY, double minZ, double maxX, double maxY, double maxZ, int width, int height) {
        int[] all = {0, 0, Math.max(0, width), Math.max(0, height)};
        if (OWN_RAYS.get(getClass()) || width <= 0 || height <= 0) {
            return all;
        }
        // the frame and image-plane size the render will use (prepareCamera: the aspect from the image
        // size where the scene gave none), computed here, not read from a frame that may be stale
        Vector3d u = new Vector3d(), v = new Vector3d(), w = new Vector3d();
        try {
            frame(u, v, w);
        } catch (IllegalArgumentException e) {
            return all;
        }
        double halfHeight = Math.tan(Math.toRadians(yFOV) / 2);
        double halfWidth = (Double.isNaN(aspect) ? (double) width / height : aspect) * halfHeight;
        if (!(halfWidth > 0 && halfHeight > 0) || !Double.isFinite(halfWidth) || !Double.isFinite(halfHeight)) {
            return all;
        }
        double aMin = Double.POSITIVE_INFINITY, aMax = Double.NEGATIVE_INFINITY, bMin = aMin, bMax = aMax;
        for (int i = 0; i < 8; i++) {
            // a ray (a u + b v - w) t from the eye meets q = p - eye at t = -q.w, a = q.u / t, b = q.v / t;
            // a box in front of the eye projects inside the hull of its corners' projections
            double qx = ((i & 1) == 0 ? minX : maxX) - eye.x, qy = ((i & 2) == 0 ? minY : maxY) - eye.y,
                    qz = ((i & 4) == 0 ? minZ : maxZ) - eye.z;
            double t = -(qx * w.x + qy * w.y + qz * w.z);
            if (!(t > 1e-9 * (Math.abs(qx) + Math.abs(qy) + Math.abs(qz))) || !Double.isFinite(t)) {
                return all;
            }
            double a = (qx * u.x + qy * u.y + qz * u.z) / t, b = (qx * v.x + qy * v.y + qz * v.z) / t;
            aMin = Math.min(aMin, a);
            aMax = Math.max(aMax, a);
            bMin = Math.min(bMin, b);
            bMax = Math.max(bMax, b);
        }
        // planeX(x) = (2x / width - 1) halfWidth, planeY(y) = (1 - 2y / height) halfHeight: invert, one pixel of margin
        double x0 = (aMin / halfWidth + 1) * width / 2, x1 = (aMax / halfWidth + 1) * width / 2;
        double y0 = (1 - bMax / halfHeight) * height / 2, y1 = (1 - bMin / halfHeight) * height / 2;
        if (!(Double.isFinite(x0) && Double.isFinite(x1) && Double.isFinite(y0) && Double.isFinite(y1))) {
            return all;
        }
        int[] r = {clamp(Math.floor(x0) - 1, width), clamp(Math.floor(y0) - 1, height), clamp(Math.ceil(x1) + 1, width),
                clamp(Math.ceil(y1) + 1, height)};
        if (r[2] <= r[0] || r[3] <= r[1]) {
            r[2] = r[0];
            r[3] = r[1];
        }
        return r;
    }

    private static int clamp(double v, int n) {
        return (int) Math.max(0, Math.min(Math.max(0, n), v));
    }

    @Override
    public String toString() {
        return "Camera[eye " + eye + ", target " + target + ", up " + up + ", yFOV " + yFOV + ", aspect " + aspect + "]";
    }
}
