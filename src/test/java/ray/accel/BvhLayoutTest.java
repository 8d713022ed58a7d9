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

    /** Ray set-ups made, and set-ups found overwritten by another set's, since the last clear. */
    static int setUps, foreignSetUps;

    /**
     * A set of probes: records its calls, and offers each probe's fixed t, last slot first. Like a
     * built-in set it makes a per-ray set-up on its first use in a query: its own marker in its own part
     * of the scratch, checked on every later use.
     */
    static final class ProbeSet extends PrimitiveSet {
        final String name;
        final double marker;

        ProbeSet(String name, List<Surface> s) {
            super(s);
            this.name = name;
            this.marker = name.hashCode() + 0.5;
        }

        private void setUp(RayQuery q) {
            int at = id() * SCRATCH;
            if (firstUse(q)) {
                setUps++;
                q.scratch[at] = marker;
            } else if (q.scratch[at] != marker) {
                foreignSetUps++;
            }
        }

        @Override
        public void closestHit(int from, int to, int slot, RayQuery q) {
            setUp(q);
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
            setUp(q);
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

    /** A box (the cube of side 2 around the origin, or a small one at z) held in its type's set; "hit" at t (never, if NaN). */
    static final class Probe extends Surface {
        final PrimitiveSet.Type type;
        final double t;
        final Aabb box;

        Probe(PrimitiveSet.Type type, double t) {
            this(type, t, new Aabb(-1, -1, -1, 1, 1, 1));
        }

        Probe(PrimitiveSet.Type type, double t, Aabb box) {
            this.type = type;
            this.t = t;
            this.box = box;
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            throw new AssertionError("a probe is tested through its set");
        }

        @Override
        public Aabb bounds() {
            return new Aabb(box.minX, box.minY, box.minZ, box.maxX, box.maxY, box.maxZ);
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
        // offered in slot order (set A's run, then set B's): an equal hit in a later slot does not take over
        Probe b3 = new Probe(B, 3);
        Bvh mixed = Bvh.build(new ArrayList<>(List.of(p0, b3)), scene());
        IntersectionRecord first = new IntersectionRecord();
        assertTrue(mixed.closestHit(down(), first, new TraceContext(2)));
        assertSame(p0, first.surface, "the earlier slot keeps an equal-t hit offered after it");
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
            long slots = spheres > 0 && triangles > 0 ? 8L * n : 0;   // per-slot run and index: only with two sets or more
            assertEquals(56L * (leaves - 1) + slots + 36L * spheres + 76L * triangles, bvh.memoryBytes(), n + " primitives");
        }
    }

    /**
     * Each set makes its ray set-up once per query, in its own part of the scratch, however many leaves
     * hand it slots: sixteen probes of two sets fill two leaves, so each set is called twice per query.
     */
    @Test
    void eachSetMakesItsRaySetUpOncePerQueryInItsOwnScratch() {
        List<Surface> list = new ArrayList<>();
        for (int i = 0; i < 16; i++) {
            list.add(new Probe(i % 2 == 0 ? A : B, Double.NaN));
        }
        Bvh bvh = Bvh.build(list, scene());
        assertEquals(1, bvh.nodeCount(), "sixteen coincident boxes: two leaves");
        TraceContext ctx = new TraceContext(2);
        for (int query = 0; query < 3; query++) {
            calls.clear();
            setUps = foreignSetUps = 0;
            bvh.closestHit(down(), new IntersectionRecord(), ctx);
            assertEquals(List.of("A4", "B4", "A4", "B4"), calls, "two leaves, each with a run of each set");
            assertEquals(2, setUps, "one set-up per set and query (query " + query + ")");
            assertEquals(0, foreignSetUps, "no set reads another set's set-up");
            setUps = 0;
            bvh.anyHit(down(), ctx);
            assertEquals(2, setUps, "any hit: one set-up per set and query");
            assertEquals(0, foreignSetUps);
        }
    }

    /**
     * The closest-hit query visits the nearer child first and drops the farther one once a hit nearer
     * than its box is found: eight probes of set A near the ray's origin (hit at t = 3) and eight of set B
     * far behind them (their box starts at t = 14): B is never tested. The any-hit query stops at A's hit
     * only if A reports one, so it is left out here.
     */
    @Test
    void theNearerChildIsVisitedFirstAndAFartherOneDropped() {
        List<Surface> list = new ArrayList<>();
        for (int i = 0; i < 8; i++) {
            double d = 0.01 * i;
            list.add(new Probe(B, 15, new Aabb(-0.1 + d, -0.1, -11, 0.1 + d, 0.1, -9)));
            list.add(new Probe(A, 3, new Aabb(-0.1 + d, -0.1, 1, 0.1 + d, 0.1, 3)));
        }
        Bvh bvh = Bvh.build(list, scene());
        for (Vector3d dir : new Vector3d[] {new Vector3d(0, 0, -1), new Vector3d(0.001, 0, -1)}) {
            calls.clear();
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(bvh.closestHit(new Ray(new Vector3d(0, 0, 5), dir), rec, new TraceContext(2)));
            assertEquals(3, rec.t, 0);
            assertEquals(List.of("A8"), calls, "only the near leaf is tested, along " + dir);
        }
        // from the other side the far cluster is the near one
        calls.clear();
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(bvh.closestHit(new Ray(new Vector3d(0, 0, -20), new Vector3d(0, 0, 1)), rec, new TraceContext(2)));
        assertEquals(List.of("B8"), calls, "from below, only the B leaf");
    }

    /** A surface without bounds, hit by a ray that misses the box of a one-leaf tree, is still the hit. */
    @Test
    void anUnboundedHitCountsWhenTheRayMissesTheTree() {
        Surface floor = new Surface() {
            @Override
            public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
                double t = (ray.origin.y + 2) / -ray.direction.y;   // the plane y = -2
                if (!(t >= ray.tMin && t <= ray.tMax)) {
                    return false;
                }
                record.t = t;
                record.location = ray.evaluate(t);
                record.normal.set(0, 1, 0);
                return true;
            }
        };
        Probe box = new Probe(A, 1);
        Bvh bvh = Bvh.build(new ArrayList<>(List.of(box, floor)), scene());
        assertEquals(0, bvh.nodeCount(), "one bounded primitive: the root is a leaf");
        Ray missingTheBox = new Ray(new Vector3d(10, 5, 0), new Vector3d(0, -1, 0));
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(bvh.closestHit(missingTheBox, rec, new TraceContext(2)), "the floor is hit");
        assertEquals(7, rec.t, 1e-12);
        assertSame(floor, rec.surface);
        assertTrue(bvh.anyHit(new Ray(new Vector3d(10, 5, 0), new Vector3d(0, -1, 0)), new TraceContext(2)));
    }
}
