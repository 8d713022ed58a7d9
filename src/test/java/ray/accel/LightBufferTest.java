package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
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
 * The light buffers ({@link LightBuffer}) must give every shadow ray the tree's any-hit answer: on random
 * scenes of triangles sharing edges and vertices, spheres, a user's bounded surface and an unbounded one,
 * with point lights outside the scene, among its primitives, on a vertex, on a box's plane, at a grid
 * cell's corner and far away; for shadow rays as the renderer spawns them (from a surface point offset
 * off it, from a vertex, from a point next to the light, axis-parallel) and for rays the buffers must not
 * answer (not ending at a light, running past it, starting behind their origin), with and without the
 * occluder cache, through the binary and the wide traversal, at several cell counts.
 */
class LightBufferTest {

    private static Vector3d rnd(Random r, double s) {
        return new Vector3d(s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1));
    }

    @Test
    void shadowRaysGetTheTreesAnswer() {
        Random r = new Random(1986);
        int rays = 0, served = 0, shadowed = 0, lit = 0, near = 0;
        for (int sceneNo = 0; sceneNo < 8; sceneNo++) {
            List<Vector3d> vertices = new ArrayList<>();
            List<Surface> all = BvhPacketTest.scene(r, vertices, sceneNo % 2 == 1);
            Vector3d[] lights = {
                rnd(r, 30),                                             // anywhere, often outside
                rnd(r, 4),                                              // among the primitives
                new Vector3d(vertices.get(r.nextInt(vertices.size()))), // on a vertex
                new Vector3d(vertices.get(r.nextInt(vertices.size())).x, 0.5, 0),  // on a plane through a vertex
                new Vector3d(0, 0, 0),                                  // at the cube's centre
                new Vector3d(2e5, -3e5, 1e5),                           // far away
            };
            double[] xyz = new double[3 * lights.length];
            for (int l = 0; l < lights.length; l++) {
                xyz[3 * l] = lights[l].x;
                xyz[3 * l + 1] = lights[l].y;
                xyz[3 * l + 2] = lights[l].z;
            }
            boolean wideToo = ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent() && sceneNo % 4 == 2;
            Bvh plain = Bvh.build(all, new Scene(), Integer.MAX_VALUE);
            Bvh buffered = Bvh.build(all, new Scene(), wideToo ? 0 : Integer.MAX_VALUE, xyz, Double.POSITIVE_INFINITY);
            assertNull(plain.lightBuffers());
            assertNotNull(buffered.lightBuffers(), "buffers made whatever the tree's size");
            assertEquals(wideToo, buffered.isWide());
            TraceContext cp = new TraceContext(10), cb = new TraceContext(10);
            IntersectionRecord rec = new IntersectionRecord();
            for (int i = 0; i < 24_000; i++) {
                Vector3d light = lights[r.nextInt(lights.length)];
                Ray ray = new Ray();
                int kind = r.nextInt(8);
                boolean mayServe = true;
                switch (kind) {
                    case 0, 1, 2 -> {   // from a surface point, as the renderer spawns it
                        Ray probe = new Ray();
                        probe.origin.set(rnd(r, 12));
                        Vector3d d = new Vector3d(vertices.get(r.nextInt(vertices.size())));
                        d.sub(probe.origin);
                        probe.direction.set(d);
                        probe.tMin = 0;
                        probe.tMax = Double.POSITIVE_INFINITY;
                        if (!plain.closestHit(probe, rec, cp)) {
                            continue;
                        }
                        rec.spawnRayTo(light.x, light.y, light.z, ray);
                    }
                    case 3 -> {   // from a vertex, straight at the light
                        ray.origin.set(vertices.get(r.nextInt(vertices.size())));
                        ray.direction.sub(light, ray.origin);
                        ray.tMin = 0;
                        ray.tMax = 1 - 1e-7;
                    }
                    case 4 -> {   // from next to the light: its near list
                        near++;
                        Vector3d o = rnd(r, Math.pow(10, -1 - r.nextInt(6)));
                        o.add(light);
                        ray.origin.set(o);
                        ray.direction.sub(light, o);
                        ray.tMin = 0;
                        ray.tMax = r.nextBoolean() ? 1 : 1 - 1e-7;
                    }
                    case 5 -> {   // axis-parallel toward the light: zero components, infinite inverses
                        Vector3d o = new Vector3d(light);
                        double z = r.nextBoolean() ? 0.0 : -0.0;
                        o.x += 10 * (2 * r.nextDouble() - 1);
                        if (r.nextBoolean()) {
                            o.y += 10 * (2 * r.nextDouble() - 1);
                        }
                        ray.origin.set(o);
                        ray.direction.sub(light, o);
                        if (ray.direction.y == 0) {
                            ray.direction.y = z;
                        }
                        ray.direction.z = z;
                        ray.tMin = 0;
                        ray.tMax = 1 - 1e-7;
                    }
                    case 6 -> {   // not a shadow ray to a light: the tree answers
                        mayServe = false;
                        ray.origin.set(rnd(r, 12));
                        ray.direction.set(rnd(r, 1));
                        ray.tMin = 0;
                        ray.tMax = r.nextBoolean() ? 20 : Double.POSITIVE_INFINITY;
                    }
                    default -> {   // toward the light but past it, or from behind the origin: the tree answers
                        mayServe = false;
                        ray.origin.set(rnd(r, 12));
                        ray.direction.sub(light, ray.origin);
                        ray.tMin = r.nextBoolean() ? -0.5 : 0;
                        ray.tMax = ray.tMin < 0 ? 1 : 1 + 1e-3 + r.nextDouble();
                    }
                }
                if (ray.direction.lengthSquared() == 0) {
                    continue;
                }
                RayQuery q = new RayQuery(buffered, new Scene(), 8);
                q.startAny(ray);
                boolean serves = LightBuffer.serves(buffered.lightBuffers(), q) != null;
                if (!mayServe) {
                    assertTrue(!serves, "a ray that does not end at a light is the tree's: " + ray);
                }
                if (serves) {
                    served++;
                }
                int slot = r.nextInt(3) - 1;   // -1: no occluder cache
                String what = "ray " + i + " (kind " + kind + ") of scene " + sceneNo + " toward " + light + ": " + ray;
                boolean ap = plain.anyHit(ray, cp, slot), ab = buffered.anyHit(ray, cb, slot);
                assertEquals(ap, ab, "any hit, cache slot " + slot + ", " + what);
                rays++;
                if (ap) {
                    shadowed++;
                } else {
                    lit++;
                }
            }
        }
        assertTrue(rays > 120_000 && served > 60_000, rays + " rays, " + served + " answered by a buffer");
        assertTrue(shadowed > 20_000 && lit > 20_000, shadowed + " shadowed, " + lit + " lit");
        assertTrue(near > 15_000, "rays from next to a light: " + near);
    }

    /** The same on one scene at cell counts from one a face to many more than the default. */
    @Test
    void anyCellCountGivesTheTreesAnswer() {
        for (int cells : new int[] {1, 3, 64, 700}) {
            String old = System.getProperty("ray.lightBuffer.cells");
            System.setProperty("ray.lightBuffer.cells", Integer.toString(cells));
            try {
                Random r = new Random(cells);
                List<Vector3d> vertices = new ArrayList<>();
                List<Surface> all = BvhPacketTest.scene(r, vertices);
                Vector3d light = rnd(r, 6);
                Bvh plain = Bvh.build(all, new Scene(), Integer.MAX_VALUE);
                Bvh buffered = Bvh.build(all, new Scene(), Integer.MAX_VALUE, new double[] {light.x, light.y, light.z},
                        Double.POSITIVE_INFINITY);
                TraceContext cp = new TraceContext(10), cb = new TraceContext(10);
                int shadowed = 0;
                for (int i = 0; i < 20_000; i++) {
                    Ray ray = new Ray();
                    ray.origin.set(i % 2 == 0 ? rnd(r, 12) : vertices.get(r.nextInt(vertices.size())));
                    ray.direction.sub(light, ray.origin);
                    ray.tMin = 0;
                    ray.tMax = 1 - 1e-7;
                    boolean ap = plain.anyHit(ray, cp), ab = buffered.anyHit(ray, cb);
                    assertEquals(ap, ab, cells + " cells a side, ray " + i + ": " + ray);
                    shadowed += ap ? 1 : 0;
                }
                assertTrue(shadowed > 500 && shadowed < 19_500, "shadowed " + shadowed);
            } finally {
                if (old == null) {
                    System.clearProperty("ray.lightBuffer.cells");
                } else {
                    System.setProperty("ray.lightBuffer.cells", old);
                }
            }
        }
    }

    /** Buffers only where they pay: a tree of 200 inner nodes or more, 64 shadow rays a leaf and light or more. */
    @Test
    void buffersOnlyWhereTheyPay() {
        Random r = new Random(7);
        List<Surface> all = new ArrayList<>();
        while (Bvh.build(all, new Scene()).nodeCount() < Bvh.LIGHT_BUFFER_NODES) {   // more random scenes, in the same space
            List<Surface> more = BvhPacketTest.scene(r, new ArrayList<>());
            for (Surface s : more) {
                all.add(s);
            }
        }
        double[] light = {1, 20, 3};
        Bvh b = Bvh.build(all, new Scene(), light, 1e9);
        assertTrue(b.nodeCount() >= Bvh.LIGHT_BUFFER_NODES);
        assertNotNull(b.lightBuffers());
        double leaves = b.nodeCount() + 1;
        assertNull(Bvh.build(all, new Scene(), light, Bvh.LIGHT_BUFFER_RAYS_PER_LEAF * leaves - 1).lightBuffers(),
                "too few rays for the tree");
        assertNotNull(Bvh.build(all, new Scene(), light, Bvh.LIGHT_BUFFER_RAYS_PER_LEAF * leaves).lightBuffers());
        assertNull(Bvh.build(all.subList(0, 20), new Scene(), light, 1e9).lightBuffers(), "a small tree");
        assertNull(Bvh.build(all.subList(0, 20), new Scene(), light, Double.POSITIVE_INFINITY).lightBuffers(),
                "a small tree, however many rays a render says it casts");
        assertNull(Bvh.build(all, new Scene(), new double[0], 1e9).lightBuffers(), "no point light");
        assertNull(Bvh.build(all, new Scene(), new double[] {1e200, 0, 0}, 1e9).lightBuffers(),
                "a light so far that a squared distance would not be finite");
        assertNull(Bvh.build(all, new Scene(), new double[] {Double.NaN, 0, 0}, 1e9).lightBuffers());
        assertNull(Bvh.build(all, new Scene()).lightBuffers());
        assertTrue(b.memoryBytes() > Bvh.build(all, new Scene()).memoryBytes(), "the buffers are counted");
        assertEquals(LightBuffer.MAX_LIGHTS, Bvh.build(all, new Scene(), new double[3 * 40], 1e9).lightBuffers().length,
                "the first sixteen of forty lights");
        assertEquals(16, LightBuffer.lightsFor(40, 65_536));
        assertEquals(2, LightBuffer.lightsFor(2, 500_000));
        assertEquals(1, LightBuffer.lightsFor(40, 1 << 20));
        assertEquals(0, LightBuffer.lightsFor(40, (1 << 20) + 1), "none for more than 2^20 leaves");
    }
}
