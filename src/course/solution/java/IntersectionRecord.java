import javax.vecmath.Vector3d;

/** What a ray hit: filled in by {@link Surface#intersects} when it returns true. */
public class IntersectionRecord {

    /** The hit point. */
    public Vector3d location = new Vector3d();
    /** The unit surface normal at the hit, on the side the ray came from. */
    public Vector3d normal = new Vector3d();
    /** The ray parameter of the hit: location = ray.evaluate(t). */
    public double t;
    /** The surface that was hit (its material shades the point). */
    public Surface surface;

    public IntersectionRecord() {
    }

    /** Copies every field of {@code other} into this record. */
    public void set(IntersectionRecord other) {
        location.set(other.location);
        normal.set(other.normal);
        t = other.t;
        surface = other.surface;
    }

    @Override
    public String toString() {
        return "IntersectionRecord[t " + t + ", location " + location + ", normal " + normal + ", surface "
                + (surface == null ? "null" : surface.getClass().getSimpleName()) + "]";
    }
}
