package ray;

/**
 * A few rays cast together, each with its own hit record and hit flag: camera rays leaving the eye,
 * cast by {@link Scene#castCameras} and shaded one by one with {@link Scene#shadeCamera}. One per
 * render thread ({@link TraceContext#packet}), grown once to the size a render asks for: no allocation
 * per ray.
 */
public final class RayPacket {

    /** Rays in use: {@code rays[0..size-1]}. */
    public int size;
    public Ray[] rays = new Ray[0];
    /** Ray k's closest hit, valid where {@code hit[k]}. */
    public IntersectionRecord[] records = new IntersectionRecord[0];
    public boolean[] hit = new boolean[0];

    /** Makes room for {@code n} rays (keeping those made before). */
    public void reserve(int n) {
        int old = rays.length;
        if (n <= old) {
            return;
        }
        rays = java.util.Arrays.copyOf(rays, n);
        records = java.util.Arrays.copyOf(records, n);
        hit = new boolean[n];
        for (int i = old; i < n; i++) {
            rays[i] = new Ray();
            records[i] = new IntersectionRecord();
        }
    }
}
