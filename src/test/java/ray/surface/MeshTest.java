package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.parse.SceneFormatException;

/** A mesh's hits by hand: smooth normals from the barycentrics, two sides, and a mesh as a CSG operand. */
class MeshTest {

    @TempDir
    Path dir;
    private final Scene scene = new Scene();

    private Mesh mesh(String obj, int smooth, int twoSided) throws IOException, SceneFormatException {
        return mesh(dir, obj, smooth, twoSided);
    }

    /** A mesh read from {@code obj} written into {@code dir} as m.obj, with the test material. */
    static Mesh mesh(Path dir, String obj, int smooth, int twoSided) throws IOException, SceneFormatException {
        Files.writeString(dir.resolve("m.obj"), obj);
        Mesh m = new Mesh();
        m.file = "m.obj";
        m.smooth = smooth;
        m.twoSided = twoSided;
        m.material = CSGTest.material();
        m.init();
        ray.parse.ObjFile.loadInto(m, dir);
        return m;
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    }

    static final String TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 1 0 1\nvn 0 1 1\nf 1//1 2//2 3//3\n";

    @Test
    void smoothNormalIsTheBarycentricBlendOfTheCornerNormals() throws Exception {
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(mesh(TRIANGLE, 1, 0).intersects(ray(0.25, 0.25, 5, 0, 0, -1), rec, scene));
        // weights 0.5, 0.25, 0.25 of the unit corner normals (0,0,1), (1,0,1)/sqrt2, (0,1,1)/sqrt2
        double h = 0.25 / Math.sqrt(2);
        Vector3d n = new Vector3d(h, h, 0.5 + 2 * h);
        n.normalize();
        assertEquals(n.x, rec.normal.x, 1e-7);
        assertEquals(n.y, rec.normal.y, 1e-7);
        assertEquals(n.z, rec.normal.z, 1e-7);
        assertEquals(5, rec.t, 0);
        assertTrue(rec.frontFace);
        assertTrue(rec.surface instanceof Mesh);
        // flat: the facet's normal
        assertTrue(mesh(TRIANGLE, 0, 0).intersects(ray(0.25, 0.25, 5, 0, 0, -1), rec, scene));
        assertEquals(new Vector3d(0, 0, 1), rec.normal);
    }

    @Test
    void oneSidedMeshIsMissedFromBehindTwoSidedIsHitWithItsBackFace() throws Exception {
        IntersectionRecord rec = new IntersectionRecord();
        assertFalse(mesh(TRIANGLE, 0, 0).intersects(ray(0.25, 0.25, -5, 0, 0, 1), rec, scene));
        Mesh two = mesh(TRIANGLE, 1, 1);
        assertTrue(two.intersects(ray(0.25, 0.25, -5, 0, 0, 1), rec, scene));
        assertFalse(rec.frontFace);
        assertEquals(5, rec.t, 0);
        assertTrue(rec.normal.z < 0 && rec.normal.x < 0 && rec.normal.y < 0, "the smooth normal turned to the ray: " + rec.normal);
        assertTrue(two.intersects(ray(0.25, 0.25, 5, 0, 0, -1), rec, scene));
        assertTrue(rec.frontFace);
        assertTrue(rec.normal.z > 0);
    }

