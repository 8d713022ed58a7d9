package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The BVH must answer exactly what testing every surface would answer: the same closest t and
 * surface, the same any-hit verdict, for built-in triangles and spheres, a user's own bounded
 * surface inside the tree and an unbounded one outside it.
 */
class BvhTraversalTest {

    /** A user's surface: an axis-aligned box, with bounds, tested only through its own intersects. */
    public static class Box extends Surface {
        public Vector3d min = new Vector3d(), max = new Vector3d(1, 1, 1);

        @Override
        public boolean intersects(Ray ray, IntersectionRecord rec, Scene scene) {
            double t0 = ray.tMin, t1 = ray.tMax;
            double[] o = {ray.origin.x, ray.origin.y, ray.origin.z}, d = {ray.direction.x, ray.direction.y, ray.direction.z};
            double[] lo = {min.x, min.y, min.z}, hi = {max.x, max.y, max.z};
            int axis = -1;
            for (int a = 0; a < 3; a++) {
                double n = (lo[a] - o[a]) / d[a], f = (hi[a] - o[a]) / d[a];
                if (n > f) {
                    double t = n;
                    n = f;
                    f = t;
                }
                if (n > t0) {
                    t0 = n;
                    axis = a;
                }
                t1 = Math.min(t1, f);
            }
            if (!(t0 <= t1) || axis < 0) {
                return false;
            }
            rec.t = t0;
            ray.evaluate(t0, rec.location);
            rec.normal.set(axis == 0 ? 1 : 0, axis == 1 ? 1 : 0, axis == 2 ? 1 : 0);
            rec.surface = this;
            return true;
        }

        @Override
        public Aabb bounds() {
            return new Aabb(min.x, min.y, min.z, max.x, max.y, max.z);
        }
    }

    /** A user's unbounded surface (no bounds override): the plane y = level, seen from above. */
    public static class Floor extends Surface {
        public double level;

        @Override
        public boolean intersects(Ray ray, IntersectionRecord rec, Scene scene) {
            double t = (level - ray.origin.y) / ray.direction.y;
            if (!(t >= ray.tMin && t <= ray.tMax)) {
                return false;
            }
            rec.t = t;
            ray.evaluate(t, rec.location);
            rec.normal.set(0, 1, 0);
            rec.surface = this;
            return true;
        }
    }

