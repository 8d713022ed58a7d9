package ray.accel;

/** An axis-aligned box, used when building the BVH. */
public final class Aabb {
    public double minX = Double.POSITIVE_INFINITY, minY = Double.POSITIVE_INFINITY, minZ = Double.POSITIVE_INFINITY;
    public double maxX = Double.NEGATIVE_INFINITY, maxY = Double.NEGATIVE_INFINITY, maxZ = Double.NEGATIVE_INFINITY;

    public Aabb() {
    }

    public Aabb(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        this.minX = minX; this.minY = minY; this.minZ = minZ;
        this.maxX = maxX; this.maxY = maxY; this.maxZ = maxZ;
    }

    /** Makes this box empty again (what {@code new Aabb()} is) and returns it, for reuse without allocating. */
    public Aabb reset() {
        return set(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY);
    }

    /** Sets all six bounds and returns this box. */
    public Aabb set(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
        this.minX = minX; this.minY = minY; this.minZ = minZ;
        this.maxX = maxX; this.maxY = maxY; this.maxZ = maxZ;
        return this;
    }

    public static Aabb infinite() {
        double i = Double.POSITIVE_INFINITY;
        return new Aabb(-i, -i, -i, i, i, i);
    }

    /** True when every bound is a finite number and min <= max. */
    public boolean isFinite() {
        return Double.isFinite(minX) && Double.isFinite(minY) && Double.isFinite(minZ)
                && Double.isFinite(maxX) && Double.isFinite(maxY) && Double.isFinite(maxZ)
                && minX <= maxX && minY <= maxY && minZ <= maxZ;
    }

    public void include(double x, double y, double z) {
        if (x < minX) minX = x;
        if (y < minY) minY = y;
        if (z < minZ) minZ = z;
        if (x > maxX) maxX = x;
        if (y > maxY) maxY = y;
        if (z > maxZ) maxZ = z;
    }

    @Override
    public String toString() {
        return "Aabb[" + minX + " " + minY + " " + minZ + " .. " + maxX + " " + maxY + " " + maxZ + "]";
    }
}
