package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Diffuse;
import ray.material.Material;

/**
 * CSG against cases whose answer is known without it: a degenerate operation equals a plain operand,
 * numbers worked out by hand, and a brute-force classification of random rays through random CSG trees
 * (every operand root along the ray, each interval judged by point membership).
 */
class CSGTest {

    private final Scene scene = new Scene();

    static Sphere sphere(double cx, double cy, double cz, double r, Material m) {
        Sphere s = new Sphere();
        s.center = new Vector3d(cx, cy, cz);
        s.radius = r;
        s.material = m;
        s.init();
        return s;
    }

    static CSG csg(String operation, Surface left, Surface right) {
        CSG c = new CSG();
        c.operation = operation;
        c.left = left;
        c.right = right;
        c.init();
        return c;
    }

    static Diffuse material() {
        return new Diffuse();
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    }

    private static void assertSameRecord(IntersectionRecord expected, IntersectionRecord actual, String what) {
        assertEquals(expected.t, actual.t, what + ": t");
        assertEquals(expected.location, actual.location, what + ": location");
        assertEquals(expected.normal, actual.normal, what + ": normal");
        assertEquals(expected.frontFace, actual.frontFace, what + ": frontFace");
        assertEquals(expected.error, actual.error, what + ": error");
        assertSame(expected.surface, actual.surface, what + ": surface");
    }

    // ---- worked by hand ----

    /** A ray along x through two unit spheres at x = 0 and x = 1.5 overlapping in [0.5, 1]. */
    @Test
    void operationsOnOverlappingSpheresAlongTheAxis() {
        Diffuse ma = material(), mb = material();
        Sphere a = sphere(0, 0, 0, 1, ma), b = sphere(1.5, 0, 0, 1, mb);
        IntersectionRecord rec = new IntersectionRecord();
        Ray r = ray(-5, 0, 0, 1, 0, 0);
        assertTrue(csg("union", a, b).intersects(r, rec, scene));
        assertEquals(4, rec.t, 1e-12);
        assertSame(a, rec.surface);
        assertTrue(csg("intersection", a, b).intersects(r, rec, scene));
        assertEquals(5.5, rec.t, 1e-12);                 // b's front face at x = 0.5, inside a
        assertSame(b, rec.surface);
        assertTrue(rec.frontFace);
        // a minus b from the far side: b's front face (x = 2.5) and a's back face (x = 1) change nothing;
        // leaving b at x = 0.5, inside a, enters the result
        Ray back = ray(5, 0, 0, -1, 0, 0);
        CSG d = csg("difference", a, b);
        assertTrue(d.intersects(back, rec, scene));
        assertEquals(5 - 0.5, rec.t, 1e-12);
        assertSame(b, rec.surface, "the inside of right exposed by a difference shows right's material");
        assertTrue(rec.frontFace, "entering the difference");
        assertEquals(1, rec.normal.x, 1e-12, "normal faces the ray");
    }

    @Test
    void rayStartingInsideTheResultHitsItsFarSide() {
        Sphere a = sphere(0, 0, 0, 1, material()), b = sphere(1.5, 0, 0, 1, material());
        IntersectionRecord rec = new IntersectionRecord();
        // from x = 0.75 (inside both) along +x: the union is left at x = 2.5, the intersection at x = 1
        assertTrue(csg("union", a, b).intersects(ray(0.75, 0, 0, 1, 0, 0), rec, scene));
        assertEquals(2.5 - 0.75, rec.t, 1e-12);
        assertFalse(rec.frontFace);
        assertTrue(csg("intersection", a, b).intersects(ray(0.75, 0, 0, 1, 0, 0), rec, scene));
        assertEquals(1 - 0.75, rec.t, 1e-12);
        assertFalse(rec.frontFace);
        assertEquals(-1, rec.normal.x, 1e-12);
        // from x = 0.75 along -x, a minus b: inside b, so outside the result until x = 0.5, then inside a
        assertTrue(csg("difference", a, b).intersects(ray(0.75, 0, 0, -1, 0, 0), rec, scene));
        assertEquals(0.25, rec.t, 1e-12);
        assertTrue(rec.frontFace);
    }

    @Test
    void differenceOfASphereWithItselfIsEmpty() {
        Sphere a = sphere(0, 0, 0, 1, material());
        IntersectionRecord rec = new IntersectionRecord();
        CSG d = csg("difference", a, a);
        for (double y = -0.9; y < 1; y += 0.1) {
            assertFalse(d.intersects(ray(-5, y, 0.1, 1, 0, 0), rec, scene));
            assertFalse(d.intersects(ray(0, y, 0, 1, 0.3, 0), rec, scene));
        }
    }

