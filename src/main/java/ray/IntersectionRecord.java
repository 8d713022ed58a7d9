package ray;

import javax.vecmath.Vector3d;
import ray.surface.Surface;

/**
 * What a ray hit: the framework's record, plus what robust secondary rays need.
 *
 * <p>{@code normal} is the unit normal turned to face the incoming ray (so the inside of a sphere is
 * shaded as seen), {@code frontFace} says whether the ray arrived on the outward side, and
 * {@code error} bounds, per coordinate, how far the computed {@code location} may be from the true
 * surface point. {@link #spawnRay} and {@link #spawnRayTo} are the one place a new ray is offset off
 * the surface, by that bound, so self-intersection is avoided at every scale.
 */
public class IntersectionRecord {

    /** Fraction of a shadow ray's length left out at the light end (a light on a surface is unshadowed). */
    public static final double SHADOW_END = 1e-7;
    /**
     * Distance left out at the light end, relative to the light's largest coordinate (1024 eps, about
     * 1.1e-13): a light placed on a surface is off it by its rounding, so far from the origin and close
     * to the shading point the fraction {@link #SHADOW_END} alone would let that surface shadow it.
     */
    public static final double TARGET_ERROR = 1024 * 0x1p-53;
    /** (SHADOW_END / 2)^2: a target error whose square is below it times the squared length is surely under SHADOW_END. */
    private static final double SHORT_END_SQUARED = 0.25 * SHADOW_END * SHADOW_END;

    public Vector3d location = new Vector3d();
    public Vector3d normal = new Vector3d();
    public double t;
    public Surface surface;
    /** True when the ray arrived on the side the surface's outward normal points to. */
    public boolean frontFace = true;
    /** Absolute bound on the rounding error of each coordinate of {@code location}; 0 = unknown. */
    public double error;
    /**
     * Where rays leaving on the normal's side start from, relative to {@code location}: set by a smooth
     * mesh (Hanika's shadow-terminator lift, {@code ray.surface.Mesh}) for the hit at {@link #liftT} on
     * {@link #liftSurface}, and ignored for any other hit, so no other surface has to clear it.
     */
    public final Vector3d lift = new Vector3d();
    public Surface liftSurface;
    public double liftT;

    public IntersectionRecord() {
    }

    /** Copies every field of {@code other} into this record. */
    public void set(IntersectionRecord other) {
        location.set(other.location);
        normal.set(other.normal);
        t = other.t;
        surface = other.surface;
        frontFace = other.frontFace;
        error = other.error;
        lift.set(other.lift);
        liftSurface = other.liftSurface;
        liftT = other.liftT;
    }

    /** A new ray leaving the surface along {@code direction}, starting just off the surface on that side. */
    public Ray spawnRay(Vector3d direction) {
        Ray r = new Ray();
        spawnRay(direction.x, direction.y, direction.z, r);
        return r;
    }

    /**
     * A new ray from just off the surface to {@code target}: t runs from 0 to just short of 1 (short by
     * {@link #SHADOW_END} of the length or {@link #TARGET_ERROR} times the target's magnitude, whichever
     * is more), so a surface the target lies on does not block it.
     */
    public Ray spawnRayTo(Vector3d target) {
        Ray r = new Ray();
        spawnRayTo(target.x, target.y, target.z, r);
        return r;
    }

    /** Allocation-free {@link #spawnRay(Vector3d)}: sets {@code out}'s origin, direction and span; keeps its depth. */
    public void spawnRay(double dx, double dy, double dz, Ray out) {
        offsetOrigin(dx, dy, dz, out.origin);
        out.direction.x = dx;
        out.direction.y = dy;
        out.direction.z = dz;
        out.tMin = 0;
        out.tMax = Double.POSITIVE_INFINITY;
    }

    /** Allocation-free {@link #spawnRayTo(Vector3d)}. */
    public void spawnRayTo(double px, double py, double pz, Ray out) {
        offsetOrigin(px - location.x, py - location.y, pz - location.z, out.origin);
        out.direction.x = px - out.origin.x;
        out.direction.y = py - out.origin.y;
        out.direction.z = pz - out.origin.z;
        out.tMin = 0;
        // stop short of the target by a fraction of the length and by the target's own rounding error
        double len2 = out.direction.x * out.direction.x + out.direction.y * out.direction.y
                + out.direction.z * out.direction.z;
        // Math.max by comparisons (C1 calls Math.max on every shadow ray rather than inlining it); the
        // absolute values hold no -0, and a NaN still gives a NaN tMax, as Math.max would
        double ax = Math.abs(px), ay = Math.abs(py), az = Math.abs(pz);
        double m = ax >= ay ? ax : ay;
        m = m >= az ? m : az;
        double tm = TARGET_ERROR * m;
        // the usual case without the root and the division: (tm / len)^2 < (SHADOW_END / 2)^2 by a margin no
        // rounding can cross, so e < SHADOW_END below (a length^2 under 2^-900 or a NaN takes the long way)
        if (tm * tm < SHORT_END_SQUARED * len2 && len2 > 0x1p-900) {
            out.tMax = 1 - SHADOW_END;
            return;
        }
        double e = tm / Math.sqrt(len2);
        out.tMax = 1 - (e >= SHADOW_END || e != e ? e : SHADOW_END);
    }

    /**
     * The spawn point for a ray leaving along (dx, dy, dz): the hit point moved along the normal, to the
     * side the ray leaves on, by the error bound (the L1 norm of the normal makes the step cover the
     * bound in every coordinate; Wächter and Binder, Ray Tracing Gems ch. 6; pbrt-v4 OffsetRayOrigin).
     * A ray leaving a smooth mesh on its normal's side starts from the lifted point instead
     * ({@link #lift}: Hanika's shadow-terminator fix), so the flat facet under a smooth normal does not
     * shadow itself near the terminator.
     */
    private void offsetOrigin(double dx, double dy, double dz, Vector3d out) {
        double nx = normal.x, ny = normal.y, nz = normal.z;
        double err = error > 0 ? error : fallbackError();
        double d = err * (Math.abs(nx) + Math.abs(ny) + Math.abs(nz));
        double x = location.x, y = location.y, z = location.z;
        if (nx * dx + ny * dy + nz * dz < 0) {
            d = -d;
        } else if (liftSurface == surface && liftT == t && surface != null) {
            x += lift.x;
            y += lift.y;
            z += lift.z;
        }
        out.x = x + d * nx;
        out.y = y + d * ny;
        out.z = z + d * nz;
    }

    /** For surfaces that leave {@code error} unset: a bound generous enough for a textbook quadratic. */
    private double fallbackError() {
        double m = Math.max(Math.abs(location.x), Math.max(Math.abs(location.y), Math.abs(location.z)));
        return Math.max(m, Double.MIN_NORMAL) * 1e-9;
    }

    @Override
    public String toString() {
        return "Hit[t=" + t + ", at " + location + ", n " + normal + (frontFace ? "" : " (back)") + ", " + surface + "]";
    }
}
