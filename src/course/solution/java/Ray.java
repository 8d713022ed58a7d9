import javax.vecmath.Vector3d;

/**
 * A ray: the points {@code origin + t * direction} for t between {@link #tMin} and {@link #tMax}.
 *
 * <p>{@code tMin} starts at {@link #EPSILON}, not 0, so a ray leaving a surface (a shadow ray, a
 * mirror ray) does not hit that same surface again at t = 0 because of rounding ("shadow acne").
 */
public class Ray {

    /**
     * The smallest t a hit may have. Points computed with doubles lie off the true surface by about
     * 1e-15 times their size; 1e-6 leaves a wide margin for scenes the size of the samples (|p| up
     * to about 1000) and is still far below anything visible.
     */
    public static final double EPSILON = 1e-6;

    /** Where the ray starts. */
    public Vector3d origin = new Vector3d();
    /** Where it goes (need not have unit length; camera rays from Camera.getRayThrough do). */
    public Vector3d direction = new Vector3d();
    /** The valid span of t: only hits with tMin <= t <= tMax count. */
    public double tMin = EPSILON, tMax = Double.POSITIVE_INFINITY;
    /** Mirror bounces before this ray: 0 for a camera ray, one more for each mirror reflection. */
    public int depth;

    public Ray() {
    }

    /** A ray from {@code origin} along {@code direction} (both copied). */
    public Ray(Vector3d origin, Vector3d direction) {
        this.origin.set(origin);
        this.direction.set(direction);
    }

    /** The point at parameter t: origin + t * direction, as a new vector. */
    public Vector3d evaluate(double t) {
        Vector3d p = new Vector3d();
        p.scaleAdd(t, direction, origin);
        return p;
    }

    @Override
    public String toString() {
        return "Ray[origin " + origin + ", direction " + direction + ", t in [" + tMin + ", " + tMax + "], depth " + depth + "]";
    }
}
