package ray.surface;

import javax.vecmath.Vector3d;

/**
 * The argument checks of the primitives' {@code init()}: each refuses a value with an
 * IllegalArgumentException whose message the parser reports at the object's line.
 */
final class Checks {

    private Checks() {
    }

    /** Refuses a vector with a NaN or infinite coordinate (the parser refuses those already; code may not). */
    static void requireFinite(Vector3d v, String what) {
        if (!Double.isFinite(v.x) || !Double.isFinite(v.y) || !Double.isFinite(v.z)) {
            throw new IllegalArgumentException(what + " must be finite, got " + v);
        }
    }

    /** Refuses a zero-length (or non-finite) direction vector. */
    static void requireDirection(Vector3d v, String what) {
        requireFinite(v, what);
        double len2 = v.x * v.x + v.y * v.y + v.z * v.z;
        if (!(len2 > 0) || !Double.isFinite(len2)) {
            throw new IllegalArgumentException(what + " must have a non-zero length, got " + v);
        }
    }

    /** Refuses a length that is not a positive finite number. */
    static void requirePositive(double x, String what) {
        if (!(x > 0) || !Double.isFinite(x)) {
            throw new IllegalArgumentException(what + " must be a positive number, got " + x);
        }
    }
}
