package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.surface.SphereTest.assertSentinel;
import static ray.surface.SphereTest.assertVec;
import static ray.surface.SphereTest.sentinel;

import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/** The one-sided, watertight ray/triangle test against hand-derived hits and misses. */
class TriangleTest {

    private static final double EPS = 1e-12;
    private final Scene scene = new Scene();

    static Triangle tri(Vector3d a, Vector3d b, Vector3d c) {
        Triangle t = new Triangle();
        t.v0 = new Vector3d(a);
        t.v1 = new Vector3d(b);
        t.v2 = new Vector3d(c);
        t.init();
        return t;
    }

    static Triangle tri(double... v) {
        return tri(new Vector3d(v[0], v[1], v[2]), new Vector3d(v[3], v[4], v[5]), new Vector3d(v[6], v[7], v[8]));
    }

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    }

    /** The right triangle (0,0,0), (1,0,0), (0,1,0): n = (1,0,0) x (0,1,0) = +z. */
    private static Triangle unit() {
        return tri(0, 0, 0, 1, 0, 0, 0, 1, 0);
    }

    @Test
    void frontHitHasBarycentricLocationAndWindingNormal() {
        Triangle t = unit();
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(t.intersects(ray(0.25, 0.5, 2, 0, 0, -1), rec, scene));
        assertEquals(2, rec.t, EPS);
        assertVec(0.25, 0.5, 0, rec.location, "location");
        assertVec(0, 0, 1, rec.normal, "normal");
        assertTrue(rec.frontFace);
        assertSame(t, rec.surface);
    }

    /** Slanted triangle: n = (-1,1,0) x (-1,0,1) = (1,1,1); the ray from (1,1,1) meets x+y+z=1 at t=2/3. */
    @Test
    void slantedTriangleNormalIsNormalisedCrossProduct() {
        Triangle t = tri(1, 0, 0, 0, 1, 0, 0, 0, 1);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(t.intersects(ray(1, 1, 1, -1, -1, -1), rec, scene));
        assertEquals(2.0 / 3, rec.t, EPS);
        assertVec(1.0 / 3, 1.0 / 3, 1.0 / 3, rec.location, "location");
        double k = 1 / Math.sqrt(3);
        assertVec(k, k, k, rec.normal, "normal");
    }

    @Test
    void backSideIsMissed() {
        IntersectionRecord rec = sentinel();
        assertFalse(unit().intersects(ray(0.25, 0.25, -2, 0, 0, 1), rec, scene));
        assertSentinel(rec);
    }

    /** Directions with each axis dominant, both signs, pure and mixed, plus diagonals and ties. */
    static List<Vector3d> directions() {
        double[][] d = {
            {1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
            {2, 0.3, -0.4}, {-2, 0.3, -0.4}, {0.5, 3, 0.2}, {0.5, -3, 0.2}, {-0.1, 0.4, 5}, {-0.1, 0.4, -5},
            {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {1, -1, -1}, {-1, 1, 1}, {-1, 1, -1}, {-1, -1, 1}, {-1, -1, -1},
            {1, 1, 0}, {0, -1, 1}, {-1, 0, -1}, {1e-3, -7, 2e-3},
        };
        List<Vector3d> out = new ArrayList<>();
        for (double[] v : d) {
            out.add(new Vector3d(v[0], v[1], v[2]));
        }
        return out;
    }

    /**
     * An equilateral triangle centred on c, perpendicular to d, wound so that its normal is -d (it
     * faces a ray travelling along d). With a unit vector a perpendicular to d and b = a x d, the
     * vertices c + 2a, c - a + sqrt(3) b, c - a - sqrt(3) b give (v1-v0) x (v2-v0) = 6 sqrt(3) a x b,
     * and a x (a x d) = -d.
     */
    static Triangle facing(Vector3d d, Vector3d c, boolean front) {
        Vector3d dn = new Vector3d(d);
        dn.normalize();
        Vector3d helper = Math.abs(dn.x) < 0.9 ? new Vector3d(1, 0, 0) : new Vector3d(0, 1, 0);
        Vector3d a = new Vector3d();
        a.cross(helper, dn);
        a.normalize();
        Vector3d b = new Vector3d();
        b.cross(a, dn);
        double s = Math.sqrt(3);
        Vector3d p0 = combo(c, 2, a, 0, b), p1 = combo(c, -1, a, s, b), p2 = combo(c, -1, a, -s, b);
        return front ? tri(p0, p1, p2) : tri(p0, p2, p1);
    }

    private static Vector3d combo(Vector3d c, double ka, Vector3d a, double kb, Vector3d b) {
        return new Vector3d(c.x + ka * a.x + kb * b.x, c.y + ka * a.y + kb * b.y, c.z + ka * a.z + kb * b.z);
    }

    /** Guards the winding swap in setupRay: every dominant axis and sign must keep one-sidedness right. */
    @ParameterizedTest
    @MethodSource("directions")
    void oneSidedForEveryDominantAxisAndSign(Vector3d d) {
        Vector3d c = new Vector3d(0.2, -0.1, 0.3);
        Vector3d origin = new Vector3d(c.x - 3 * d.x, c.y - 3 * d.y, c.z - 3 * d.z);
        Vector3d n = new Vector3d(d);
        n.normalize();
        n.negate();

        // the triangle facing the ray is hit at c, t = 3, normal -d
        Triangle front = facing(d, c, true);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(front.intersects(new Ray(origin, d), rec, scene), "front face along " + d);
        assertEquals(3, rec.t, 1e-12, "t along " + d);
        assertVec(c.x, c.y, c.z, rec.location, "location along " + d);
        assertVec(n.x, n.y, n.z, rec.normal, "normal along " + d);

        // the same triangle wound the other way is missed from this side ...
        Triangle back = facing(d, c, false);
        IntersectionRecord miss = sentinel();
        assertFalse(back.intersects(new Ray(origin, d), miss, scene), "back face along " + d);
        assertSentinel(miss);

        // ... and hit from the other side
        Vector3d minus = new Vector3d(d);
        minus.negate();
        Vector3d other = new Vector3d(c.x + 3 * d.x, c.y + 3 * d.y, c.z + 3 * d.z);
        assertTrue(back.intersects(new Ray(other, minus), rec, scene), "reversed winding seen along " + minus);
        assertFalse(front.intersects(new Ray(other, minus), miss, scene), "front triangle seen from behind along " + minus);
    }

    /** Oblique incidence on the same triangles: one-sidedness does not depend on the angle. */
    @ParameterizedTest
    @MethodSource("directions")
    void obliqueRaysAreOneSidedToo(Vector3d d) {
        Vector3d c = new Vector3d(-1, 2, 0.5);
        Triangle front = facing(d, c, true), back = facing(d, c, false);
        Vector3d edge = new Vector3d(front.v0);
        edge.sub(c);                                  // 2a: in the plane
        Vector3d dn = new Vector3d(d);
        dn.normalize();
        Vector3d tilted = new Vector3d(dn.x + 0.4 * edge.x, dn.y + 0.4 * edge.y, dn.z + 0.4 * edge.z);
        Vector3d origin = new Vector3d(c.x - 3 * tilted.x, c.y - 3 * tilted.y, c.z - 3 * tilted.z);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(front.intersects(new Ray(origin, tilted), rec, scene), "front along " + tilted);
        assertEquals(3, rec.t, 1e-12);
        assertVec(c.x, c.y, c.z, rec.location, "location");
        assertFalse(back.intersects(new Ray(origin, tilted), sentinel(), scene), "back along " + tilted);
    }

    @Test
    void rayInTrianglePlaneMisses() {
        IntersectionRecord rec = sentinel();
        // axis-aligned: along x through the inside of the triangle, in z = 0
        assertFalse(unit().intersects(ray(-1, 0.25, 0, 1, 0, 0), rec, scene));
        assertFalse(unit().intersects(ray(2, 0.25, 0, -1, 0, 0), rec, scene));
        // slanted: (1,-1,0) lies in x+y+z=1, and the ray crosses the inside at (0.25, 0.25, 0.5)
        assertFalse(tri(1, 0, 0, 0, 1, 0, 0, 0, 1).intersects(ray(-0.5, 1, 0.5, 1, -1, 0), rec, scene));
        assertSentinel(rec);
    }

    @Test
    void raysOutsideEachEdgeMiss() {
        Triangle t = unit();
        IntersectionRecord rec = sentinel();
        assertFalse(t.intersects(ray(0.6, 0.6, 1, 0, 0, -1), rec, scene), "beyond the hypotenuse");
        assertFalse(t.intersects(ray(-0.1, 0.5, 1, 0, 0, -1), rec, scene), "left of x = 0");
        assertFalse(t.intersects(ray(0.5, -0.1, 1, 0, 0, -1), rec, scene), "below y = 0");
        assertFalse(t.intersects(ray(1.5, 1.5, 1, 0, 0, -1), rec, scene), "far away");
        assertSentinel(rec);
    }

    @Test
    void hitOutsideTRangeIsExcluded() {
        Triangle t = unit();
        Ray r = ray(0.25, 0.25, 1, 0, 0, -1);   // hits at exactly t = 1
        IntersectionRecord rec = sentinel();
        r.tMax = 0.99;
        assertFalse(t.intersects(r, rec, scene), "beyond tMax");
        r.tMax = Double.POSITIVE_INFINITY;
        r.tMin = 1.01;
        assertFalse(t.intersects(r, rec, scene), "before tMin");
        assertSentinel(rec);
        r.tMin = 1;
        r.tMax = 1;       // the closed span [1, 1] contains the hit
        assertTrue(t.intersects(r, rec, scene), "t = tMin = tMax");
        assertEquals(1, rec.t);
    }

    @Test
    void triangleBehindOriginIsMissed() {
        IntersectionRecord rec = sentinel();
        assertFalse(unit().intersects(ray(0.25, 0.25, 1, 0, 0, 1), rec, scene));
        assertSentinel(rec);
    }

    @Test
    void unnormalisedDirectionScalesTOnly() {
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(unit().intersects(ray(0.25, 0.5, 2, 0, 0, -8), rec, scene));
        assertEquals(0.25, rec.t, EPS);
        assertVec(0.25, 0.5, 0, rec.location, "location");
    }

    /** Zero area in three ways: all vertices equal, a repeated vertex, three collinear vertices. */
    @Test
    void degenerateTrianglesAreNeverHit() {
        Triangle[] bad = {
            tri(1, 1, 1, 1, 1, 1, 1, 1, 1),
            tri(0, 0, 0, 0, 0, 0, 0, 1, 0),
            tri(0, 0, 0, 1, 1, 1, 2, 2, 2),
            tri(0, 0, 0, 1, 0, 0, 3, 0, 0),
        };
        for (Triangle t : bad) {
            assertTrue(t.isDegenerate(), t.toString());
            for (Vector3d d : directions()) {
                for (Vector3d target : new Vector3d[] {t.v0, t.v1, t.v2, mid(t.v0, t.v2)}) {
                    Vector3d o = new Vector3d(target.x - 2 * d.x, target.y - 2 * d.y, target.z - 2 * d.z);
                    IntersectionRecord rec = sentinel();
                    assertFalse(t.intersects(new Ray(o, d), rec, scene), t + " along " + d);
                    assertSentinel(rec);
                }
            }
        }
        assertFalse(unit().isDegenerate());
    }

    private static Vector3d mid(Vector3d a, Vector3d b) {
        return new Vector3d((a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2);
    }

    @Test
    void boundsEncloseTheVertices() {
        Aabb b = tri(1, -2, 3, -4, 5, 0, 2, 2, 2).bounds();
        assertEquals(-4, b.minX);
        assertEquals(-2, b.minY);
        assertEquals(0, b.minZ);
        assertEquals(2, b.maxX);
        assertEquals(5, b.maxY);
        assertEquals(3, b.maxZ);
    }
}