    private static Vector3d rnd(Random r, double s) {
        return new Vector3d(s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1));
    }

    private static List<Surface> randomSurfaces(Random r, int tris, int spheres, int boxes) {
        List<Surface> l = new ArrayList<>();
        for (int i = 0; i < tris; i++) {
            Triangle t = new Triangle();
            Vector3d c = rnd(r, 10);
            t.v0 = new Vector3d(c);
            t.v1 = new Vector3d(c);
            t.v2 = new Vector3d(c);
            t.v0.add(rnd(r, 1));
            t.v1.add(rnd(r, 1));
            t.v2.add(rnd(r, 1));
            l.add(t);
        }
        for (int i = 0; i < spheres; i++) {
            Sphere s = new Sphere();
            s.center = rnd(r, 10);
            s.radius = 0.1 + r.nextDouble();
            l.add(s);
        }
        for (int i = 0; i < boxes; i++) {
            Box b = new Box();
            b.min = rnd(r, 10);
            b.max = new Vector3d(b.min);
            b.max.add(new Vector3d(r.nextDouble(), r.nextDouble(), r.nextDouble()));
            l.add(b);
        }
        return l;
    }

    /** Closest hit by testing every surface with the framework's intersects. */
    private static Surface bruteClosest(List<Surface> all, Ray ray, double[] tOut) {
        Surface best = null;
        double tMax = ray.tMax;
        IntersectionRecord rec = new IntersectionRecord();
        for (Surface s : all) {
            Ray r = new Ray(ray.origin, ray.direction);
            r.tMin = ray.tMin;
            r.tMax = tMax;
            if (!s.isDegenerate() && s.intersects(r, rec, null) && (best == null || rec.t < tMax)) {
                tMax = rec.t;
                best = s;
            }
        }
        tOut[0] = tMax;
        return best;
    }

    @Test
    void closestAndAnyHitAgreeWithTestingEverySurface() {
        Random r = new Random(4620);
        List<Surface> all = randomSurfaces(r, 400, 120, 40);
        Floor floor = new Floor();
        floor.level = -12;
        all.add(floor);
        Scene scene = new Scene();
        Bvh bvh = Bvh.build(all, scene);
        TraceContext ctx = new TraceContext(10);
        IntersectionRecord rec = new IntersectionRecord();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            Vector3d o = rnd(r, 15), d = rnd(r, 1);
            if (d.length() == 0) {
                continue;
            }
            Ray ray = new Ray(o, d);
            ray.tMin = r.nextInt(4) == 0 ? 0.5 * r.nextDouble() : 0;
            ray.tMax = r.nextInt(3) == 0 ? 1 + 20 * r.nextDouble() : Double.POSITIVE_INFINITY;
            double[] t = new double[1];
            Surface expected = bruteClosest(all, ray, t);
            double tMaxBefore = ray.tMax;
            boolean got = bvh.closestHit(ray, rec, ctx);
            assertEquals(tMaxBefore, ray.tMax, "the ray's span is left as it was");
            assertEquals(expected != null, got, () -> "closest hit of " + ray);
            assertEquals(expected != null, bvh.anyHit(ray, ctx), () -> "any hit of " + ray);
            if (expected != null) {
                hits++;
                assertEquals(t[0], rec.t, () -> "t of " + ray);
                assertSame(expected, rec.surface, () -> "surface hit by " + ray);
                double dn = rec.normal.dot(ray.direction);
                assertTrue(dn <= 0, "normal faces the ray");
            }
        }
        assertTrue(hits > 5_000, "the test rays should hit often: " + hits);
    }

    /** A scene big enough for the parallel build must give the same tree whatever the threads did. */
    @Test
    void parallelBuildIsDeterministicAndCoversEveryPrimitiveOnce() {
        Random r = new Random(17);
        int n = 3 * BvhBuilder.PARALLEL_MIN;
        double[] box = new double[6 * n];
        for (int i = 0; i < n; i++) {
            Vector3d c = rnd(r, 100);
            double e = r.nextDouble();
            box[6 * i] = c.x; box[6 * i + 1] = c.y; box[6 * i + 2] = c.z;
            box[6 * i + 3] = c.x + e; box[6 * i + 4] = c.y + e; box[6 * i + 5] = c.z + e;
        }
        BvhBuilder a = new BvhBuilder(box.clone()), b = new BvhBuilder(box.clone());
        a.build();
        b.build();
        assertEquals(a.root, b.root);
        assertTrue(java.util.Arrays.equals(a.order, b.order));
        assertTrue(java.util.Arrays.equals(a.nodeChild, b.nodeChild));
        assertTrue(java.util.Arrays.equals(a.nodeBox, b.nodeBox));
        // every slot is in exactly one leaf, leaves are small, and every box holds its subtree's primitives
        int[] seen = new int[n];
        checkSubtree(a, a.root, a.rootBox, 0, box, seen, 0);
        for (int i = 0; i < n; i++) {
            assertEquals(1, seen[i], "slot " + i);
        }
    }

    private static void checkSubtree(BvhBuilder b, int ref, float[] boxes, int off, double[] prim, int[] seen, int depth) {
        assertTrue(depth < 100, "depth");
        if (ref < 0) {
            int leaf = ~ref, first = leaf >>> 4, count = leaf & 15;
            assertTrue(count >= 1 && count <= BvhBuilder.MAX_LEAF, "leaf size " + count);
            for (int i = first; i < first + count; i++) {
                seen[i]++;
                int p = b.order[i];
                for (int a = 0; a < 3; a++) {
                    assertTrue(boxes[off + a] <= prim[6 * p + a] && prim[6 * p + 3 + a] <= boxes[off + 3 + a], "box holds its primitives");
                }
            }
            return;
        }
        for (int c = 0; c < 2; c++) {
            float[] child = java.util.Arrays.copyOfRange(b.nodeBox, 12 * ref + 6 * c, 12 * ref + 6 * c + 6);
            for (int a = 0; a < 3; a++) {
                assertTrue(boxes[off + a] <= child[a] && child[3 + a] <= boxes[off + 3 + a], "child box inside its parent's");
            }
            checkSubtree(b, b.nodeChild[2 * ref + c], child, 0, prim, seen, depth + 1);
        }
    }
}
