package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.accel.Aabb;
import ray.accel.PrimitiveSet;
import ray.accel.RayQuery;

/** Built-in spheres packed for the BVH (centre and radius, 4 doubles each), tested with {@link Sphere#hit}. */
final class SphereSet extends PrimitiveSet {

    static final Type TYPE = new Type() {
        @Override
        public PrimitiveSet pack(List<Surface> surfaces) {
            return new SphereSet(surfaces);
        }

        @Override
        public Aabb bounds(Surface s, Aabb scratch) {   // Sphere.bounds() without a new box
            return Sphere.bounds((Sphere) s, scratch);
        }
    };

    private final double[] s;

    private SphereSet(List<Surface> list) {
        super(list);
        s = new double[4 * surfaces.length];
        for (int i = 0; i < surfaces.length; i++) {
            Sphere sp = (Sphere) surfaces[i];
            s[4 * i] = sp.center.x;
            s[4 * i + 1] = sp.center.y;
            s[4 * i + 2] = sp.center.z;
            s[4 * i + 3] = sp.radius;
        }
    }

    @Override
    public void closestHit(int from, int to, int slot, RayQuery q) {
        double[] sv = s;
        double ox = q.ox, oy = q.oy, oz = q.oz, dx = q.dx, dy = q.dy, dz = q.dz, tMin = q.tMin;
        for (int i = from, o = 4 * from; i < to; i++, o += 4, slot++) {
            double t = Sphere.hit(sv[o], sv[o + 1], sv[o + 2], sv[o + 3], ox, oy, oz, dx, dy, dz, tMin, q.tMax);
            if (t == t) {
                q.offer(t, this, i, slot);
            }
        }
    }

    @Override
    public boolean anyHit(int from, int to, RayQuery q) {
        double[] sv = s;
        double ox = q.ox, oy = q.oy, oz = q.oz, dx = q.dx, dy = q.dy, dz = q.dz, tMin = q.tMin, tMax = q.tMax;
        for (int i = from, o = 4 * from; i < to; i++, o += 4) {
            double t = Sphere.hit(sv[o], sv[o + 1], sv[o + 2], sv[o + 3], ox, oy, oz, dx, dy, dz, tMin, tMax);
            if (t == t) {
                return true;
            }
        }
        return false;
    }

    @Override
    public void fill(int i, RayQuery q, IntersectionRecord rec) {
        int o = 4 * i;
        Sphere.fill(s[o], s[o + 1], s[o + 2], s[o + 3], q.ox, q.oy, q.oz, q.dx, q.dy, q.dz, q.tMax, rec);
        rec.surface = surfaces[i];
    }

    @Override
    public long memoryBytes() {
        return 8L * s.length + 4L * surfaces.length;
    }
}
