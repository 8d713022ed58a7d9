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
import ray.RayPacket;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The packet query ({@link Bvh#closestHits}) must give each ray exactly its single query's hit: the same
 * t, surface, side and record, bit for bit, on random scenes of triangles (with shared edges and
 * vertices, and duplicates, so that several primitives are hit at the same t and the leaf slot decides),
 * spheres (duplicated too), a user's bounded surface in the tree and an unbounded one outside it; for
 * coherent packets (one origin, one sign per axis: traced together), rays aimed exactly at the grid's
 * vertices and edges, and incoherent ones (traced ray by ray).
 */
class BvhPacketTest {

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

    /** A bumpy grid of triangles sharing edges and vertices (its vertices into {@code vertices}), some twice. */
    private static void grid(Random r, int n, List<Surface> out, List<Vector3d> vertices) {
        Vector3d[][] v = new Vector3d[n + 1][n + 1];
        for (int i = 0; i <= n; i++) {
            for (int j = 0; j <= n; j++) {
                v[i][j] = new Vector3d(-8 + 16.0 * i / n, 0.3 * r.nextDouble(), -8 + 16.0 * j / n);
                vertices.add(v[i][j]);
            }
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                out.add(tri(v[i][j], v[i + 1][j], v[i + 1][j + 1]));
                out.add(tri(v[i][j], v[i + 1][j + 1], v[i][j + 1]));
                if (r.nextInt(10) == 0) {
                    out.add(tri(v[i][j], v[i + 1][j], v[i + 1][j + 1]));   // the same triangle again: a tie
                }
            }
        }
    }

    /** {@link #scene}, and with {@code floor} an unbounded surface below it (a floor at y = -1). */
    static List<Surface> scene(Random r, List<Vector3d> vertices, boolean floor) {
        List<Surface> all = scene(r, vertices);
        if (floor) {
            BvhTraversalTest.Floor f = new BvhTraversalTest.Floor();
            f.level = -1;
            all.add(f);
        }
        return all;
    }

    static List<Surface> scene(Random r, List<Vector3d> vertices) {
        List<Surface> l = new ArrayList<>();
        grid(r, 14, l, vertices);
        for (int i = 0; i < 150; i++) {
            Vector3d c = rnd(r, 8);
            l.add(tri(new Vector3d(c.x + r.nextDouble(), c.y + 2, c.z), new Vector3d(c.x, c.y + 2 + r.nextDouble(), c.z),
                    new Vector3d(c.x, c.y + 2, c.z + r.nextDouble())));
        }
        for (int i = 0; i < 80; i++) {
            Sphere s = new Sphere();
            s.center = rnd(r, 8);
            s.center.y = Math.abs(s.center.y) + 1;
            s.radius = 0.1 + 0.6 * r.nextDouble();
            l.add(s);
            if (r.nextInt(8) == 0) {
                Sphere twin = new Sphere();
                twin.center = new Vector3d(s.center);
                twin.radius = s.radius;
                l.add(twin);
            }
        }
        for (int i = 0; i < 20; i++) {
            BvhTraversalTest.Box b = new BvhTraversalTest.Box();
            b.min = rnd(r, 8);
            b.min.y = Math.abs(b.min.y) + 1;
            b.max = new Vector3d(b.min);
            b.max.add(new Vector3d(r.nextDouble(), r.nextDouble(), r.nextDouble()));
            l.add(b);
        }
        java.util.Collections.shuffle(l, r);
        return l;
    }

    @Test
    void packetHitsAreSingleRayHitsBitForBit() {
        packetHitsAreSingleRayHits(Integer.MAX_VALUE);
    }

    /**
     * The same over the tree collapsed four-wide ({@link Wide4#closestHits}, the JVM with the Vector API's
     * module, as the build runs the tests); Wide4Test checks the wide single queries against the binary ones.
     */
    @Test
    void widePacketHitsAreSingleRayHitsBitForBit() {
        packetHitsAreSingleRayHits(0);
    }

    private static void packetHitsAreSingleRayHits(int wideNodes) {
        Random r = new Random(2020);
        int lanesChecked = 0, together = 0, ties = 0;
        for (int sceneNo = 0; sceneNo < 6; sceneNo++) {
            List<Vector3d> vertices = new ArrayList<>();
            List<Surface> all = scene(r, vertices);
            if (sceneNo % 2 == 1) {
                BvhTraversalTest.Floor floor = new BvhTraversalTest.Floor();
                floor.level = -1;
                all.add(floor);
            }
            Bvh bvh = Bvh.build(all, new Scene(), wideNodes);
            assertTrue(bvh.nodeCount() > 100, "a tree deep enough to trace packets through");
            assertEquals(wideNodes == 0, bvh.isWide());
            TraceContext ctx = new TraceContext(10), single = new TraceContext(10);
            RayPacket p = ctx.packet;
            p.reserve(64);
            IntersectionRecord rec = new IntersectionRecord();
            for (int packet = 0; packet < 400; packet++) {
                int n = 2 + r.nextInt(63), kind = r.nextInt(4);
                Vector3d o = rnd(r, 12);
                o.y = 6 + 6 * r.nextDouble();
                Vector3d aim = rnd(r, 7);
                double spread = kind == 0 ? 2 : 0.05 + 0.5 * r.nextDouble();   // kind 0: incoherent
                double tMin = r.nextInt(4) == 0 ? 0.5 * r.nextDouble() : 0;
                p.size = n;
                for (int k = 0; k < n; k++) {
                    Vector3d d;
                    if (kind == 3 || (kind == 2 && r.nextBoolean())) {
                        // exactly at a vertex of the grid, or the midpoint of an edge: ties between neighbours
                        Vector3d v = vertices.get(r.nextInt(vertices.size()));
                        d = new Vector3d(v);
                        if (r.nextBoolean()) {
                            Vector3d w = vertices.get(Math.min(vertices.size() - 1, vertices.indexOf(v) + 1));
                            d.add(w);
                            d.scale(0.5);
                        }
                        d.sub(o);
                    } else {
                        d = new Vector3d(aim);
                        d.add(rnd(r, spread));
                        d.sub(o);
                    }
                    if (r.nextBoolean()) {
                        d.normalize();
                    }
                    Ray ray = p.rays[k];
                    ray.origin.set(o);
                    ray.direction.set(d);
                    ray.tMin = tMin;
                    ray.tMax = r.nextInt(5) == 0 ? 5 + 20 * r.nextDouble() : Double.POSITIVE_INFINITY;
                    ray.depth = 0;
                }
                if (sameSigns(p)) {
                    together++;
                }
                bvh.closestHits(p, ctx);
                for (int k = 0; k < n; k++) {
                    Ray ray = p.rays[k];
                    double tMaxBefore = ray.tMax;
                    boolean hit = bvh.closestHit(ray, rec, single);
                    String what = "ray " + k + " of packet " + packet + " of scene " + sceneNo + ": " + ray;
                    assertEquals(tMaxBefore, ray.tMax, "the ray's span is left as it was");
                    assertEquals(hit, p.hit[k], what);
                    lanesChecked++;
                    if (hit) {
                        IntersectionRecord got = p.records[k];
                        assertEquals(Double.doubleToRawLongBits(rec.t), Double.doubleToRawLongBits(got.t), what);
                        assertSame(rec.surface, got.surface, what);
                        assertEquals(rec.frontFace, got.frontFace, what);
                        assertEquals(rec.location, got.location, what);
                        assertEquals(rec.normal, got.normal, what);
                        assertEquals(Double.doubleToRawLongBits(rec.error), Double.doubleToRawLongBits(got.error), what);
                        if (tieAt(all, ray, rec)) {
                            ties++;
                        }
                    }
                }
            }
        }
        assertTrue(lanesChecked > 50_000, "rays checked: " + lanesChecked);
        assertTrue(together > 1_000, "packets traced together: " + together);
        assertTrue(ties > 100, "rays whose closest t is shared by two primitives: " + ties);
    }

    /** True when the packet's rays share one sign per axis, none zero (then the BVH traces them together). */
    private static boolean sameSigns(RayPacket p) {
        Vector3d d0 = p.rays[0].direction;
        for (int k = 0; k < p.size; k++) {
            Vector3d d = p.rays[k].direction;
            if (d.x * d0.x <= 0 || d.y * d0.y <= 0 || d.z * d0.z <= 0) {
                return false;
            }
        }
        return true;
    }

    /** True when another surface than the one reported is hit at the same t (a tie the slot decided). */
    static boolean tieAt(List<Surface> all, Ray ray, IntersectionRecord best) {
        IntersectionRecord rec = new IntersectionRecord();
        for (Surface s : all) {
            Ray r = new Ray(ray.origin, ray.direction);
            r.tMin = ray.tMin;
            r.tMax = ray.tMax;
            if (s != best.surface && !s.isDegenerate() && s.intersects(r, rec, null) && rec.t == best.t) {
                return true;
            }
        }
        return false;
    }
}
