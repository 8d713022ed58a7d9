package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;

/**
 * Seeded property test: random CSG trees of spheres (nested up to three levels), random rays from
 * inside and outside, at several scales, checked against a brute-force classification along the ray.
 * The brute force lists every root of every sphere, judges each interval between roots by point
 * membership at its middle, and expects the first root where membership changes (within the ray's
 * span), on the sphere that has that root, with frontFace = inside after it.
 */
class CSGPropertyTest {

    private final Scene scene = new Scene();

    /** A random tree and its spheres. */
    private static final class Tree {
        final List<Sphere> leaves = new ArrayList<>();
        Surface root;
    }

    private static Surface randomTree(Random rnd, int depth, Tree t, double scale, Vector3d offset) {
        if (depth == 0 || rnd.nextInt(4) == 0) {
            Sphere s = CSGTest.sphere(offset.x + scale * (rnd.nextDouble() * 3 - 1.5), offset.y + scale * (rnd.nextDouble() * 3 - 1.5),
                    offset.z + scale * (rnd.nextDouble() * 3 - 1.5), scale * (0.4 + rnd.nextDouble() * 1.6), CSGTest.material());
            t.leaves.add(s);
            return s;
        }
        String op = List.of("union", "intersection", "difference").get(rnd.nextInt(3));
        return CSGTest.csg(op, randomTree(rnd, depth - 1, t, scale, offset), randomTree(rnd, depth - 1, t, scale, offset));
    }

    /** Point membership, straight from the set operations. */
    private static boolean inside(Surface s, Vector3d p) {
        if (s instanceof Sphere sp) {
            double dx = p.x - sp.center.x, dy = p.y - sp.center.y, dz = p.z - sp.center.z;
            return dx * dx + dy * dy + dz * dz < sp.radius * sp.radius;
        }
        CSG c = (CSG) s;
        boolean a = inside(c.left, p), b = inside(c.right, p);
        return switch (c.operation) {
            case "union" -> a || b;
            case "intersection" -> a && b;
            default -> a && !b;
        };
    }

    @Test
    void randomTreesMatchBruteForceClassification() {
        int checked = 0, skipped = 0, hits = 0;
        for (long seed = 1; seed <= 300; seed++) {
            Random rnd = new Random(seed * 0x9E3779B97F4A7C15L);
            double scale = Math.pow(10, rnd.nextInt(9) - 4);          // 1e-4 .. 1e4
            Vector3d offset = new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            offset.scale(scale * (rnd.nextBoolean() ? 1 : 100));
            Tree tree = new Tree();
            tree.root = randomTree(rnd, 3, tree, scale, offset);
            for (int i = 0; i < 200; i++) {
                Vector3d o = new Vector3d(offset.x + scale * (rnd.nextDouble() * 6 - 3), offset.y + scale * (rnd.nextDouble() * 6 - 3),
                        offset.z + scale * (rnd.nextDouble() * 6 - 3));
                Vector3d d = new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
                if (rnd.nextBoolean()) {           // half the rays aimed near a sphere's centre
                    Sphere aim = tree.leaves.get(rnd.nextInt(tree.leaves.size()));
                    d.scale(0.3 * aim.radius);
                    d.add(aim.center);
                    d.sub(o);
                }
                d.scale(Math.exp(rnd.nextDouble() * 4 - 2));
                Ray r = new Ray(o, d);
                r.tMin = 0;
                if (rnd.nextInt(4) == 0) {
                    r.tMax = rnd.nextDouble() * 3 * scale / d.length();
                }
                String what = "seed " + seed + " ray " + i + ": " + r + " through " + tree.root;
                int result = check(tree, r, what);
                if (result < 0) {
                    skipped++;
                } else {
                    checked++;
                    hits += result;
                }
            }
        }
        assertTrue(skipped < checked / 100, "too many ambiguous rays skipped: " + skipped + " of " + (checked + skipped));
        assertTrue(hits > checked / 5, "too few hits to mean anything: " + hits + " of " + checked);
    }

    /** 1 for a checked hit, 0 for a checked miss, -1 for a ray too close to a tangency or a shared root to judge. */
    private int check(Tree tree, Ray r, String what) {
        double[] roots = new double[2 * tree.leaves.size()];
        Sphere[] owner = new Sphere[roots.length];
        int n = 0;
        Vector3d o = r.origin, d = r.direction;
        for (Sphere s : tree.leaves) {
            double t = r.tMin;
            for (int k = 0; k < 2; k++) {
                t = Sphere.hit(s.center.x, s.center.y, s.center.z, s.radius, o.x, o.y, o.z, d.x, d.y, d.z, t, Double.POSITIVE_INFINITY);
                if (Double.isNaN(t)) {
                    break;
                }
                roots[n] = t;
                owner[n++] = s;
                t = Math.nextUp(t);
            }
        }
        Integer[] idx = new Integer[n];
        for (int i = 0; i < n; i++) {
            idx[i] = i;
        }
        Arrays.sort(idx, (a, b) -> Double.compare(roots[a], roots[b]));
        // too close to call: two roots (a tangent ray, two spheres meeting on the ray) or the start on a surface
        double tol = 1e-7 * (Math.abs(r.tMin) + (n > 0 ? roots[idx[n - 1]] : 0)) + 1e-300;
        for (int i = 0; i < n; i++) {
            double prev = i == 0 ? r.tMin : roots[idx[i - 1]];
            if (roots[idx[i]] - prev < tol || Math.abs(roots[idx[i]] - r.tMax) < tol) {
                return -1;
            }
        }
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = tree.root.intersects(r, rec, scene);
        double before = r.tMin;
        boolean in = inside(tree.root, r.evaluate(before));
        for (int i = 0; i < n; i++) {
            double t = roots[idx[i]];
            if (t > r.tMax) {
                break;
            }
            double next = i + 1 < n ? roots[idx[i + 1]] : 2 * t + 1;
            boolean after = inside(tree.root, r.evaluate(0.5 * (t + next)));
            if (after != in) {
                assertTrue(hit, what + ": expected a hit at t = " + t);
                assertEquals(t, rec.t, what);
                assertSame(owner[idx[i]], rec.surface, what);
                assertEquals(after, rec.frontFace, what + ": frontFace");
                assertTrue(rec.normal.dot(d) <= 0, what + ": normal faces the ray");
                return 1;
            }
        }
        assertEquals(false, hit, what + ": expected a miss, got " + rec);
        return 0;
    }
}
