import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

@ExtendWith(NamesTheMethod.class)
@Order(1)
@Tag("method:Sphere.intersects")
@DisplayName("1. Sphere.intersects")
class SphereIntersectsTest {

    static final String M = "Sphere.intersects";

    static Sphere sphere(double x, double y, double z, double r) {
        Sphere s = new Sphere();
        s.center = new Vector3d(x, y, z);
        s.radius = r;
        return s;
    }

    /** The hit the miss tests build on: a method that always says false fails here, not in the miss tests. */
    static void requireAHit() {
        Expect.that(sphere(0, 0, 0, 1).intersects(Expect.ray(0, 0, 5, 0, 0, -1), new IntersectionRecord(), Doubles.scene()), M,
                "(first, the hit this test builds on) a ray from (0, 0, 5) towards -z must hit the unit sphere", "returned false");
    }

    @Test
    @DisplayName("a ray from (0, 0, 5) towards -z hits the unit sphere at t = 4")
    void hitFromOutside() {
        Sphere s = sphere(0, 0, 0, 1);
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = s.intersects(Expect.ray(0, 0, 5, 0, 0, -1), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from (0, 0, 5) towards -z must hit the unit sphere at t = 4", "returned false");
        Expect.near(4, rec.t, M, "record.t for the ray from (0, 0, 5) towards -z and the unit sphere");
        Expect.near(Expect.v(0, 0, 1), rec.location, M, "record.location for that hit");
        Expect.near(Expect.v(0, 0, 1), rec.normal, M, "record.normal for that hit (unit length, pointing out of the sphere)");
        Expect.that(rec.surface == s, M, "record.surface must be the sphere that was hit", "is " + rec.surface);
    }

    @Test
    @DisplayName("t counts in units of the ray's direction, which need not have unit length")
    void directionNotUnitLength() {
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = sphere(0, 0, 0, 1).intersects(Expect.ray(0, 0, 5, 0, 0, -2), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from (0, 0, 5) along (0, 0, -2) must hit the unit sphere", "returned false");
        Expect.near(2, rec.t, M, "record.t for the ray from (0, 0, 5) along (0, 0, -2) (the hit point is origin + t * direction)");
        Expect.near(Expect.v(0, 0, 1), rec.location, M, "record.location for that hit");
    }

    @Test
    @DisplayName("a sphere away from the origin, with radius 2")
    void offCentre() {
        Sphere s = sphere(1, 2, -3, 2);
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = s.intersects(Expect.ray(1, 2, 5, 0, 0, -1), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from (1, 2, 5) towards -z must hit the sphere of radius 2 around (1, 2, -3) at t = 6", "returned false");
        Expect.near(6, rec.t, M, "record.t for the sphere of radius 2 around (1, 2, -3)");
        Expect.near(Expect.v(1, 2, -1), rec.location, M, "record.location for that hit");
        Expect.near(Expect.v(0, 0, 1), rec.normal, M, "record.normal for that hit (unit length: divide by the radius)");
    }

    @Test
    @DisplayName("an oblique hit: the normal is (p - c) / R")
    void obliqueNormal() {
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = sphere(0, 0, 0, 2).intersects(Expect.ray(1, 0, 5, 0, 0, -1), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from (1, 0, 5) towards -z must hit the sphere of radius 2 around the origin", "returned false");
        double z = Math.sqrt(3);
        Expect.near(5 - z, rec.t, M, "record.t for the ray from (1, 0, 5) towards -z and the sphere of radius 2");
        Expect.near(Expect.v(0.5, 0, z / 2), rec.normal, M, "record.normal at (1, 0, sqrt 3)");
    }

    @Test
    @DisplayName("a miss returns false and leaves the record alone")
    void miss() {
        requireAHit();
        IntersectionRecord rec = new IntersectionRecord();
        rec.t = 123;
        boolean hit = sphere(0, 0, 0, 1).intersects(Expect.ray(0, 2, 5, 0, 0, -1), rec, Doubles.scene());
        Expect.that(!hit, M, "a ray from (0, 2, 5) towards -z passes above the unit sphere and must miss it", "returned true");
        Expect.that(rec.t == 123 && rec.surface == null, M, "on a miss the record must be left as it was",
                "changed it to t = " + rec.t + ", surface " + rec.surface);
    }

    @Test
    @DisplayName("a sphere behind the ray (behind the camera) is not hit")
    void behindTheRay() {
        requireAHit();
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = sphere(0, 0, 0, 1).intersects(Expect.ray(0, 0, 5, 0, 0, 1), rec, Doubles.scene());
        Expect.that(!hit, M, "a ray from (0, 0, 5) towards +z must miss the unit sphere behind it (both roots are negative: t = -4, -6)",
                "returned true with t = " + rec.t);
    }

    @Test
    @DisplayName("a ray starting inside hits the far side, normal facing the ray")
    void fromInside() {
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = sphere(0, 0, 0, 1).intersects(Expect.ray(0, 0, 0, 0, 0, -1), rec, Doubles.scene());
        Expect.that(hit, M, "a ray from the centre (0, 0, 0) towards -z must hit the unit sphere from inside at t = 1", "returned false");
        Expect.near(1, rec.t, M, "record.t for the ray from the centre (the smaller root, -1, is behind the ray: take the larger one)");
        Expect.near(Expect.v(0, 0, 1), rec.normal, M, "record.normal seen from inside (turned to face the ray, so an inside is lit)");
    }

    @Test
    @DisplayName("only hits within [tMin, tMax] count")
    void span() {
        IntersectionRecord rec = new IntersectionRecord();
        Ray r = Expect.ray(0, 0, 5, 0, 0, -1);
        r.tMax = 3;
        Expect.that(!sphere(0, 0, 0, 1).intersects(r, rec, Doubles.scene()), M,
                "with ray.tMax = 3 the hits at t = 4 and 6 are out of the span: it must miss", "returned true");
        r = Expect.ray(0, 0, 5, 0, 0, -1);
        r.tMin = 4.5;
        boolean hit = sphere(0, 0, 0, 1).intersects(r, rec, Doubles.scene());
        Expect.that(hit, M, "with ray.tMin = 4.5 the near hit (t = 4) is out of the span and the far one (t = 6) counts", "returned false");
        Expect.near(6, rec.t, M, "record.t with ray.tMin = 4.5");
    }

    @Test
    @DisplayName("a ray leaving the surface does not hit it again at t = 0 (no shadow acne)")
    void leavingTheSurface() {
        requireAHit();
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = sphere(0, 0, 0, 1).intersects(Expect.ray(0, 0, 1, 0, 0, 1), rec, Doubles.scene());
        Expect.that(!hit, M, "a ray from the surface point (0, 0, 1) outwards must not hit the sphere again (its roots are t = 0"
                + " and -2, both below ray.tMin = Ray.EPSILON)", "returned true with t = " + rec.t);
    }

    @Test
    @DisplayName("two spheres into each other: each is hit where it is")
    void intersectingSpheres() {
        Sphere a = sphere(-0.5, 0, 0, 1), b = sphere(0.5, 0, 0, 1);
        IntersectionRecord ra = new IntersectionRecord(), rb = new IntersectionRecord();
        Ray r = Expect.ray(0, 0, 5, 0, 0, -1);
        Expect.that(a.intersects(r, ra, Doubles.scene()) && b.intersects(r, rb, Doubles.scene()), M,
                "a ray from (0, 0, 5) towards -z must hit both of two overlapping unit spheres at x = -0.5 and x = 0.5", "missed one");
        Expect.near(5 - Math.sqrt(0.75), ra.t, M, "record.t for the sphere around (-0.5, 0, 0)");
        Expect.that(ra.surface == a, M, "record.surface must be the sphere that was hit", "is " + ra.surface);
        Expect.near(Expect.v(0.5, 0, Math.sqrt(0.75)), ra.normal, M, "record.normal of the sphere around (-0.5, 0, 0)");
    }
}
