package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.accel.Aabb;

/**
 * What {@link Cylinder} and {@link Cone} share: a closed solid of revolution standing on a disc of
 * {@code radius} around {@code base}, reaching {@code axis} (whose length is the height) along its
 * axis, intersected in its own frame (z along the axis, the base at z = 0) and filled in from there.
 */
public abstract class AxialSurface extends Surface {

    /** Relative rounding-error bound of a hit point moved back to world coordinates (generous). */
    static final double ERROR = 64 * HitMath.EPS;

    public Vector3d base = new Vector3d();
    public Vector3d axis = new Vector3d(0, 1, 0);
    public double radius = 1;

    /** The frame around {@code axis} and its length, derived by {@link #init()}. */
    // private: the parser lets a scene set any field that is not private, static or final, and these
    // are derived by init() from base and axis (issue 17: they were listed as settable)
    private Frame frame = new Frame(0, 1, 0);
    private double height = 1;

    /** The local frame (w along the axis), derived by {@link #init()}. */
    final Frame frame() {
        return frame;
    }

    /** The axis's length, derived by {@link #init()}. */
    final double height() {
        return height;
    }

    @Override
    public void init() {
        String name = getClass().getSimpleName().toLowerCase(java.util.Locale.ROOT);
        Checks.requireFinite(base, name + " base");
        Checks.requireDirection(axis, name + " axis");
        Checks.requirePositive(radius, name + " radius");
        frame = new Frame(axis.x, axis.y, axis.z);
        height = axis.length();
    }

    /** The solid's radius at height z along the axis (0 <= z <= height). */
    abstract double radiusAt(double z);

    /**
     * Fills the record from the local hit point (x, y, z) and unit outward local normal: world
     * coordinates, normal facing the ray ({@code front}: the ray enters), t, error bound, surface.
     */
    final void fill(IntersectionRecord rec, double t, double x, double y, double z,
                    double nx, double ny, double nz, boolean front) {
        Frame f = frame;
        rec.location.set(base.x + f.worldX(x, y, z), base.y + f.worldY(x, y, z), base.z + f.worldZ(x, y, z));
        HitMath.face(rec, f.worldX(nx, ny, nz), f.worldY(nx, ny, nz), f.worldZ(nx, ny, nz), front);
        rec.t = t;
        rec.error = ERROR * (HitMath.maxAbs(base) + radius + height);
        rec.surface = this;
    }

    /** True when (x, y, z) lies strictly inside the solid. */
    public boolean isInside(double x, double y, double z) {
        double ex = x - base.x, ey = y - base.y, ez = z - base.z;
        double a = frame.u(ex, ey, ez), b = frame.v(ex, ey, ez), c = frame.w(ex, ey, ez);
        double r = radiusAt(c);
        return c > 0 && c < height && a * a + b * b < r * r;
    }

    /** Closed: a solid, hit from inside with {@code frontFace} false, so it can be a CSG operand. */
    @Override
    public boolean isClosed() {
        return true;
    }

    @Override
    public Aabb bounds() {
        double pad = 1e-12 * (HitMath.maxAbs(base) + radius + height);
        Aabb b = new Aabb();
        for (int end = 0; end < 2; end++) {
            double r = radiusAt(end * height);
            double cx = base.x + end * axis.x, cy = base.y + end * axis.y, cz = base.z + end * axis.z;
            double ex = r * frame.circleExtent(0) + pad;
            double ey = r * frame.circleExtent(1) + pad;
            double ez = r * frame.circleExtent(2) + pad;
            b.include(cx - ex, cy - ey, cz - ez);
            b.include(cx + ex, cy + ey, cz + ez);
        }
        return b;
    }
}
