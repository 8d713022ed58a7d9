package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayPacket;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * A small scene's camera packets traced in vector lanes ({@link LaneKernel}: every primitive against four
 * rays at a time, no tree) must give each ray exactly its single query's hit through the tree: the same
 * hit or miss, t, surface, side and record, bit for bit. Seeded random scenes of up to 16 spheres and
 * triangles: triangles sharing edges and vertices, some twice and some seen from behind, spheres twice
 * and nested (ties the leaf slot decides, as {@link RayQuery#offer}'s rule), tiny and huge ones; packets
 * from one eye and from anywhere (inside spheres, on vertices), aimed at vertices, edge midpoints and
 * sphere silhouettes, with directions whose dominant axis changes inside a packet (the triangle lanes'
 * scalar fallback), axis-parallel and zero components, tMin 0 and above, finite tMax, and sizes that do
 * not fill the last vector. Runs where the test JVM has {@code jdk.incubator.vector} (the build adds it).
 */
class LanesTest {

    private static Vector3d rnd(Random r, double s) {
        return new Vector3d(s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1));
    }

    private static Triangle tri(Vector3d a, Vector3d b, Vector3d c) {
        Triangle t = new Triangle();
        t.v0 = new Vector3d(a);
        t.v1 = new Vector3d(b);
        t.v2 = new Vector3d(c);
        return t;
    }

    private static Sphere sphere(Vector3d c, double radius) {
        Sphere s = new Sphere();
        s.center = new Vector3d(c);
        s.radius = radius;
        return s;
    }

    /** Up to 16 primitives; their corners, centres and silhouette points into {@code targets}. */
    private static List<Surface> scene(Random r, List<Vector3d> targets) {
        List<Surface> l = new ArrayList<>();
        int quads = r.nextInt(4);
        for (int q = 0; q < quads; q++) {   // two triangles sharing a diagonal, as classic's ground
            double s = r.nextInt(3) == 0 ? 1e-3 : 1 + 10 * r.nextDouble();
            Vector3d c = rnd(r, 5), e = rnd(r, s), f = rnd(r, s);
            Vector3d a = new Vector3d(c), b = new Vector3d(c), d = new Vector3d(c), g = new Vector3d(c);
            a.sub(e);
            b.add(f);
            d.add(e);
            g.sub(f);
            l.add(tri(a, b, d));
            l.add(tri(a, d, g));
            if (r.nextInt(3) == 0) {
                l.add(tri(a, b, d));   // the same triangle again: a tie
            }
            if (r.nextInt(3) == 0) {
                l.add(tri(a, g, d));   // the other side
            }
            targets.add(a);
            targets.add(b);
            targets.add(d);
            targets.add(g);
            Vector3d mid = new Vector3d(a);
            mid.add(d);
            mid.scale(0.5);
            targets.add(mid);
        }
        while (l.size() < 16 && r.nextInt(6) != 0) {
            double radius = r.nextInt(5) == 0 ? 1e-4 : r.nextInt(8) == 0 ? 1e4 : 0.1 + 3 * r.nextDouble();
            Vector3d c = rnd(r, 6);
            l.add(sphere(c, radius));
            if (r.nextInt(5) == 0 && l.size() < 16) {
                l.add(sphere(c, r.nextBoolean() ? radius : 0.5 * radius));   // twin or nested
            }
            targets.add(c);
            Vector3d edge = new Vector3d(c);
            edge.x += radius;
            targets.add(edge);
        }
        if (l.isEmpty()) {
            l.add(sphere(new Vector3d(), 1));
            targets.add(new Vector3d(1, 0, 0));
        }
        java.util.Collections.shuffle(l, r);
        return l.subList(0, Math.min(16, l.size()));
    }

    @Test
    void laneHitsAreTheTreesSingleHitsBitForBit() {
        assertTrue(ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent(),
                "the test JVM runs with --add-modules=jdk.incubator.vector (build.gradle)");
        Random r = new Random(4651);
        long checked = 0, hits = 0, ties = 0, mixed = 0, spheres = 0, triangles = 0;
        for (int sceneNo = 0; sceneNo < 300; sceneNo++) {
            List<Vector3d> targets = new ArrayList<>();
            List<Surface> all = scene(r, targets);
            Bvh lanes = Bvh.build(all, new Scene(), Integer.MAX_VALUE, 16), tree = Bvh.build(all, new Scene(), Integer.MAX_VALUE, 0);
            assertTrue(lanes.isLanes(), "a scene of " + all.size() + " spheres and triangles");
            assertFalse(tree.isLanes());
            assertTrue(lanes.packetsPay());
            TraceContext ctx = new TraceContext(10), single = new TraceContext(10);
            RayPacket p = ctx.packet;
            p.reserve(40);
            IntersectionRecord rec = new IntersectionRecord();
            for (int packet = 0; packet < 60; packet++) {
                int n = 1 + r.nextInt(40), kind = r.nextInt(6);
                Vector3d eye = kind == 5 ? new Vector3d(targets.get(r.nextInt(targets.size()))) : rnd(r, 15);
                Vector3d aim = targets.get(r.nextInt(targets.size()));
                double spread = kind == 0 ? 5 : kind == 1 ? 1e-6 : 0.3 * r.nextDouble();
                double tMin = kind == 5 ? 1e-9 : r.nextInt(4) == 0 ? 0.5 * r.nextDouble() : 0;
                p.size = n;
                for (int k = 0; k < n; k++) {
                    Vector3d o = kind == 4 ? rnd(r, 15) : eye;   // kind 4: rays from anywhere
                    Vector3d d = new Vector3d(r.nextInt(3) == 0 ? targets.get(r.nextInt(targets.size())) : aim);
                    if (r.nextInt(3) != 0) {
                        d.add(rnd(r, spread));
                    }
                    d.sub(o);
                    if (r.nextInt(12) == 0) {   // axis-parallel: a component +0 or -0
                        double z = r.nextBoolean() ? 0.0 : -0.0;
                        switch (r.nextInt(3)) {
                            case 0 -> d.x = z;
                            case 1 -> d.y = z;
                            default -> d.z = z;
                        }
                    }
                    if (r.nextBoolean()) {
                        d.normalize();
                    }
                    Ray ray = p.rays[k];
                    ray.origin.set(o);
                    ray.direction.set(d);
                    ray.tMin = tMin;
                    ray.tMax = r.nextInt(5) == 0 ? 20 * r.nextDouble() : Double.POSITIVE_INFINITY;
                    ray.depth = 0;
                }
                if (!sameAxes(p)) {
                    mixed++;
                }
                lanes.closestHits(p, ctx);
                for (int k = 0; k < n; k++) {
                    Ray ray = p.rays[k];
                    boolean hit = tree.closestHit(ray, rec, single);
                    String what = "ray " + k + " of packet " + packet + " of scene " + sceneNo + ": " + ray;
                    assertEquals(hit, p.hit[k], what);
                    checked++;
                    if (hit) {
                        hits++;
                        IntersectionRecord got = p.records[k];
                        assertEquals(Double.doubleToRawLongBits(rec.t), Double.doubleToRawLongBits(got.t), what);
                        assertSame(rec.surface, got.surface, what);
                        assertEquals(rec.frontFace, got.frontFace, what);
                        assertSameBits(rec.location, got.location, what);
                        assertSameBits(rec.normal, got.normal, what);
                        assertEquals(Double.doubleToRawLongBits(rec.error), Double.doubleToRawLongBits(got.error), what);
                        if (rec.surface instanceof Sphere) {
                            spheres++;
                        } else {
                            triangles++;
                        }
                        if (BvhPacketTest.tieAt(all, ray, rec)) {
                            ties++;
                        }
                    }
                }
            }
        }
        assertTrue(checked > 200_000 && hits > 50_000, checked + " rays, " + hits + " hits");
        assertTrue(spheres > 10_000 && triangles > 10_000, spheres + " sphere hits, " + triangles + " triangle hits");
        assertTrue(ties > 300, "rays whose closest t is shared by two primitives: " + ties);
        assertTrue(mixed > 1_000, "packets whose rays do not share their dominant axis: " + mixed);
    }

    /** The classic scene's five primitives and camera rays from its eye, 16 to a packet as a 4x4-sample pixel's. */
    @Test
    void classicCameraPacketsAreTheTreesHits() {
        List<Surface> all = new ArrayList<>();
        all.add(tri(new Vector3d(-12, 0, 12), new Vector3d(12, 0, 12), new Vector3d(12, 0, -12)));
        all.add(tri(new Vector3d(-12, 0, 12), new Vector3d(12, 0, -12), new Vector3d(-12, 0, -12)));
        all.add(sphere(new Vector3d(-2.3, 1, 0.3), 1));
        all.add(sphere(new Vector3d(0, 1, -1.2), 1));
        all.add(sphere(new Vector3d(2.3, 1, 0.3), 1));
        Bvh lanes = Bvh.build(all, new Scene(), Integer.MAX_VALUE, 16), tree = Bvh.build(all, new Scene(), Integer.MAX_VALUE, 0);
        assertTrue(lanes.isLanes());
        TraceContext ctx = new TraceContext(10), single = new TraceContext(10);
        RayPacket p = ctx.packet;
        p.reserve(16);
        IntersectionRecord rec = new IntersectionRecord();
        Random r = new Random(3);
        Vector3d eye = new Vector3d(0, 2.6, 9);
        for (int packet = 0; packet < 20_000; packet++) {
            double u = 0.5 * (2 * r.nextDouble() - 1), v = 0.4 * (2 * r.nextDouble() - 1);
            p.size = 16;
            for (int k = 0; k < 16; k++) {
                Vector3d d = new Vector3d(u + (k % 4) * 1e-4, -0.2 + v + (k / 4) * 1e-4, -1);
                d.normalize();
                Ray ray = p.rays[k];
                ray.origin.set(eye);
                ray.direction.set(d);
                ray.tMin = 0;
                ray.tMax = Double.POSITIVE_INFINITY;
                ray.depth = 0;
            }
            lanes.closestHits(p, ctx);
            for (int k = 0; k < 16; k++) {
                Ray ray = p.rays[k];
                boolean hit = tree.closestHit(ray, rec, single);
                String what = "ray " + k + " of packet " + packet + ": " + ray;
                assertEquals(hit, p.hit[k], what);
                if (hit) {
                    IntersectionRecord got = p.records[k];
                    assertEquals(Double.doubleToRawLongBits(rec.t), Double.doubleToRawLongBits(got.t), what);
                    assertSame(rec.surface, got.surface, what);
                    assertSameBits(rec.location, got.location, what);
                    assertSameBits(rec.normal, got.normal, what);
                }
            }
        }
    }

    private static void assertSameBits(Vector3d a, Vector3d b, String what) {
        assertEquals(Double.doubleToRawLongBits(a.x), Double.doubleToRawLongBits(b.x), what);
        assertEquals(Double.doubleToRawLongBits(a.y), Double.doubleToRawLongBits(b.y), what);
        assertEquals(Double.doubleToRawLongBits(a.z), Double.doubleToRawLongBits(b.z), what);
    }

    /** True when the packet's rays share their dominant axis and its sign (the triangle lanes' set-up). */
    private static boolean sameAxes(RayPacket p) {
        int a0 = axes(p.rays[0].direction);
        for (int k = 1; k < p.size; k++) {
            if (axes(p.rays[k].direction) != a0) {
                return false;
            }
        }
        return true;
    }

    private static int axes(Vector3d d) {
        double ax = Math.abs(d.x), ay = Math.abs(d.y), az = Math.abs(d.z);
        int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        double dkz = kz == 0 ? d.x : kz == 1 ? d.y : d.z;
        return 2 * kz + (dkz < 0 ? 1 : 0);
    }

    /** Lanes only for a small scene of sets that have them, none unbounded, and only when asked for. */
    @Test
    void onlySmallScenesOfBuiltInsGoInLanes() {
        List<Surface> all = scene(new Random(7), new ArrayList<>());
        assertTrue(Bvh.build(all, new Scene(), Integer.MAX_VALUE, all.size()).isLanes());
        assertFalse(Bvh.build(all, new Scene(), Integer.MAX_VALUE, all.size() - 1).isLanes(), "more than asked for");
        assertFalse(Bvh.build(all, new Scene(), Integer.MAX_VALUE, 0).isLanes(), "not asked for");
        List<Surface> user = new ArrayList<>(all);
        BvhTraversalTest.Box b = new BvhTraversalTest.Box();
        b.min = new Vector3d(0, 0, 0);
        b.max = new Vector3d(1, 1, 1);
        user.add(b);
        assertFalse(Bvh.build(user, new Scene(), Integer.MAX_VALUE, 64).isLanes(), "a user's surface: the tree");
        List<Surface> floor = new ArrayList<>(all);
        floor.add(new BvhTraversalTest.Floor());
        assertFalse(Bvh.build(floor, new Scene(), Integer.MAX_VALUE, 64).isLanes(), "an unbounded surface: the tree");
        assertTrue(!Bvh.WIDE || Boolean.getBoolean("ray.bvh.wide"), "off unless asked for");
    }
}