    /** A two-sided mesh is hit where the mesh or its reversed copy, both one-sided, is hit first. */
    @Test
    void twoSidedIsBothWindings() throws Exception {
        ObjWriter w = ObjWriter.uvSphere(7, 11, 0.2f, -0.1f, 0.3f, 1.3f);
        Mesh two = mesh(w.obj(false, 0, 0, 0), 0, 1);
        Mesh front = mesh(w.obj(false, 0, 0, 0), 0, 0);
        Mesh back = mesh(w.reversed().obj(false, 0, 0, 0), 0, 0);
        Random rnd = new Random(21);
        IntersectionRecord a = new IntersectionRecord(), f = new IntersectionRecord(), b = new IntersectionRecord();
        int backHits = 0;
        for (int i = 0; i < 5000; i++) {
            Ray r = new Ray(new Vector3d(rnd.nextGaussian() * 2, rnd.nextGaussian() * 2, rnd.nextGaussian() * 2),
                    new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()));
            boolean hf = front.intersects(r, f, scene), hb = back.intersects(r, b, scene);
            assertEquals(hf || hb, two.intersects(r, a, scene), "seed 21 ray " + i);
            if (hf || hb) {
                boolean fromBack = !hf || (hb && b.t < f.t);
                IntersectionRecord e = fromBack ? b : f;
                backHits += fromBack ? 1 : 0;
                assertEquals(e.t, a.t, 1e-12 * e.t, "seed 21 ray " + i);
                assertEquals(!fromBack, a.frontFace, "seed 21 ray " + i);
                assertEquals(e.normal.x, a.normal.x, 1e-9);
                assertEquals(e.normal.y, a.normal.y, 1e-9);
                assertEquals(e.normal.z, a.normal.z, 1e-9);
            }
        }
        assertTrue(backHits > 100, backHits + " back hits");
    }

    @Test
    void closedMeshAsCsgOperand() throws Exception {
        Mesh m = mesh(ObjWriter.uvSphere(8, 12, 0, 0, 0, 1).obj(false, 0, 0, 0), 0, 1);
        assertTrue(m.isClosed(), m.notClosedReason());
        CSG self = CSGTest.csg("intersection", m, m);
        CSG far = CSGTest.csg("difference", m, CSGTest.sphere(5, 0, 0, 1, CSGTest.material()));
        Random rnd = new Random(22);
        IntersectionRecord e = new IntersectionRecord(), a = new IntersectionRecord(), f = new IntersectionRecord();
        int hits = 0, inside = 0;
        for (int i = 0; i < 5000; i++) {
            Ray r = new Ray(new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()),
                    new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()));
            boolean h = m.intersects(r, e, scene);
            assertEquals(h, self.intersects(r, a, scene), "seed 22 ray " + i);
            assertEquals(h, far.intersects(r, f, scene), "seed 22 ray " + i);
            if (h) {
                hits++;
                inside += e.frontFace ? 0 : 1;
                for (IntersectionRecord x : List.of(a, f)) {
                    assertEquals(e.t, x.t, "seed 22 ray " + i);
                    assertEquals(e.location, x.location);
                    assertEquals(e.normal, x.normal);
                    assertEquals(e.frontFace, x.frontFace);
                    assertSame(m, x.surface);
                }
            }
        }
        assertTrue(hits > 1000 && inside > 300, hits + " hits, " + inside + " from inside");
    }

    /** The mesh's own BVH (a CSG operand's) answers exactly as the scene's BVH does. */
    @Test
    void ownBvhAgreesWithTheScenesBvh() throws Exception {
        Mesh m = mesh(ObjWriter.uvSphere(12, 20, 0.5f, 0, 0, 1).obj(true, 0.5f, 0, 0), 1, 1);
        Scene s = new Scene();
        s.camera = new Camera();
        s.width = 4;
        s.height = 3;
        s.surfaces.add(m);
        s.prepare();
        Random rnd = new Random(23);
        IntersectionRecord a = new IntersectionRecord(), b = new IntersectionRecord();
        for (int i = 0; i < 3000; i++) {
            Ray r = new Ray(new Vector3d(rnd.nextGaussian() * 2, rnd.nextGaussian() * 2, rnd.nextGaussian() * 2),
                    new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()));
            boolean h = m.intersects(r, a, s);
            assertEquals(h, s.intersect(r, b), "seed 23 ray " + i);
            if (h) {
                assertEquals(a.t, b.t);
                assertEquals(a.normal, b.normal);
                assertEquals(a.frontFace, b.frontFace);
                assertEquals(a.error, b.error);
                assertSame(m, b.surface);
            }
        }
    }
}
