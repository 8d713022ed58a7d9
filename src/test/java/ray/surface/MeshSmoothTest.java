package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Aabb;
import ray.accel.Bvh;

/**
 * A smooth mesh's normal, restated from scratch: the corner normals scaled to length 1
 * (stored as floats), blended by the hit's barycentrics, turned to the facet's side when the blend points behind
 * it, normalized; over seeded random triangles and corner normals (any length, any direction, normal
 * index 0 included), through the mesh's own BVH and each triangle's own test. Plus: a blend exactly
 * perpendicular to the facet is kept as it is, the occlusion test on each side of one- and two-sided
 * meshes, and the mesh's box holding only the vertices its faces use.
 */
class MeshSmoothTest {

    @TempDir
    Path dir;

    private Mesh mesh(String obj, int smooth, int twoSided) throws Exception {
        return MeshTest.mesh(dir, obj, smooth, twoSided);
    }

    @Test
    void smoothNormalIsTheBlendTurnedToTheFacet() throws Exception {
        long seed = 465;
        Random rnd = new Random(seed);
        int tris = 6, normals = 7;
        double[][] p = new double[3 * tris][3], n = new double[normals][3];
        int[][] ni = new int[tris][3];
        StringBuilder obj = new StringBuilder();
        for (int i = 0; i < 3 * tris; i++) {
            for (int c = 0; c < 3; c++) {
                p[i][c] = (float) (rnd.nextDouble() - 0.5 + (c == 0 ? 10 * (i / 3) : 0));   // 10 apart in x; read as floats
            }
            obj.append(String.format(Locale.ROOT, "v %.17g %.17g %.17g%n", p[i][0], p[i][1], p[i][2]));
        }
        for (int j = 0; j < normals; j++) {
            double len = 0.2 + 3 * rnd.nextDouble();
            for (int c = 0; c < 3; c++) {
                n[j][c] = (float) (len * (2 * rnd.nextDouble() - 1));
            }
            obj.append(String.format(Locale.ROOT, "vn %.17g %.17g %.17g%n", n[j][0], n[j][1], n[j][2]));
        }
        for (int t = 0; t < tris; t++) {
            obj.append("f");
            for (int k = 0; k < 3; k++) {
                ni[t][k] = (t + 2 * k) % normals;   // every index, 0 among them, in every corner position
                obj.append(" ").append(3 * t + k + 1).append("//").append(ni[t][k] + 1);
            }
            obj.append("\n");
        }
        Mesh m = mesh(obj.toString(), 1, 0);
        List<Surface> own = new java.util.ArrayList<>();
        m.collectPrimitives(own);
        Scene scene = new Scene();
        int flipped = 0;
        for (int t = 0; t < tris; t++) {
            Vector3d a = v(p[3 * t]), e1 = v(p[3 * t + 1]), e2 = v(p[3 * t + 2]), facet = new Vector3d();
            e1.sub(a);
            e2.sub(a);
            facet.cross(e1, e2);
            facet.normalize();
            for (int s = 0; s < 20; s++) {
                double b1 = rnd.nextDouble(), b2 = rnd.nextDouble() * (1 - b1);
                double[] b = {1 - b1 - b2, b1, b2};
                Vector3d hit = new Vector3d(), want = new Vector3d();
                for (int k = 0; k < 3; k++) {
                    double[] q = p[3 * t + k], c = n[ni[t][k]];
                    double len = Math.sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
                    hit.scaleAdd(b[k], new Vector3d(q[0], q[1], q[2]), hit);
                    want.scaleAdd(b[k], new Vector3d((float) (c[0] / len), (float) (c[1] / len), (float) (c[2] / len)), want);
                }
                if (want.dot(facet) < 0) {
                    want.negate();
                    flipped++;
                }
                want.normalize();
                Ray ray = new Ray(new Vector3d(hit.x + 0.5 * facet.x, hit.y + 0.5 * facet.y, hit.z + 0.5 * facet.z),
                        new Vector3d(-facet.x, -facet.y, -facet.z));
                String what = "seed " + seed + ", triangle " + t + ", barycentrics " + java.util.Arrays.toString(b);
                IntersectionRecord rec = new IntersectionRecord();
                assertTrue(m.intersects(ray, rec, scene), what);
                near(want, rec.normal, "mesh normal, " + what);
                assertEquals(0.5, rec.t, 1e-9, what);
                IntersectionRecord one = new IntersectionRecord();
                assertTrue(own.get(t).intersects(ray, one, scene), what);
                near(want, one.normal, "triangle's own normal, " + what);
            }
        }
        assertTrue(flipped > 10 && flipped < 100, "both sides of the facet among the blends: " + flipped + " flipped");
    }

