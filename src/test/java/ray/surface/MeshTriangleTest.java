package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

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
import ray.accel.Aabb;

/**
 * The primitives a mesh hands the BVH (one {@link MeshTriangle} per face): each one's box is exactly its
 * corners' box, its packed-set type follows the mesh's sidedness, and its own hit test agrees with the
 * mesh's (same t, point, normal, side, surface) on its own face and misses elsewhere.
 */
class MeshTriangleTest {

    @TempDir
    Path dir;

    // two triangles of a tilted quad: (0,0,0) (2,0,1) (2,3,1) and (0,0,0) (2,3,1) (0,3,0), facing +z-ish
    private static final String QUAD = "v 0 0 0\nv 2 0 1\nv 2 3 1\nv 0 3 0\nf 1 2 3\nf 1 3 4\n";

    private Mesh mesh(int twoSided) throws Exception {
        return MeshTest.mesh(dir, QUAD, 0, twoSided);
    }

    private static List<Surface> triangles(Mesh m) {
        List<Surface> out = new ArrayList<>();
        m.collectPrimitives(out);
        return out;
    }

    @Test
    void eachTrianglesBoxIsItsCornersBox() throws Exception {
        List<Surface> t = triangles(mesh(0));
        assertEquals(2, t.size());
        Aabb a = t.get(0).bounds(), b = t.get(1).bounds();
        assertEquals(List.of(0.0, 0.0, 0.0, 2.0, 3.0, 1.0), List.of(a.minX, a.minY, a.minZ, a.maxX, a.maxY, a.maxZ), "" + a);
        assertEquals(List.of(0.0, 0.0, 0.0, 2.0, 3.0, 1.0), List.of(b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ), "" + b);
        // the BVH build's way: into a box it reuses (whatever it held before)
        Aabb c = t.get(1).primitiveType().bounds(t.get(1), new Aabb(-9, -9, -9, 9, 9, 9));
        assertEquals(List.of(0.0, 0.0, 0.0, 2.0, 3.0, 1.0), List.of(c.minX, c.minY, c.minZ, c.maxX, c.maxY, c.maxZ), "" + c);
        assertTrue(t.get(0).toString().startsWith("triangle 1 of "), t.get(0).toString());
        assertTrue(t.get(1).toString().startsWith("triangle 2 of "), t.get(1).toString());
    }

    @Test
    void packedTypeFollowsTheMeshsSides() throws Exception {
        for (Surface s : triangles(mesh(0))) {
            assertSame(MeshSet.ONE_SIDED, s.primitiveType());
        }
        for (Surface s : triangles(mesh(1))) {
            assertSame(MeshSet.TWO_SIDED, s.primitiveType());
        }
    }

    @Test
    void packedSetHoldsEachTriangleOnceWithItsMesh() throws Exception {
        Mesh m = mesh(1);
        List<Surface> t = triangles(m);
        ray.accel.PrimitiveSet set = t.get(0).primitiveType().pack(t);
        assertEquals(2, set.size());
        assertSame(m, set.surface(0));
        assertSame(m, set.surface(1));
        // nine floats of corners and the index per triangle; the one mesh once for the set
        assertEquals(2 * (9 * 4 + 4), set.memoryBytes());
    }

    @Test
    void packedSetOfTwoMeshesKeepsEachTrianglesMesh() throws Exception {
        Mesh a = mesh(1), b = mesh(1);
        List<Surface> t = new ArrayList<>(triangles(a));
        t.addAll(1, triangles(b));
        ray.accel.PrimitiveSet set = t.get(0).primitiveType().pack(t);
        assertEquals(4, set.size());
        assertSame(a, set.surface(0));
        assertSame(b, set.surface(1));
        assertSame(b, set.surface(2));
        assertSame(a, set.surface(3));
        // nine floats of corners and two ints (mesh, index) per triangle
        assertEquals(4 * (9 * 4 + 4 + 4), set.memoryBytes());
    }

    @Test
    void ownHitAgreesWithTheMeshs() throws Exception {
        long seed = 11;
        Random rnd = new Random(seed);
        Scene scene = new Scene();
        for (int twoSided = 0; twoSided < 2; twoSided++) {
            Mesh m = mesh(twoSided);
            List<Surface> t = triangles(m);
            for (int i = 0; i < 200; i++) {
                // a point of the quad's plane z = x / 2, aimed at from above or below
                double x = rnd.nextDouble() * 2, y = rnd.nextDouble() * 3;
                boolean below = rnd.nextBoolean();
                Ray ray = new Ray(new Vector3d(x, y, x / 2 + (below ? -4 : 4)), new Vector3d(0, 0, below ? 1 : -1));
                String what = "seed " + seed + ", ray " + i + " " + ray + ", twoSided " + twoSided;
                IntersectionRecord want = new IntersectionRecord();
                boolean hit = m.intersects(ray, want, scene);
                assertEquals(!below || twoSided == 1, hit, "the mesh's own answer: " + what);
                int face = y < 1.5 * x ? 0 : 1;   // the diagonal from (0,0) to (2,3)
                for (int k = 0; k < 2; k++) {
                    IntersectionRecord got = new IntersectionRecord();
                    boolean own = t.get(k).intersects(ray, got, scene);
                    if (Math.abs(y - 1.5 * x) < 1e-9) {
                        continue;                   // on the shared edge either may answer
                    }
                    assertEquals(hit && k == face, own, "triangle " + k + ": " + what);
                    if (own) {
                        assertEquals(want.t, got.t, 0, what);
                        assertEquals(want.location, got.location, what);
                        assertEquals(want.normal, got.normal, what);
                        assertEquals(want.frontFace, got.frontFace, what);
                        assertEquals(!below, got.frontFace, what);
                        assertSame(m, got.surface, what);
                    }
                }
            }
        }
    }
}
