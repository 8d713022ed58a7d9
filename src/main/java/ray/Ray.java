package ray;

import javax.vecmath.Vector3d;

/**
 * A ray {@code origin + t * direction} with its valid span {@code [tMin, tMax]}.
 *
 * <p>The framework's class, kept by name. {@link #EPSILON} is the framework's default {@code tMin};
 * it is not what keeps secondary rays off their own surface: {@link IntersectionRecord#spawnRay} and
 * {@link IntersectionRecord#spawnRayTo} offset the origin by a bound on the hit point's rounding
 * error, so shadows are right at any scale (see docs/robustness.md).
 */
public class Ray {

    /** Default lower end of a ray's span, kept for code written against the framework. */
    public static final double EPSILON = 1e-9;

    public Vector3d origin = new Vector3d();
    public Vector3d direction = new Vector3d();
    public double tMin = EPSILON;
    public double tMax = Double.POSITIVE_INFINITY;
    /** Bounce count: 0 for camera rays, one more for each mirror reflection. */
    public int depth;

    public Ray() {
    }

    /** A ray from {@code origin} along {@code direction}; both vectors are copied. */
    public Ray(Vector3d origin, Vector3d direction) {
        this.origin.set(origin);
        this.direction.set(direction);
    }

    /** Returns a new vector {@code origin + t * direction}. */
    public Vector3d evaluate(double t) {
        Vector3d p = new Vector3d();
        evaluate(t, p);
        return p;
    }

    /** Writes {@code origin + t * direction} into {@code out}. */
    public void evaluate(double t, Vector3d out) {
        out.x = origin.x + t * direction.x;
        out.y = origin.y + t * direction.y;
        out.z = origin.z + t * direction.z;
    }

    /** Sets every field at once (no allocation). */
    public void set(double ox, double oy, double oz, double dx, double dy, double dz,
                    double tMin, double tMax, int depth) {
        origin.x = ox; origin.y = oy; origin.z = oz;
        direction.x = dx; direction.y = dy; direction.z = dz;
        this.tMin = tMin;
        this.tMax = tMax;
        this.depth = depth;
    }

    @Override
    public String toString() {
        return "Ray[" + origin + " + t " + direction + ", t in [" + tMin + ", " + tMax + "], depth " + depth + "]";
    }
}
