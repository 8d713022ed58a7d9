package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.parse.SceneFormatException;

/**
 * The seeded brute-force check of {@link CSGPropertyTest} with every closed surface as a leaf: spheres,
 * boxes, cylinders, cones, tori and a closed two-sided mesh (a convex polyhedron). Each leaf's roots
 * along the ray are collected by asking the leaf itself again and again; each interval between roots
 * is judged by point membership (the solids' inequalities, the polyhedron's face planes) at its middle.
 */
class CSGPrimitivesPropertyTest {

    @TempDir
    Path dir;
    private final Scene scene = new Scene();

    private static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    private Surface leaf(Random rnd, Mesh mesh) {
        Vector3d c = v(rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 3 - 1.5, rnd.nextDouble() * 3 - 1.5);
        Vector3d axis = v(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
        axis.normalize();
        double size = 0.5 + rnd.nextDouble() * 1.3;
        Surface s;
        switch (rnd.nextInt(6)) {
            case 0 -> s = CSGTest.sphere(c.x, c.y, c.z, size, CSGTest.material());
            case 1 -> {
                Box b = new Box();
                b.minPoint = v(c.x - size, c.y - 0.7 * size, c.z - 0.5 * size);
                b.maxPoint = v(c.x + size, c.y + 0.7 * size, c.z + 0.5 * size);
                s = b;
            }
            case 2, 3 -> {
                AxialSurface a = rnd.nextBoolean() ? new Cylinder() : new Cone();
                a.base = c;
                axis.scale(2 * size);
                a.axis = axis;
                a.radius = 0.6 * size;
                s = a;
            }
            case 4 -> {
                Torus t = new Torus();
                t.center = c;
                t.axis = axis;
                t.majorRadius = size;
                t.minorRadius = 0.35 * size;
                s = t;
            }
            default -> s = mesh;
        }
        s.material = CSGTest.material();
        s.init();
        return s;
    }

    private Surface tree(Random rnd, int depth, List<Surface> leaves, Mesh mesh) {
        if (depth == 0 || rnd.nextInt(4) == 0) {
            Surface s = leaf(rnd, mesh);
            if (!leaves.contains(s)) {       // the mesh may be used twice: its roots once
                leaves.add(s);
            }
            return s;
        }
        String op = List.of("union", "intersection", "difference").get(rnd.nextInt(3));
        return CSGTest.csg(op, tree(rnd, depth - 1, leaves, mesh), tree(rnd, depth - 1, leaves, mesh));
    }

    /** Point membership from each solid's own inequality. */
    static boolean inside(Surface s, Vector3d p, float[] planes) {
        if (s instanceof CSG c) {
            boolean a = inside(c.left, p, planes), b = inside(c.right, p, planes);
            return switch (c.operation) {
                case "union" -> a || b;
                case "intersection" -> a && b;
                default -> a && !b;
            };
        }
        if (s instanceof Sphere sp) {
            return sq(p.x - sp.center.x) + sq(p.y - sp.center.y) + sq(p.z - sp.center.z) < sq(sp.radius);
        }
        if (s instanceof Box b) {
            return p.x > b.minPoint.x && p.x < b.maxPoint.x && p.y > b.minPoint.y && p.y < b.maxPoint.y
                    && p.z > b.minPoint.z && p.z < b.maxPoint.z;
        }
        if (s instanceof AxialSurface a) {
            Vector3d d = new Vector3d(p);
            d.sub(a.base);
            double h = d.dot(a.axis) / a.axis.lengthSquared();
            Vector3d radial = new Vector3d(a.axis);
            radial.scale(-h);
            radial.add(d);
            double r = a instanceof Cone ? a.radius * (1 - h) : a.radius;
            return h > 0 && h < 1 && radial.length() < r;
        }
        if (s instanceof Torus t) {
            Vector3d d = new Vector3d(p);
            d.sub(t.center);
            Vector3d n = new Vector3d(t.axis);
            n.normalize();
            double z = d.dot(n);
            double rho = Math.sqrt(Math.max(0, d.lengthSquared() - z * z));
            return sq(rho - t.majorRadius) + z * z < sq(t.minorRadius);
        }
        for (int i = 0; i < planes.length; i += 4) {     // the convex mesh: inside every face's plane
            if (planes[i] * p.x + planes[i + 1] * p.y + planes[i + 2] * p.z >= planes[i + 3]) {
                return false;
            }
        }
        return true;
    }

    private static double sq(double x) {
        return x * x;
    }

    /** The closed convex mesh (a polyhedral sphere) and its face planes (n, n.v0), outward. */
    private Mesh mesh(float[][] planesOut) throws IOException, SceneFormatException {
        ObjWriter w = ObjWriter.uvSphere(7, 10, 0.3f, -0.2f, 0.1f, 1.2f);
        Files.writeString(dir.resolve("poly.obj"), w.obj(false, 0, 0, 0));
        Mesh m = new Mesh();
        m.file = "poly.obj";
        m.twoSided = 1;
        m.material = CSGTest.material();
        m.init();
        ray.parse.ObjFile.loadInto(m, dir);
        List<Float> planes = new ArrayList<>();
        for (int[] f : w.faces) {
            float[] a = w.vertices.get(f[0]), b = w.vertices.get(f[1]), c = w.vertices.get(f[2]);
            Vector3d e = v(b[0] - a[0], b[1] - a[1], b[2] - a[2]), g = v(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
            Vector3d n = new Vector3d();
            n.cross(e, g);
            n.normalize();
            planes.add((float) n.x);
            planes.add((float) n.y);
            planes.add((float) n.z);
            planes.add((float) (n.x * a[0] + n.y * a[1] + n.z * a[2]));
        }
        planesOut[0] = new float[planes.size()];
        for (int i = 0; i < planes.size(); i++) {
            planesOut[0][i] = planes.get(i);
        }
        return m;
    }

    @Test
    void randomTreesOfEveryClosedSurfaceMatchBruteForce() throws Exception {
        float[][] planes = new float[1][];
        Mesh poly = mesh(planes);
        int checked = 0, skipped = 0, hits = 0;
        for (long seed = 1; seed <= 150; seed++) {
            Random rnd = new Random(seed * 0x2545F4914F6CDD1DL);
            List<Surface> leaves = new ArrayList<>();
            Surface root = tree(rnd, 3, leaves, poly);
            for (int i = 0; i < 100; i++) {
                Vector3d o = v(rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4);
                Surface aim = leaves.get(rnd.nextInt(leaves.size()));
                Vector3d d = v(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
                if (rnd.nextBoolean()) {
                    ray.accel.Aabb b = aim.bounds();
                    d = v((b.minX + b.maxX) / 2 - o.x + 0.3 * d.x, (b.minY + b.maxY) / 2 - o.y + 0.3 * d.y,
                            (b.minZ + b.maxZ) / 2 - o.z + 0.3 * d.z);
                }
                Ray r = new Ray(o, d);
                r.tMin = 0;
                int result = check(root, leaves, planes[0], r, "seed " + seed + " ray " + i + ": " + r + " through " + root);
                if (result < 0) {
                    skipped++;
                } else {
                    checked++;
                    hits += result;
                }
            }
        }
        assertTrue(skipped < checked / 50, "too many ambiguous rays skipped: " + skipped + " of " + (checked + skipped));
        assertTrue(hits > checked / 5, "too few hits to mean anything: " + hits + " of " + checked);
    }

    private int check(Surface root, List<Surface> leaves, float[] planes, Ray r, String what) {
        List<double[]> roots = new ArrayList<>();      // (t, leaf index)
        IntersectionRecord rec = new IntersectionRecord();
        for (int li = 0; li < leaves.size(); li++) {
            double after = Double.NEGATIVE_INFINITY, from = r.tMin;
            for (int guard = 0; guard < 200; guard++) {
                Ray q = new Ray(r.origin, r.direction);
                q.tMin = from;
                if (!leaves.get(li).intersects(q, rec, scene)) {
                    break;
                }
                if (rec.t > after) {
                    if (rec.t - after > 1e-9 * Math.abs(rec.t)) {   // a mesh reports a ray through an edge twice
                        roots.add(new double[] {rec.t, li});
                    }
                    after = rec.t;
                    from = Math.nextUp(after);
                } else {
                    from = after + 4 * Math.ulp(Math.max(after, Double.MIN_NORMAL)) + (from - after) * 2;
                }
            }
        }
        roots.sort((a, b) -> Double.compare(a[0], b[0]));
        int n = roots.size();
        double tol = 1e-7 * (Math.abs(r.tMin) + (n > 0 ? roots.get(n - 1)[0] : 0)) + 1e-300;
        for (int i = 0; i < n; i++) {
            double prev = i == 0 ? r.tMin : roots.get(i - 1)[0];
            if (roots.get(i)[0] - prev < tol) {
                return -1;     // a tangency, two surfaces meeting on the ray, or the start on a surface: too close to call
            }
        }
        boolean hit = root.intersects(r, rec, scene);
        boolean in = inside(root, r.evaluate(r.tMin), planes);
        for (int i = 0; i < n; i++) {
            double t = roots.get(i)[0];
            double next = i + 1 < n ? roots.get(i + 1)[0] : 2 * t + 1;
            boolean after = inside(root, r.evaluate(0.5 * (t + next)), planes);
            if (after != in) {
                assertTrue(hit, what + ": expected a hit at t = " + t);
                assertEquals(t, rec.t, what);
                Surface leaf = leaves.get((int) roots.get(i)[1]);
                assertSame(leaf, rec.surface, what);
                assertEquals(after, rec.frontFace, what + ": frontFace");
                return 1;
            }
            in = after;
        }
        assertEquals(false, hit, what + ": expected a miss, got " + rec);
        return 0;
    }
}
