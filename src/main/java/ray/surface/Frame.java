package ray.surface;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;

/**
 * An orthonormal frame (u, v, w) around a unit axis w, and the checks and record-filling the
 * primitives built on it share. The basis is the branch-free construction of Duff et al., "Building an
 * Orthonormal Basis, Revisited" (JCGT 6(1), 2017), continuous except where w.z changes sign and
 * orthonormal to rounding.
 *
 * <p>Local coordinates of a world vector a are (a.u, a.v, a.w); a local point (x, y, z) is
 * {@code x u + y v + z w} in world coordinates. Immutable; shared by every thread.
 */
final class Frame {

    /** Unit roundoff of double. */
    static final double EPS = 0x1p-53;

    final double ux, uy, uz, vx, vy, vz, wx, wy, wz;

    /** The frame around {@code (ax, ay, az)}, which must be finite and not zero (it is normalised here). */
    Frame(double ax, double ay, double az) {
        double len = Math.sqrt(ax * ax + ay * ay + az * az);
        wx = ax / len;
        wy = ay / len;
        wz = az / len;
        double sign = Math.copySign(1.0, wz);
        double a = -1.0 / (sign + wz);
        double b = wx * wy * a;
        ux = 1.0 + sign * wx * wx * a;
        uy = sign * b;
        uz = -sign * wx;
        vx = b;
        vy = sign + wy * wy * a;
        vz = -wy;
    }

    double u(double x, double y, double z) {
        return x * ux + y * uy + z * uz;
    }

    double v(double x, double y, double z) {
        return x * vx + y * vy + z * vz;
    }

    double w(double x, double y, double z) {
        return x * wx + y * wy + z * wz;
    }

    /** World x, y, z of the local vector (a, b, c). */
    double worldX(double a, double b, double c) {
        return a * ux + b * vx + c * wx;
    }

    double worldY(double a, double b, double c) {
        return a * uy + b * vy + c * wy;
    }

    double worldZ(double a, double b, double c) {
        return a * uz + b * vz + c * wz;
    }

    /** Half the world extent, along world axis i (0, 1, 2), of a circle of radius 1 around w. */
    double circleExtent(int axis) {
        double c = axis == 0 ? wx : axis == 1 ? wy : wz;
        return Math.sqrt(Math.max(0, 1 - c * c));
    }

    // ---- shared by the primitives ----

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
