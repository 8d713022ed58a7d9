package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static ray.robust.RobustSupport.add;
import static ray.robust.RobustSupport.forEachSeed;
import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.maxAbs;
import static ray.robust.RobustSupport.sub;
import static ray.robust.RobustSupport.unit;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.surface.Triangle;

/**
 * Watertightness of the ray/triangle test (Woop, Benthin and Wald 2013): a ray through a shared edge
 * or vertex of a closed mesh hits one of the triangles there, at every scale and position; and the
 * hit point lies on the triangle's plane to within a bound relative to its magnitude.
 */
class TriangleWatertightTest {

    private static final int CASES = 24;

    /** A mesh kind per case: sphere-like (irrational vertices), box grid (coplanar, axis-aligned), ellipsoid. */
    private static ClosedMesh randomMesh(Random r) {
        double s = logUniform(r, 1e-6, 1e6);
        Vector3d t = unit(r);
        t.scale(s * logUniform(r, 1e-3, 1e6));          // up to a million mesh sizes from the origin
        switch (r.nextInt(3)) {
            case 0:
                return ClosedMesh.icosphere(2).transformed(s, new Vector3d(1, 1, 1), t);
            case 1:
                return ClosedMesh.cubeGrid(5).transformed(s, new Vector3d(1, 1, 1), t);
            default:
                Vector3d k = new Vector3d(logUniform(r, 0.1, 10), logUniform(r, 0.1, 10), logUniform(r, 0.1, 10));
                return ClosedMesh.icosphere(2).transformed(s, k, t);
        }
    }

