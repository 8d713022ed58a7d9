package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;

/**
 * A point light of intensity I at a position; the light arriving at distance r is I / r^2, and a
 * surface between the light and the point casts a hard shadow.
 *
 * <pre>
 * Light PointLight
 * Vector3d position [5 5 5]      # default [0 0 0]
 * Vector3d intensity [20 20 20]  # default [1 1 1]
 * </pre>
 */
public class PointLight extends SampledLight {

    public Vector3d position = new Vector3d();
    public Vector3d intensity = new Vector3d(1, 1, 1);

    @Override
    public void init() {
        if (!finite(position) || !finite(intensity)) {
            throw new IllegalArgumentException("point light position and intensity must be finite numbers");
        }
    }

    @Override
    public boolean sample(IntersectionRecord record, Scene scene, int index, LightSample out) {
        double dx = position.x - record.location.x;
        double dy = position.y - record.location.y;
        double dz = position.z - record.location.z;
        double r2 = dx * dx + dy * dy + dz * dz;
        if (!(r2 > 0) || r2 == Double.POSITIVE_INFINITY) {
            return false;   // the light sits on the point: no direction, no finite amount
        }
        double r = Math.sqrt(r2);
        out.direction.set(dx / r, dy / r, dz / r);
        out.position.set(position);
        out.distance = r;
        double k = 1 / r2;
        double ix = intensity.x * k, iy = intensity.y * k, iz = intensity.z * k;
        out.intensity.set(ix, iy, iz);
        out.shadowTested = false;
        // a light closer than ~1e-154 would overflow I / r^2 (tested here: C1 calls finite() rather than inlining it)
        return Double.isFinite(ix) && Double.isFinite(iy) && Double.isFinite(iz);
    }

    @Override
    public boolean isDark() {
        return intensity.x == 0 && intensity.y == 0 && intensity.z == 0;
    }

    @Override
    public int shadowRaysPerPoint() {
        return 1;
    }

    static boolean finite(Vector3d v) {
        return Double.isFinite(v.x) && Double.isFinite(v.y) && Double.isFinite(v.z);
    }

    @Override
    public String toString() {
        return "PointLight[position " + position + ", intensity " + intensity + "]";
    }
}
