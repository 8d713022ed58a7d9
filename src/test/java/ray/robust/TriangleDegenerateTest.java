package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
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
import ray.accel.Aabb;
import ray.parse.Parser;
import ray.surface.Triangle;

/**
 * Triangles that cannot be hit: zero-area ones (never hit, no shadow, one warning at load), needles
 * (finite hits or misses), and any triangle for a ray lying in its plane.
 */
class TriangleDegenerateTest {

    /**
     * Trap: a zero-area triangle producing hits (NaN normal, division by zero) or casting shadows. A
     * repeated vertex and exactly collinear vertices (integers times 2^k), at any scale: rays aimed at
     * their vertices and midpoints never hit them, directly or through the BVH.
     */
    @Test
    void zeroAreaTrianglesAreNeverHit() {
        forEachSeed(0xde9L, 200, r -> {
            double k = Math.scalb(1.0, r.nextInt(41) - 20);
            Vector3d a = ints(r, 1000), e = ints(r, 50);
            a.scale(k);
            e.scale(k);
            Vector3d b = add(a, 1, e);
            Vector3d c = r.nextBoolean() ? new Vector3d(b) : add(a, -3, e);
            Triangle tri = RobustSupport.triangle(a, b, c);
            assertTrue(tri.isDegenerate(), "not recognised as zero-area: " + tri);
            Scene scene = RobustSupport.scene(List.of(tri));
            for (Vector3d p : new Vector3d[] {a, b, c, add(a, 0.5, sub(c, a)), add(a, 0.5, sub(b, a))}) {
                Vector3d o = add(p, k * logUniform(r, 1e-3, 1e3), unit(r));
                Ray ray = new Ray(o, sub(p, o));
                ray.tMin = 0;
                IntersectionRecord rec = new IntersectionRecord();
                assertFalse(tri.intersects(ray, rec, scene), "zero-area triangle hit: " + tri + " by " + ray);
                assertFalse(scene.intersect(ray, rec), "zero-area triangle hit through the BVH: " + tri + " by " + ray);
                assertFalse(scene.occluded(ray), "zero-area triangle casts a shadow: " + tri);
            }
        });
    }

    /**
     * Trap: a needle (three vertices collinear before rounding, so a sliver of area ~ulp after it) that is
     * not zero-area giving a NaN normal or a hit point off the triangle. Any hit must be finite, with a
     * unit normal, inside the triangle's box.
     */
    @Test
    void needleTrianglesGiveFiniteHitsOrMisses() {
        forEachSeed(0x9eed1eL, 500, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d a = unit(r), e = unit(r);
            a.scale(s * logUniform(r, 1e-3, 1e6));
            e.scale(s);
            Triangle tri = RobustSupport.triangle(a, add(a, 1, e), add(a, 2, e));
            for (int i = 0; i < 8; i++) {
                Vector3d p = add(a, 2 * r.nextDouble(), e);
                Vector3d o = add(p, s * logUniform(r, 1e-3, 1e3), unit(r));
                Ray ray = new Ray(o, sub(p, o));
                ray.tMin = 0;
                IntersectionRecord rec = new IntersectionRecord();
                if (tri.intersects(ray, rec, null)) {
                    assertTrue(Double.isFinite(rec.t) && Double.isFinite(maxAbs(rec.location)), "non-finite hit " + rec);
                    assertEquals(1, rec.normal.length(), 1e-12, "normal not unit: " + rec);
                    double slack = 1e-12 * (maxAbs(a) + s);
                    Aabb box = tri.bounds();
                    Vector3d q = rec.location;
                    assertTrue(q.x >= box.minX - slack && q.y >= box.minY - slack && q.z >= box.minZ - slack
                            && q.x <= box.maxX + slack && q.y <= box.maxY + slack && q.z <= box.maxZ + slack,
                            "hit outside the needle's box: " + rec + " for " + tri);
                }
            }
        });
    }

    /** Trap: one warning per zero-area triangle flooding the console, or none at all. */
    @Test
    void zeroAreaTrianglesAreReportedOnceAtLoad() throws Exception {
        StringBuilder sb = new StringBuilder("Width 8\nHeight 6\n\nCamera Camera\n\nMaterial Diffuse m\n\n");
        sb.append("Surface Triangle\nVector3d v0 [0 0 0]\nVector3d v1 [1 0 0]\nVector3d v2 [0 1 0]\nref material m\n\n");
        for (int i = 0; i < 3; i++) {    // the first zero-area triangle's header is line 14
            sb.append("Surface Triangle\nVector3d v0 [1 1 1]\nVector3d v1 [2 2 2]\nVector3d v2 [3 3 3]\nref material m\n\n");
        }
        List<String> warnings = new ArrayList<>();
        Scene s = Parser.parse(sb.toString(), "deg.txt", warnings);
        assertEquals(1, warnings.size(), "expected one warning, got " + warnings);
        assertTrue(warnings.get(0).startsWith("deg.txt:14:"), warnings.get(0));
        assertTrue(warnings.get(0).contains("and 2 more"), warnings.get(0));
        assertEquals(4, s.surfaces.size());
    }

    /**
     * Trap: a ray lying in the triangle's plane being reported as a hit (the edge functions are all 0,
     * the determinant 0: a division by zero gives an arbitrary t). Integer coordinates times a power of
     * two keep the ray exactly in the plane at every scale; it runs through the triangle's interior.
     */
    @Test
    void raysInTheTrianglePlaneMiss() {
        forEachSeed(0x9a7a11e1L, 2000, r -> {
            double s = Math.scalb(1.0, r.nextInt(81) - 40);
            Vector3d v0 = ints(r, 1000), e = ints(r, 64), f = ints(r, 64);
            Vector3d v1 = add(v0, 1, e), v2 = add(v0, 1, f);
            Vector3d n = new Vector3d();
            n.cross(e, f);
            if (n.lengthSquared() == 0) {
                return;
            }
            // origin outside the triangle in its plane, v0 - a (e + f); the ray along e + f crosses v0 and the interior
            int a = 1 + r.nextInt(4);
            Vector3d o = add(add(v0, -a, e), -a, f);
            Vector3d d = add(new Vector3d(e), 1, f);
            d.scale(1 + r.nextInt(5));
            for (Vector3d v : new Vector3d[] {v0, v1, v2, o}) {
                v.scale(s);
            }
            d.scale(s);
            Triangle tri = RobustSupport.triangle(v0, v1, v2);
            Ray ray = new Ray(o, d);
            ray.tMin = 0;
            assertFalse(tri.intersects(ray, new IntersectionRecord(), null), "ray in the plane of " + tri + " hit it: " + ray);
        });
    }
    private static Vector3d ints(Random r, int n) {
        return new Vector3d(r.nextInt(2 * n + 1) - n, r.nextInt(2 * n + 1) - n, r.nextInt(2 * n + 1) - n);
    }
}