    /**
     * Trap: a non-watertight test (Moller-Trumbore's u >= 0, v >= 0, u + v <= 1 computed separately per
     * triangle) lets rays through exact shared vertices and edges slip between both triangles, which
     * shows as pinholes of background along a mesh's edges. Rays are aimed at every vertex, every edge
     * midpoint and a random point on every edge, from a random direction entering the mesh there.
     */
    @Test
    void raysThroughSharedEdgesAndVerticesOfClosedMeshAlwaysHit() {
        int[] totals = new int[2];
        forEachSeed(0x7a7e47L, CASES, r -> {
            ClosedMesh m = randomMesh(r);
            List<Triangle> tris = m.triangles();
            Scene scene = RobustSupport.scene(tris);
            List<List<Integer>> around = m.facesAroundVertices();
            List<String> slips = new ArrayList<>();
            int rays = 0;
            for (int v = 0; v < m.vertices.size(); v++) {
                shoot(r, m, tris, scene, m.vertices.get(v), around.get(v), "vertex " + v, slips);
                rays++;
            }
            for (int[] e : m.edges()) {
                Vector3d a = m.vertices.get(e[0]), b = m.vertices.get(e[1]);
                List<Integer> faces = List.of(e[2], e[3]);
                Vector3d mid = new Vector3d((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2);
                shoot(r, m, tris, scene, mid, faces, "midpoint of edge " + e[0] + "-" + e[1], slips);
                double l = r.nextDouble();
                shoot(r, m, tris, scene, add(a, l, sub(b, a)), faces, "point " + l + " along edge " + e[0] + "-" + e[1], slips);
                rays += 2;
            }
            totals[0] += rays;
            totals[1] += slips.size();
            if (!slips.isEmpty()) {
                fail(slips.size() + " of " + rays + " rays slipped through the mesh; first: " + slips.get(0));
            }
        });
        assertTrue(totals[0] > 20000, "too few rays tested: " + totals[0]);
    }

    /**
     * Shoots a ray at {@code p} from outside, along a direction that enters the mesh through every face in
     * {@code faces}; the closest hit (brute force and BVH) must exist and be at p.
     */
    private static void shoot(Random r, ClosedMesh m, List<Triangle> tris, Scene scene, Vector3d p, List<Integer> faces,
                              String what, List<String> slips) {
        Vector3d e = entering(r, m, faces);
        double size = Math.max(maxAbs(sub(m.vertices.get(0), m.vertices.get(m.vertices.size() / 2))), Double.MIN_NORMAL);
        Vector3d o = add(p, size * logUniform(r, 1e-3, 1e3), e);
        Vector3d d = sub(p, o);
        d.scale(logUniform(r, 1e-3, 1e3));
        Ray ray = new Ray(o, d);
        ray.tMin = 0;
        IntersectionRecord best = null;
        for (Triangle t : tris) {
            IntersectionRecord rec = new IntersectionRecord();
            Ray q = new Ray(o, d);
            q.tMin = 0;
            q.tMax = best == null ? Double.POSITIVE_INFINITY : best.t;
            if (t.intersects(q, rec, scene)) {
                best = rec;
            }
        }
        IntersectionRecord bvh = new IntersectionRecord();
        boolean bvhHit = scene.intersect(ray, bvh);
        if (best == null || !bvhHit) {
            slips.add(what + " " + p + (best == null ? " (brute force missed)" : "") + (bvhHit ? "" : " (BVH missed)") + ", " + ray);
            return;
        }
        double tol = 1e3 * RobustSupport.EPS * (maxAbs(o) + maxAbs(p));
        double off = maxAbs(sub(best.location, p));
        if (off > tol) {
            slips.add(what + ": hit " + off + " away from the aimed point (tolerance " + tol + ") at " + best.location + ", " + ray);
        }
        assertEquals(best.t, bvh.t, 1e-12 * best.t, "BVH and brute force disagree on t for " + what + ", " + ray);
    }

    /** A unit direction pointing out of every face in {@code faces} (by at least 0.05 in cosine). */
    private static Vector3d entering(Random r, ClosedMesh m, List<Integer> faces) {
        Vector3d mean = new Vector3d();
        for (int f : faces) {
            mean.add(m.faceNormal(f));
        }
        mean.normalize();
        for (int attempt = 0; attempt < 50; attempt++) {
            Vector3d e = unit(r);
            e.scaleAdd(1.5, mean, e);
            e.normalize();
            boolean ok = true;
            for (int f : faces) {
                ok &= e.dot(m.faceNormal(f)) > 0.05;
            }
            if (ok) {
                return e;
            }
        }
        return mean;
    }

    /**
     * Trap: a hit point computed as o + t d from a far origin is off the triangle's plane by the rounding
     * of t times |d| (the distance travelled), so spawned rays start behind it. The point is computed
     * from the barycentrics instead: it must lie within 8 eps max|v| of the plane (measured exactly) and
     * within the record's own error bound, for triangles at scales 1e-6..1e6 up to a million sizes
     * from the origin, hit from up to 1e4 sizes away with unnormalised directions.
     */
    @Test
    void hitPointLiesOnTriangleWithinRelativeBound() {
        forEachSeed(0x7e1a7eL, 10000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e6));
            Vector3d a = add(c, s, unit(r)), b = add(c, s, unit(r)), d = add(c, s, unit(r));
            Triangle tri = RobustSupport.triangle(a, b, d);
            Vector3d n = new Vector3d();
            n.cross(sub(b, a), sub(d, a));
            if (tri.isDegenerate() || n.length() < 1e-3 * s * s) {
                return;                                  // slivers are the needle test's business
            }
            n.normalize();
            double u = 0.01 + 0.98 * r.nextDouble(), v = (0.99 - u) * r.nextDouble();
            Vector3d aim = add(add(a, u, sub(b, a)), v, sub(d, a));
            double cos = logUniform(r, 1e-3, 1);
            Vector3d o = add(aim, s * logUniform(r, 1e-3, 1e4), RobustSupport.atAngle(r, n, cos));
            Ray ray = new Ray(o, RobustSupport.unnormalised(r, sub(aim, o)));
            ray.tMin = 0;
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(tri.intersects(ray, rec, null), "missed the interior of " + tri + ": " + ray);
            double m = Math.max(maxAbs(a), Math.max(maxAbs(b), maxAbs(d)));
            double res = Math.abs(RobustSupport.planeResidual(rec.location, a, b, d));
            assertTrue(res <= 8 * RobustSupport.EPS * m, "hit point " + res + " off the plane (bound " + 8 * RobustSupport.EPS * m + "): "
                    + rec + ", " + ray);
            assertTrue(res <= rec.error, "record's error bound " + rec.error + " is below the actual error " + res);
            assertTrue(rec.normal.dot(ray.direction) < 0 && Math.abs(rec.normal.length() - 1) < 1e-12, "normal: " + rec);
        });
    }

    /** Sanity check of the generator the other tests rely on: closed, outward-wound meshes. */
    @Test
    void generatedMeshesAreClosedAndWoundOutward() {
        for (ClosedMesh m : List.of(ClosedMesh.icosphere(2), ClosedMesh.cubeGrid(5))) {
            for (int[] e : m.edges()) {
                assertTrue(e[3] >= 0, "edge " + e[0] + "-" + e[1] + " has one face: the mesh is open");
            }
            for (int f = 0; f < m.faces.size(); f++) {
                Vector3d c = new Vector3d();
                for (int v : m.faces.get(f)) {
                    c.add(m.vertices.get(v));
                }
                assertTrue(m.faceNormal(f).dot(c) > 0, "face " + f + " is wound inward");
            }
            assertEquals(2, m.vertices.size() - m.edges().size() + m.faces.size(), "Euler characteristic of a sphere");
        }
    }

    /**
     * Trap: the slab test or the triangle set-up dividing by a zero direction component. Rays exactly
     * along an axis (two direction components +0.0 or -0.0) down onto every grid vertex of a box, those
     * on the box's edges included (where the side faces lie exactly in the ray's plane), must hit.
     */
    @Test
    void axisParallelRaysOntoGridVerticesHit() {
        forEachSeed(0xa415L, 8, r -> {
            double s = Math.scalb(1.0, r.nextInt(41) - 20) * (r.nextBoolean() ? 1 : 3);
            Vector3d t = new Vector3d(r.nextInt(2001) - 1000, r.nextInt(2001) - 1000, r.nextInt(2001) - 1000);
            t.scale(s * logUniform(r, 1, 1e3));
            ClosedMesh m = ClosedMesh.cubeGrid(4).transformed(s, new Vector3d(1, 1, 1), t);
            List<Triangle> tris = m.triangles();
            Scene scene = RobustSupport.scene(tris);
            int misses = 0, rays = 0;
            String first = null;
            for (Vector3d p : m.vertices) {
                for (int axis = 0; axis < 3; axis++) {
                    for (int sign = -1; sign <= 1; sign += 2) {
                        double[] dir = {0, 0, 0};
                        dir[axis] = -sign * logUniform(r, 1e-3, 1e3);
                        // only vertices on the face the ray comes down on (its coordinate on that side)
                        double pc = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
                        double centre = axis == 0 ? t.x : axis == 1 ? t.y : t.z;
                        if (sign * (pc - centre) <= 0) {
                            continue;
                        }
                        Vector3d o = new Vector3d(p);
                        double lift = 4 * s;
                        if (axis == 0) o.x += sign * lift; else if (axis == 1) o.y += sign * lift; else o.z += sign * lift;
                        // -0.0 in the zero components half the time
                        double z = r.nextBoolean() ? 0.0 : -0.0;
                        Vector3d d = new Vector3d(dir[0] == 0 ? z : dir[0], dir[1] == 0 ? z : dir[1], dir[2] == 0 ? z : dir[2]);
                        Ray ray = new Ray(o, d);
                        ray.tMin = 0;
                        IntersectionRecord rec = new IntersectionRecord();
                        rays++;
                        if (!scene.intersect(ray, rec)) {
                            misses++;
                            if (first == null) {
                                first = "vertex " + p + ", " + ray;
                            }
                        }
                    }
                }
            }
            assertEquals(0, misses, misses + " of " + rays + " axis-parallel rays missed the box; first: " + first);
        });
    }
}
