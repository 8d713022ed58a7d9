package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * What the BVH's class comment promises about its layout, seen from outside through primitive sets of
 * the test's own: a leaf hands each set one run of its slots (the slots are grouped by set), equal-t
 * hits go to the earlier slot whatever the order they are offered in, and {@link Bvh#memoryBytes()} is
 * 56 bytes per inner node, 8 per slot and what the sets pack.
 */
class BvhLayoutTest {

    /** Every call to a set's closestHit/anyHit: set name and run length. */
    static final List<String> calls = new ArrayList<>();

    /** A set of probes: records its calls, and offers each probe's fixed t, last slot first. */
    static final class ProbeSet extends PrimitiveSet {
        final String name;

        ProbeSet(String name, List<Surface> s) {
            super(s);
            this.name = name;
        }

        @Override
        public void closestHit(int from, int to, int slot, RayQuery q) {
            calls.add(name + (to - from));
            for (int i = to - 1; i >= from; i--) {   // the reverse of slot order
                double t = ((Probe) surface(i)).t;
                if (t >= q.tMin && t <= q.tMax) {
                    q.offer(t, this, i, slot + (i - from));
                }
            }
        }

        @Override
        public boolean anyHit(int from, int to, RayQuery q) {
            calls.add(name + (to - from));
            return false;
        }

        @Override
        public void fill(int i, RayQuery q, IntersectionRecord rec) {
            rec.t = q.tMax;
            rec.surface = surface(i);
        }

        @Override
        public long memoryBytes() {
            return 1000L * size();
        }
    }

    static final PrimitiveSet.Type A = s -> new ProbeSet("A", s), B = s -> new ProbeSet("B", s);

    /** A box around the origin that the BVH holds in the set of its type; "hit" at t (never, if NaN). */
    static final class Probe extends Surface {
        final PrimitiveSet.Type type;
        final double t;

        Probe(PrimitiveSet.Type type, double t) {
            this.type = type;
            this.t = t;
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            throw new AssertionError("a probe is tested through its set");
        }

        @Override
        public Aabb bounds() {
            return new Aabb(-1, -1, -1, 1, 1, 1);
        }

        @Override
        public PrimitiveSet.Type primitiveType() {
            return type;
        }
    }

    private static Scene scene() {
        Scene s = new Scene();
        s.camera = new Camera();
        return s;
    }

    private static Ray down() {
        return new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1));
    }

    /** Eight probes of two sets, alternating, share one leaf (coincident boxes): each set gets one run of 4. */
    @Test
    void aLeafHandsEachSetOneRunOfItsSlots() {
        List<Surface> list = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            list.add(new Probe(i % 2 == 0 ? A : B, Double.NaN));
        }
        Bvh bvh = Bvh.build(list, scene());
        assertEquals(0, bvh.nodeCount(), "eight coincident boxes: one leaf");
        calls.clear();
        assertFalse(bvh.closestHit(down(), new IntersectionRecord(), new TraceContext(2)));
        assertEquals(List.of("A4", "B4"), calls, "closest hit: one run per set, in order of first appearance");
        calls.clear();
        assertFalse(bvh.anyHit(down(), new TraceContext(2)));
        assertEquals(List.of("A4", "B4"), calls, "any hit");
        assertEquals(8 * 8 + 1000 * 8, bvh.memoryBytes(), "a leaf of 8 slots and the sets' bytes");
    }

    /** Three probes hit at the same t, offered last slot first: the first slot (the first in the list) wins. */
    @Test
    void equalHitsGoToTheEarlierSlot() {
        Probe p0 = new Probe(A, 3), p1 = new Probe(A, 3), p2 = new Probe(A, 3), far = new Probe(A, 4);
        for (List<Surface> list : List.<List<Surface>>of(List.of(p0, p1, p2, far), List.of(far, p0, p1, p2))) {
            Bvh bvh = Bvh.build(new ArrayList<>(list), scene());
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(bvh.closestHit(down(), rec, new TraceContext(2)));
            assertEquals(3, rec.t, 0);
            assertSame(p0, rec.surface, "of three hits at t = 3, the one in the earliest slot");
        }
        // a nearer hit in a later slot still wins
        Probe near = new Probe(A, 2.5);
        Bvh bvh = Bvh.build(new ArrayList<>(List.of(p0, p1, near)), scene());
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(bvh.closestHit(down(), rec, new TraceContext(2)));
        assertSame(near, rec.surface);
    }

    /**
     * n coincident spheres and triangles are halved by count into leaves of at most 8: 1000 make 128
     * leaves and 127 inner nodes; memory is 56 bytes per inner node, 8 per slot, 4 doubles and a reference
     * per sphere, 9 doubles and a reference per triangle.
     */
    @Test
    void nodeCountAndMemoryFollowTheLayout() {
        for (int n : new int[] {1, 8, 9, 20, 1000}) {
            List<Surface> list = new ArrayList<>();
            int spheres = 0, triangles = 0;
            for (int i = 0; i < n; i++) {
                if (i % 3 == 0) {
                    Triangle t = new Triangle();
                    t.v0 = new Vector3d(1, 0, 0);
                    t.v1 = new Vector3d(-1, 1, 0);
                    t.v2 = new Vector3d(-1, -1, 0);   // its box is centred on the origin, like the spheres'
                    list.add(t);
                    triangles++;
                } else {
                    Sphere s = new Sphere();
                    s.radius = 0.5 + i % 7;
                    list.add(s);
                    spheres++;
                }
            }
            for (Surface s : list) {
                s.init();
            }
            Bvh bvh = Bvh.build(list, scene());
            int leaves = 1;
            while ((n + leaves - 1) / leaves > BvhBuilder.MAX_LEAF) {
                leaves *= 2;
            }
            assertEquals(leaves - 1, bvh.nodeCount(), n + " coincident primitives");
            assertEquals(n, bvh.primitiveCount());
            assertEquals(56L * (leaves - 1) + 8L * n + 36L * spheres + 76L * triangles, bvh.memoryBytes(), n + " primitives");
        }
    }
}
