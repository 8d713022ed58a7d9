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
import ray.surface.Surface;

/**
 * The wide traversal ({@link Wide4}: four boxes a node, tested in SIMD) must answer every query exactly as
 * the binary tree it is collapsed from: the same hit or miss, t, surface, side and record bit for bit, and
 * the same any-hit answer with and without the occluder cache, on random scenes of triangles sharing edges
 * and vertices (and duplicated: ties the leaf slot decides), spheres, a user's bounded surface and an
 * unbounded one; for rays from anywhere and from the scene's own vertices, aimed at vertices and edge
 * midpoints, axis-parallel (zero and negative-zero direction components: infinite inverses, NaN slab
 * distances), with tMin above zero and finite tMax. Runs where the test JVM has {@code jdk.incubator.vector}
 * (the build adds it).
 */
class Wide4Test {

    private static Vector3d rnd(Random r, double s) {
        return new Vector3d(s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1));
    }

    @Test
    void wideAnswersAreTheBinaryTreesBitForBit() {
        assertTrue(ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent(),
                "the test JVM runs with --add-modules=jdk.incubator.vector (build.gradle)");
        Random r = new Random(465);
        int rays = 0, hits = 0, ties = 0, axis = 0, shadowed = 0;
        for (int sceneNo = 0; sceneNo < 6; sceneNo++) {
            List<Vector3d> vertices = new ArrayList<>();
            List<Surface> all = BvhPacketTest.scene(r, vertices, sceneNo % 2 == 1);
            Bvh binary = Bvh.build(all, new Scene(), Integer.MAX_VALUE), wide = Bvh.build(all, new Scene(), 0);
            assertTrue(wide.isWide() && !binary.isWide());
            assertTrue(wide.nodeCount() > 100, "a deep tree");
            assertTrue(wide.memoryBytes() <= 1.05 * binary.memoryBytes(), "about a third as many nodes, twice the size each: "
                    + wide.memoryBytes() + " bytes against " + binary.memoryBytes());
            TraceContext cb = new TraceContext(10), cw = new TraceContext(10);
            IntersectionRecord rb = new IntersectionRecord(), rw = new IntersectionRecord();
            for (int i = 0; i < 30_000; i++) {
                Ray ray = new Ray();
                int kind = r.nextInt(5);
                Vector3d o = kind == 4 ? new Vector3d(vertices.get(r.nextInt(vertices.size()))) : rnd(r, 12);
                Vector3d d;
                if (kind >= 2) {   // at a vertex or an edge's midpoint: ties between neighbours
                    Vector3d v = vertices.get(r.nextInt(vertices.size()));
                    d = new Vector3d(v);
                    if (r.nextBoolean()) {
                        d.add(vertices.get(Math.min(vertices.size() - 1, vertices.indexOf(v) + 1)));
                        d.scale(0.5);
                    }
                    d.sub(o);
                } else {
                    d = rnd(r, 1);
                }
                if (r.nextInt(6) == 0) {   // axis-parallel: one or two components +0 or -0
                    axis++;
                    double z = r.nextBoolean() ? 0.0 : -0.0;
                    switch (r.nextInt(3)) {
                        case 0 -> d.x = z;
                        case 1 -> d.y = z;
                        default -> {
                            d.z = z;
                            d.x = -z;
                        }
                    }
                }
                if (d.lengthSquared() == 0) {
                    continue;
                }
                if (r.nextBoolean()) {
                    d.normalize();
                }
                ray.origin.set(o);
                ray.direction.set(d);
                ray.tMin = kind == 4 ? 1e-9 : r.nextInt(4) == 0 ? 0.5 * r.nextDouble() : 0;
                ray.tMax = r.nextInt(4) == 0 ? 3 + 20 * r.nextDouble() : Double.POSITIVE_INFINITY;
                String what = "ray " + i + " of scene " + sceneNo + ": " + ray;
                boolean hb = binary.closestHit(ray, rb, cb), hw = wide.closestHit(ray, rw, cw);
                assertEquals(hb, hw, what);
                rays++;
                if (hb) {
                    hits++;
                    assertEquals(Double.doubleToRawLongBits(rb.t), Double.doubleToRawLongBits(rw.t), what);
                    assertSame(rb.surface, rw.surface, what);
                    assertEquals(rb.frontFace, rw.frontFace, what);
                    assertSameBits(rb.location, rw.location, what);
                    assertSameBits(rb.normal, rw.normal, what);
                    assertEquals(Double.doubleToRawLongBits(rb.error), Double.doubleToRawLongBits(rw.error), what);
                    if (BvhPacketTest.tieAt(all, ray, rb)) {
                        ties++;
                    }
                }
                int slot = r.nextInt(3) - 1;   // -1: no occluder cache
                boolean ab = binary.anyHit(ray, cb, slot), aw = wide.anyHit(ray, cw, slot);
                assertEquals(ab, aw, "any hit, cache slot " + slot + ", " + what);
                if (ab) {
                    shadowed++;
                }
            }
        }
        assertTrue(rays > 150_000 && hits > 30_000 && shadowed > 30_000, rays + " rays, " + hits + " hits, " + shadowed + " any");
        assertTrue(ties > 100, "rays whose closest t is shared by two primitives: " + ties);
        assertTrue(axis > 20_000, "axis-parallel rays: " + axis);
    }

    private static void assertSameBits(Vector3d a, Vector3d b, String what) {
        assertEquals(Double.doubleToRawLongBits(a.x), Double.doubleToRawLongBits(b.x), what);
        assertEquals(Double.doubleToRawLongBits(a.y), Double.doubleToRawLongBits(b.y), what);
        assertEquals(Double.doubleToRawLongBits(a.z), Double.doubleToRawLongBits(b.z), what);
    }

    /** A tree below the threshold, or without the property, stays binary; so does a one-leaf tree. */
    @Test
    void smallTreesStayBinary() {
        List<Surface> all = BvhPacketTest.scene(new Random(1), new ArrayList<>());
        Bvh b = Bvh.build(all, new Scene(), Integer.MAX_VALUE);
        assertTrue(!b.isWide());
        assertTrue(!Bvh.build(all, new Scene(), b.nodeCount() + 1).isWide());
        assertTrue(Bvh.build(all, new Scene(), b.nodeCount()).isWide());
        assertTrue(!Bvh.build(all.subList(0, 1), new Scene(), 0).isWide(), "a root that is a leaf");
        assertTrue(!Bvh.WIDE || Boolean.getBoolean("ray.bvh.wide"), "off unless asked for");
    }
}
