package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;

/**
 * The small numerics the extension primitives' kernels share: the unit roundoff their error bounds are
 * written in, the largest coordinate of a vector, clamping, and the record's normal turned to face the ray.
 */
final class HitMath {

    /** Unit roundoff of double. */
    static final double EPS = 0x1p-53;

    private HitMath() {
    }

    /** v limited to [lo, hi]. */
    static double clamp(double v, double lo, double hi) {
        return v < lo ? lo : v > hi ? hi : v;
    }

    /** Largest |coordinate| of a vector. */
    static double maxAbs(Vector3d v) {
        return Math.max(Math.abs(v.x), Math.max(Math.abs(v.y), Math.abs(v.z)));
    }

    /**
     * Sets the record's normal to the unit outward normal (nx, ny, nz) turned to face the ray (negated when
     * {@code front} is false, i.e. the ray arrives from inside or from the back) and its front-face flag.
     */
    static void face(IntersectionRecord rec, double nx, double ny, double nz, boolean front) {
        if (front) {
            rec.normal.set(nx, ny, nz);
        } else {
            rec.normal.set(-nx, -ny, -nz);
        }
        rec.frontFace = front;
    }
}