    /** Within float precision: the file's numbers are read as floats. */
    private static void near(Vector3d want, Vector3d got, String what) {
        assertTrue(Math.abs(want.x - got.x) < 1e-6 && Math.abs(want.y - got.y) < 1e-6 && Math.abs(want.z - got.z) < 1e-6,
                what + ": expected " + want + ", got " + got);
    }

    private static Vector3d v(double[] a) {
        return new Vector3d(a[0], a[1], a[2]);
    }

    @Test
    void aBlendPerpendicularToTheFacetIsKept() throws Exception {
        Mesh m = mesh("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 2 0 0\nf 1//1 2//1 3//1\n", 1, 0);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(m.intersects(new Ray(new Vector3d(0.25, 0.25, 1), new Vector3d(0, 0, -1)), rec, new Scene()));
        SphereTest.assertVec(1, 0, 0, rec.normal, "normal " + rec.normal);
    }

    @Test
    void occlusionSeesTheBackOnlyOfATwoSidedMesh() throws Exception {
        // three triangles side by side in z = 0, facing +z
        String obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 2 1 0\nv 4 0 0\nv 5 0 0\nv 4 1 0\n"
                + "f 1 2 3\nf 4 5 6\nf 7 8 9\n";
        for (int twoSided = 0; twoSided < 2; twoSided++) {
            Mesh m = mesh(obj, 0, twoSided);
            Bvh bvh = Bvh.build(List.of(m), new Scene());
            TraceContext ctx = new TraceContext(0);
            for (int t = 0; t < 3; t++) {
                double x = 2 * t + 0.25;
                assertTrue(bvh.anyHit(new Ray(new Vector3d(x, 0.25, 1), new Vector3d(0, 0, -1)), ctx),
                        "front of triangle " + t + ", twoSided " + twoSided);
                assertEquals(twoSided == 1, bvh.anyHit(new Ray(new Vector3d(x, 0.25, -1), new Vector3d(0, 0, 1)), ctx),
                        "back of triangle " + t + ", twoSided " + twoSided);
                Ray shortRay = new Ray(new Vector3d(x, 0.25, -1), new Vector3d(0, 0, 1));
                shortRay.tMax = 0.5;
                assertEquals(false, bvh.anyHit(shortRay, ctx), "short of triangle " + t);
                IntersectionRecord rec = new IntersectionRecord();
                assertEquals(twoSided == 1, m.intersects(new Ray(new Vector3d(x, 0.25, -1), new Vector3d(0, 0, 1)), rec,
                        new Scene()), "closest hit from the back of triangle " + t + ", twoSided " + twoSided);
            }
        }
    }

    @Test
    void boxHoldsOnlyTheVerticesFacesUse() throws Exception {
        Mesh m = mesh("v 100 100 100\nv 0 0 0\nv 1 -2 0\nv 0 1 3\nf 2 3 4\n", 0, 0);
        Aabb b = m.bounds();
        assertEquals(List.of(0.0, -2.0, 0.0, 1.0, 1.0, 3.0), List.of(b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ), "" + b);
    }
}
