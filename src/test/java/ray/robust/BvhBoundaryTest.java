package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.forEachSeed;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.surface.Surface;

/**
 * BVH traversal loses no hit at box boundaries. Everything sits on a lattice of quarter units (times a
 * power of two, shifted by a lattice offset), so primitive and node boxes have their faces exactly on
 * lattice planes, and rays start exactly on those planes, run exactly along them, or run along an
 * axis with the other two direction components +0.0 or -0.0. A third of the cases shift the lattice by
 * an offset that floats cannot hold, so node boxes must be rounded outward. The BVH's answer must equal a brute-force
 * loop over the same surfaces, for closest hits and for shadow queries.
 */
class BvhBoundaryTest {

    private static double lattice(Random r, int range) {
        return 0.25 * (r.nextInt(8 * range + 1) - 4 * range);
    }

    private static Vector3d latticePoint(Random r, int range, double s, Vector3d t) {
        return new Vector3d(s * lattice(r, range) + t.x, s * lattice(r, range) + t.y, s * lattice(r, range) + t.z);
    }

    /** Cubes (closed 12-triangle boxes), spheres and flat axis-aligned triangles, all on the lattice. */
    private static List<Surface> latticeScene(Random r, double s, Vector3d t) {
        List<Surface> out = new ArrayList<>();
        for (int i = 0; i < 25; i++) {
            Vector3d c = latticePoint(r, 2, s, t);
            double h = 0.25 * (1 + r.nextInt(2)) * s;
            out.addAll(ClosedMesh.cubeGrid(1).transformed(h, new Vector3d(1, 1, 1), c).triangles());
        }
        for (int i = 0; i < 15; i++) {
            out.add(RobustSupport.sphere(latticePoint(r, 2, s, t), 0.25 * (1 + r.nextInt(2)) * s));
        }
        for (int i = 0; i < 15; i++) {
            // a triangle in a lattice plane normal to one axis, either winding
            Vector3d a = latticePoint(r, 2, s, t), b = latticePoint(r, 2, s, t), c = latticePoint(r, 2, s, t);
            int axis = r.nextInt(3);
            double plane = axis == 0 ? a.x : axis == 1 ? a.y : a.z;
            for (Vector3d v : new Vector3d[] {b, c}) {
                if (axis == 0) v.x = plane; else if (axis == 1) v.y = plane; else v.z = plane;
            }
            ray.surface.Triangle tri = RobustSupport.triangle(a, b, c);
            if (!tri.isDegenerate()) {
                out.add(tri);
            }
        }
        return out;
    }

    /** A direction of one of three kinds: along an axis (signed zeros), in a lattice plane, or general. */
    private static Vector3d direction(Random r) {
        double len = Math.scalb(1.0, r.nextInt(21) - 10);
        double[] d = new double[3];
        switch (r.nextInt(3)) {
            case 0:
                d[r.nextInt(3)] = r.nextBoolean() ? len : -len;
                break;
            case 1:
                for (int k = 0; k < 3; k++) {
                    d[k] = len * (r.nextInt(5) - 2) * 0.5;
                }
                d[r.nextInt(3)] = 0;
                break;
            default:
                for (int k = 0; k < 3; k++) {
                    d[k] = r.nextBoolean() ? len * (r.nextInt(5) - 2) * 0.5 : len * r.nextGaussian();
                }
        }
        for (int k = 0; k < 3; k++) {
            if (d[k] == 0 && r.nextBoolean()) {
                d[k] = -0.0;
            }
        }
        return new Vector3d(d[0], d[1], d[2]);
    }

    /**
     * Trap: a slab test that computes (plane - origin) * (1 / 0) = 0 * infinity = NaN and lets the NaN
     * reject the box (origin on the plane, ray along it), or that rounds a zero-thickness box (a flat
     * triangle's) or a box face touched exactly by the ray inward, losing the hit; float node boxes
     * rounded to nearest instead of outward.
     */
    @Test
    void bvhFindsTheSameHitsAsBruteForceOnBoxBoundaries() {
        int[] checked = new int[2];
        forEachSeed(0xb0c5L, 20, r -> {
            double s = Math.scalb(1.0, r.nextInt(41) - 20);
            // at the origin, shifted by whole lattice steps (planes stay exact in float), or by an arbitrary
            // offset (then float node boxes must be rounded outward, not to nearest)
            Vector3d t = new Vector3d(r.nextInt(2001) - 1000, r.nextInt(2001) - 1000, r.nextInt(2001) - 1000);
            int shift = r.nextInt(3);
            t.scale(shift == 0 ? 0 : shift == 1 ? s : s * Math.PI);
            List<Surface> surfaces = latticeScene(r, s, t);
            Scene scene = RobustSupport.scene(surfaces);
            for (int i = 0; i < 800; i++) {
                Vector3d o = latticePoint(r, 3, s, t);
                Ray ray = new Ray(o, direction(r));
                ray.tMin = 0;
                if (r.nextInt(3) == 0) {
                    ray.tMax = s * 0.25 * r.nextInt(20) / ray.direction.length();
                }
                double brute = bruteForce(surfaces, ray);
                IntersectionRecord rec = new IntersectionRecord();
                boolean hit = scene.intersect(ray, rec);
                String what = ray + " among " + surfaces.size() + " surfaces";
                assertEquals(!Double.isNaN(brute), hit, "BVH " + (hit ? "hit" : "missed") + " where brute force "
                        + (hit ? "missed" : "hit at t " + brute) + ": " + what);
                if (hit) {
                    assertEquals(brute, rec.t, 1e-12 * Math.abs(brute), "closest t differs: " + what);
                    checked[1]++;
                }
                assertEquals(hit, scene.occluded(ray), "shadow query disagrees with the closest hit: " + what);
                checked[0]++;
            }
        });
        assertTrue(checked[1] > checked[0] / 5, "too few hits to mean anything: " + checked[1] + " of " + checked[0]);
    }

    /** The closest t over all surfaces by plain loop, NaN for none. */
    private static double bruteForce(List<Surface> surfaces, Ray ray) {
        double best = Double.NaN;
        for (Surface sf : surfaces) {
            Ray q = new Ray(ray.origin, ray.direction);
            q.tMin = ray.tMin;
            q.tMax = Double.isNaN(best) ? ray.tMax : best;
            IntersectionRecord rec = new IntersectionRecord();
            if (sf.intersects(q, rec, null)) {
                best = rec.t;
            }
        }
        return best;
    }
}