    @Test
    void rangeLimitsAreKept() {
        Sphere a = sphere(0, 0, 0, 1, material()), b = sphere(1.5, 0, 0, 1, material());
        CSG u = csg("union", a, b);
        IntersectionRecord rec = new IntersectionRecord();
        Ray r = ray(-5, 0, 0, 1, 0, 0);
        r.tMax = 3.9;
        assertFalse(u.intersects(r, rec, scene));
        r.tMax = 4;
        assertTrue(u.intersects(r, rec, scene));
        r.tMin = 4.5;                                    // starts inside the union: next is its far side
        r.tMax = Double.POSITIVE_INFINITY;
        assertTrue(u.intersects(r, rec, scene));
        assertEquals(7.5, rec.t, 1e-12);
    }

    @Test
    void ownMaterialNamesTheCsg() {
        Sphere a = sphere(0, 0, 0, 1, material()), b = sphere(1.5, 0, 0, 1, material());
        CSG c = new CSG();
        c.left = a;
        c.right = b;
        c.material = material();
        c.init();
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(c.intersects(ray(-5, 0, 0, 1, 0, 0), rec, scene));
        assertSame(c, rec.surface);
    }

    // ---- bad operands ----

    @Test
    void unknownOperationIsRefused() {
        Sphere a = sphere(0, 0, 0, 1, material());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> csg("xor", a, a));
        assertEquals("unknown operation 'xor' (expected union, intersection or difference)", e.getMessage());
    }

    @Test
    void operandThatIsNotClosedIsRefused() {
        Sphere a = sphere(0, 0, 0, 1, material());
        Triangle t = new Triangle();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> csg("union", a, t));
        assertTrue(e.getMessage().startsWith("right operand Triangle is not a closed surface"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> csg("union", null, a));
        assertTrue(e.getMessage().startsWith("no left operand"), e.getMessage());
    }

    // ---- degenerate operations equal a plain operand, record for record ----

    /** Random rays from inside and outside a region around the spheres, some unnormalised. */
    private static Ray randomRay(Random rnd) {
        Vector3d o = new Vector3d(rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4);
        Vector3d d = new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
        d.scale(Math.exp(rnd.nextDouble() * 4 - 2));
        return new Ray(o, d);
    }

    @Test
    void intersectionOfASphereWithItselfIsTheSphere() {
        Sphere a = sphere(0.3, -0.2, 0.1, 1.7, material());
        assertEquivalent(csg("intersection", a, a), a, 11);
        assertEquivalent(csg("union", a, a), a, 12);
    }

    @Test
    void differenceWhoseRightMissesTheLeftIsTheLeft() {
        Sphere a = sphere(0, 0, 0, 1.5, material()), far = sphere(3, 1, 0, 1, material());
        assertEquivalent(csg("difference", a, far), a, 13);
    }

    @Test
    void unionOfDisjointSpheresIsBothSpheres() {
        Sphere a = sphere(-1.5, 0, 0, 1, material()), b = sphere(1.5, 0.5, 0, 1.2, material());
        CSG u = csg("union", a, b);
        long seed = 14;
        Random rnd = new Random(seed);
        IntersectionRecord ra = new IntersectionRecord(), rb = new IntersectionRecord(), rc = new IntersectionRecord();
        for (int i = 0; i < 20_000; i++) {
            Ray r = randomRay(rnd);
            boolean ha = a.intersects(r, ra, scene), hb = b.intersects(r, rb, scene);
            boolean hc = u.intersects(r, rc, scene);
            assertEquals(ha || hb, hc, "seed " + seed + " ray " + i + ": " + r);
            if (hc) {
                assertSameRecord(!hb || (ha && ra.t <= rb.t) ? ra : rb, rc, "seed " + seed + " ray " + i + ": " + r);
            }
        }
    }

    private void assertEquivalent(CSG c, Surface plain, long seed) {
        Random rnd = new Random(seed);
        IntersectionRecord expected = new IntersectionRecord(), actual = new IntersectionRecord();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            Ray r = randomRay(rnd);
            boolean h = plain.intersects(r, expected, scene);
            assertEquals(h, c.intersects(r, actual, scene), "seed " + seed + " ray " + i + ": " + r);
            if (h) {
                hits++;
                assertSameRecord(expected, actual, "seed " + seed + " ray " + i + ": " + r);
            }
        }
        assertTrue(hits > 1000, "too few hits to mean anything: " + hits);
    }
}
