import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

@ExtendWith(NamesTheMethod.class)
@Order(2)
@Tag("method:Triangle.intersects")
@DisplayName("2. Triangle.intersects")
class TriangleIntersectsTest {

    static final String M = "Triangle.intersects";

    static Triangle triangle(Vector3d a, Vector3d b, Vector3d c) {
        Triangle t = new Triangle();
        t.v0 = a;
        t.v1 = b;
        t.v2 = c;
        return t;
    }

    /** (0,0,0), (1,0,0), (0,1,0): its front faces +z. */
    static Triangle unit() {
        return triangle(Expect.v(0, 0, 0), Expect.v(1, 0, 0), Expect.v(0, 1, 0));
    }

    /** The hit the miss tests build on: a method that always says false fails here, not in the miss tests. */
    static void requireAHit() {
        Expect.that(unit().intersects(Expect.ray(0.25, 0.25, 1, 0, 0, -1), new IntersectionRecord(), Doubles.scene()), M,
                "(first, the hit this test builds on) a ray from (0.25, 0.25, 1) towards -z must hit the triangle (0,0,0) (1,0,0) (0,1,0)",
                "returned false");
    }

    @Test
    @DisplayName("a ray from the front hits, filling t, location, normal and surface")
    void frontHit() {
        Triangle tri = unit();
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = tri.intersects(Expect.ray(0.25, 0.25, 1, 0, 0, -1), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from (0.25, 0.25, 1) towards -z must hit the triangle (0,0,0) (1,0,0) (0,1,0) at t = 1", "returned false");
        Expect.near(1, rec.t, M, "record.t for that hit");
        Expect.near(Expect.v(0.25, 0.25, 0), rec.location, M, "record.location for that hit");
        Expect.near(Expect.v(0, 0, 1), rec.normal, M, "record.normal: (v1 - v0) x (v2 - v0) made unit length");
        Expect.that(rec.surface == tri, M, "record.surface must be the triangle that was hit", "is " + rec.surface);
    }

    @Test
    @DisplayName("the back of a triangle is not hit (one-sided)")
    void backMisses() {
        requireAHit();
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = unit().intersects(Expect.ray(0.25, 0.25, -1, 0, 0, 1), rec, Doubles.scene());
        Expect.that(!hit, M, "a ray from (0.25, 0.25, -1) towards +z arrives at the back of the triangle (its normal is +z)"
                + " and must miss it: triangles are one-sided", "returned true");
    }

    @Test
    @DisplayName("points outside the triangle are missed")
    void outside() {
        requireAHit();
        double[][] points = {{0.75, 0.75}, {-0.1, 0.5}, {0.5, -0.1}, {1.01, 0}};
        for (double[] p : points) {
            IntersectionRecord rec = new IntersectionRecord();
            rec.t = 123;
            boolean hit = unit().intersects(Expect.ray(p[0], p[1], 1, 0, 0, -1), rec, Doubles.scene());
            Expect.that(!hit, M, "a ray towards (" + p[0] + ", " + p[1] + ", 0), outside the triangle (0,0,0) (1,0,0) (0,1,0),"
                    + " must miss it (beta >= 0, gamma >= 0, beta + gamma <= 1 for points inside)", "returned true");
            Expect.that(rec.t == 123, M, "on a miss the record must be left as it was", "changed record.t to " + rec.t);
        }
    }

    @Test
    @DisplayName("a triangle behind the ray (behind the camera) is not hit")
    void behindTheRay() {
        requireAHit();
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = unit().intersects(Expect.ray(0.25, 0.25, -1, 0, 0, -1), rec, Doubles.scene());
        Expect.that(!hit, M, "a ray from (0.25, 0.25, -1) towards -z has the triangle behind it (t = -1) and must miss it",
                "returned true with t = " + rec.t);
    }

    @Test
    @DisplayName("only hits within [tMin, tMax] count")
    void span() {
        requireAHit();
        Ray r = Expect.ray(0.25, 0.25, 1, 0, 0, -1);
        r.tMax = 0.5;
        Expect.that(!unit().intersects(r, new IntersectionRecord(), Doubles.scene()), M,
                "with ray.tMax = 0.5 the hit at t = 1 is out of the span: it must miss", "returned true");
        Ray leaving = Expect.ray(0.25, 0.25, 0, 0, 0, -1);
        Expect.that(!unit().intersects(leaving, new IntersectionRecord(), Doubles.scene()), M,
                "a ray starting on the triangle (t = 0 is below ray.tMin = Ray.EPSILON) must miss it", "returned true");
    }

    @Test
    @DisplayName("a ray in the triangle's plane misses; a zero-area triangle is never hit")
    void degenerate() {
        requireAHit();
        Expect.that(!unit().intersects(Expect.ray(-1, 0.25, 0, 1, 0, 0), new IntersectionRecord(), Doubles.scene()), M,
                "a ray lying in the triangle's plane must miss it", "returned true");
        Triangle flat = triangle(Expect.v(0, 0, 0), Expect.v(1, 1, 0), Expect.v(2, 2, 0));
        Expect.that(!flat.intersects(Expect.ray(1, 1, 1, 0, 0, -1), new IntersectionRecord(), Doubles.scene()), M,
                "a triangle with its corners on one line has no area and must never be hit", "returned true");
    }

    @Test
    @DisplayName("a tilted triangle, a ray whose direction is not unit length")
    void tilted() {
        Triangle tri = triangle(Expect.v(0, 0, -2), Expect.v(2, 0, -2), Expect.v(0, 2, -4));
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = tri.intersects(Expect.ray(0.5, 0.5, 0, 0, 0, -2), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from (0.5, 0.5, 0) along (0, 0, -2) must hit the triangle (0,0,-2) (2,0,-2) (0,2,-4)", "returned false");
        Expect.near(1.25, rec.t, M, "record.t (the hit is at (0.5, 0.5, -2.5), t = 1.25 for a direction of length 2)");
        Expect.near(Expect.v(0.5, 0.5, -2.5), rec.location, M, "record.location");
        Expect.near(Expect.unit(0, 1, 1), rec.normal, M, "record.normal: (v1 - v0) x (v2 - v0) made unit length");
    }
}
