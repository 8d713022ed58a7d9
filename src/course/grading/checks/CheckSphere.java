import javax.vecmath.Vector3d;

/** Sphere.intersects (method 1), alone: only Ray and IntersectionRecord besides the sphere. */
public final class CheckSphere {

    static final String M = "Sphere.intersects";

    static Sphere sphere(Vector3d c, double r) {
        Sphere s = new Sphere();
        s.center = c;
        s.radius = r;
        return s;
    }

    static Ray ray(Vector3d o, Vector3d d) {
        return new Ray(o, d);
    }

    static String unit = "the unit sphere at the origin";

    public static void hitInFront() {
        Sphere s = sphere(GraderSupport.v(0, 0, 0), 1);
        IntersectionRecord rec = new IntersectionRecord();
        String situation = "a ray from (0, 0, 5) towards -z and " + unit;
        boolean hit = GraderSupport.call(M, situation, () -> s.intersects(ray(GraderSupport.v(0, 0, 5), GraderSupport.v(0, 0, -1)), rec, null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit at t = 4; yours returned false");
        GraderSupport.expectNumber(M, situation, "record.t", rec.t, 4, 1e-6);
        GraderSupport.expectVector(M, situation, "record.location", rec.location, GraderSupport.v(0, 0, 1), 1e-6);
        GraderSupport.expectVector(M, situation, "record.normal", rec.normal, GraderSupport.v(0, 0, 1), 1e-6);
        GraderSupport.expect(rec.surface == s, M + ": " + situation + ": record.surface must be the sphere itself; yours is " + rec.surface);
    }

    public static void offCentreAndLongDirection() {
        Sphere s = sphere(GraderSupport.v(1, 2, -3), 2);
        IntersectionRecord rec = new IntersectionRecord();
        String situation = "a ray from (1, 2, 7) along (0, 0, -2) (not unit length) and the sphere of radius 2 at (1, 2, -3)";
        boolean hit = GraderSupport.call(M, situation, () -> s.intersects(ray(GraderSupport.v(1, 2, 7), GraderSupport.v(0, 0, -2)), rec, null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit at t = 4; yours returned false");
        GraderSupport.expectNumber(M, situation, "record.t", rec.t, 4, 1e-6);
        GraderSupport.expectVector(M, situation, "record.location", rec.location, GraderSupport.v(1, 2, -1), 1e-6);
        GraderSupport.expectVector(M, situation, "record.normal (unit length)", rec.normal, GraderSupport.v(0, 0, 1), 1e-6);
    }

    /** A miss proves something only from a method that can hit: else "returns false" would pass. */
    static void mustHitFirst(String what) {
        Sphere s = sphere(GraderSupport.v(0, 0, 0), 1);
        String situation = "a ray from (0, 0, 5) straight at " + unit;
        boolean hit = GraderSupport.call(M, situation, () -> s.intersects(ray(GraderSupport.v(0, 0, 5), GraderSupport.v(0, 0, -1)), new IntersectionRecord(), null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit; yours returned false, so its " + what + " prove nothing yet");
    }

    public static void missesBesideAndBehind() {
        mustHitFirst("misses");
        Sphere s = sphere(GraderSupport.v(0, 0, 0), 1);
        IntersectionRecord rec = new IntersectionRecord();
        rec.t = 123;
        String beside = "a ray from (0, 2, 5) towards -z passing beside " + unit;
        boolean hit = GraderSupport.call(M, beside, () -> s.intersects(ray(GraderSupport.v(0, 2, 5), GraderSupport.v(0, 0, -1)), rec, null));
        GraderSupport.expect(!hit, M + ": " + beside + " must miss; yours returned true");
        String behind = "a ray from (0, 0, 5) towards +z, away from " + unit + " (the sphere is behind it)";
        hit = GraderSupport.call(M, behind, () -> s.intersects(ray(GraderSupport.v(0, 0, 5), GraderSupport.v(0, 0, 1)), rec, null));
        GraderSupport.expect(!hit, M + ": " + behind + " must miss; yours returned true (a negative t is not a hit)");
        GraderSupport.expect(rec.t == 123, M + ": on a miss the record must be left alone; yours changed record.t to " + rec.t);
    }

    public static void fromInside() {
        Sphere s = sphere(GraderSupport.v(0, 0, 0), 1);
        IntersectionRecord rec = new IntersectionRecord();
        String situation = "a ray from the centre of " + unit + " towards +x (it starts inside)";
        boolean hit = GraderSupport.call(M, situation, () -> s.intersects(ray(GraderSupport.v(0, 0, 0), GraderSupport.v(1, 0, 0)), rec, null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit the far side at t = 1; yours returned false");
        GraderSupport.expectNumber(M, situation, "record.t (the larger root: the smaller is behind the origin)", rec.t, 1, 1e-6);
        GraderSupport.expectVector(M, situation, "record.normal (facing the ray)", rec.normal, GraderSupport.v(-1, 0, 0), 1e-6);
    }

    public static void respectsSpan() {
        mustHitFirst("misses outside [tMin, tMax]");
        Sphere s = sphere(GraderSupport.v(0, 0, 0), 1);
        IntersectionRecord rec = new IntersectionRecord();
        Ray r = ray(GraderSupport.v(0, 0, 5), GraderSupport.v(0, 0, -1));
        r.tMax = 3.5;
        String situation = "a ray from (0, 0, 5) towards -z with tMax = 3.5 and " + unit + " (first hit at t = 4)";
        boolean hit = GraderSupport.call(M, situation, () -> s.intersects(r, rec, null));
        GraderSupport.expect(!hit, M + ": " + situation + " must miss; yours returned true (only t in [tMin, tMax] counts)");
        Ray r2 = ray(GraderSupport.v(0, 0, 5), GraderSupport.v(0, 0, -1));
        r2.tMin = 4.5;
        IntersectionRecord rec2 = new IntersectionRecord();
        String situation2 = "a ray from (0, 0, 5) towards -z with tMin = 4.5 and " + unit;
        hit = GraderSupport.call(M, situation2, () -> s.intersects(r2, rec2, null));
        GraderSupport.expect(hit, M + ": " + situation2 + " must hit the far side at t = 6; yours returned false");
        GraderSupport.expectNumber(M, situation2, "record.t", rec2.t, 6, 1e-6);
    }
}
