package ray.surface;

/**
 * An orthonormal frame (u, v, w) around a unit axis w: the local coordinates of the primitives with an
 * axis (Disc, Cylinder, Cone, Torus). The basis is the branch-free construction of Duff et al., "Building an
 * Orthonormal Basis, Revisited" (JCGT 6(1), 2017), continuous except where w.z changes sign and
 * orthonormal to rounding.
 *
 * <p>Local coordinates of a world vector a are (a.u, a.v, a.w); a local point (x, y, z) is
 * {@code x u + y v + z w} in world coordinates. Immutable; shared by every thread.
 */
final class Frame {

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
}
