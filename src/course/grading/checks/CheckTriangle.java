/** Triangle.intersects (method 2), alone. The front is the side (v1 - v0) x (v2 - v0) points to. */
public final class CheckTriangle {

    static final String M = "Triangle.intersects";
    static final String TRI = "the triangle (0, 0, 0), (1, 0, 0), (0, 1, 0) (front towards +z)";

    static Triangle tri() {
        Triangle t = new Triangle();
        t.v0 = GraderSupport.v(0, 0, 0);
        t.v1 = GraderSupport.v(1, 0, 0);
        t.v2 = GraderSupport.v(0, 1, 0);
        return t;
    }

    public static void hitFromFront() {
        Triangle t = tri();
        IntersectionRecord rec = new IntersectionRecord();
        String situation = "a ray from (0.25, 0.25, 2) towards -z and " + TRI;
        boolean hit = GraderSupport.call(M, situation, () -> t.intersects(new Ray(GraderSupport.v(0.25, 0.25, 2), GraderSupport.v(0, 0, -1)), rec, null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit at t = 2; yours returned false");
        GraderSupport.expectNumber(M, situation, "record.t", rec.t, 2, 1e-6);
        GraderSupport.expectVector(M, situation, "record.location", rec.location, GraderSupport.v(0.25, 0.25, 0), 1e-6);
        GraderSupport.expectVector(M, situation, "record.normal (unit, (v1 - v0) x (v2 - v0))", rec.normal, GraderSupport.v(0, 0, 1), 1e-6);
        GraderSupport.expect(rec.surface == t, M + ": " + situation + ": record.surface must be the triangle itself; yours is " + rec.surface);
    }

    public static void obliqueHit() {
        Triangle t = new Triangle();
        t.v0 = GraderSupport.v(0, 0, -2);
        t.v1 = GraderSupport.v(4, 0, -2);
        t.v2 = GraderSupport.v(0, 4, -2);
        IntersectionRecord rec = new IntersectionRecord();
        String situation = "a ray from (0, 0, 2) along (1, 1, -2) and the triangle (0, 0, -2), (4, 0, -2), (0, 4, -2)";
        boolean hit = GraderSupport.call(M, situation, () -> t.intersects(new Ray(GraderSupport.v(0, 0, 2), GraderSupport.v(1, 1, -2)), rec, null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit at t = 2; yours returned false");
        GraderSupport.expectNumber(M, situation, "record.t", rec.t, 2, 1e-6);
        GraderSupport.expectVector(M, situation, "record.location", rec.location, GraderSupport.v(2, 2, -2), 1e-6);
    }

    /** A miss proves something only from a method that can hit: else "returns false" would pass. */
    static void mustHitFirst(String what) {
        Triangle t = tri();
        String situation = "a ray from (0.25, 0.25, 2) straight at the front of " + TRI;
        boolean hit = GraderSupport.call(M, situation, () -> t.intersects(new Ray(GraderSupport.v(0.25, 0.25, 2), GraderSupport.v(0, 0, -1)), new IntersectionRecord(), null));
        GraderSupport.expect(hit, M + ": " + situation + " must hit; yours returned false, so its " + what + " prove nothing yet");
    }

    public static void backIsInvisible() {
        mustHitFirst("misses from behind");
        Triangle t = tri();
        IntersectionRecord rec = new IntersectionRecord();
        String situation = "a ray from (0.25, 0.25, -2) towards +z, arriving at the BACK of " + TRI;
        boolean hit = GraderSupport.call(M, situation, () -> t.intersects(new Ray(GraderSupport.v(0.25, 0.25, -2), GraderSupport.v(0, 0, 1)), rec, null));
        GraderSupport.expect(!hit, M + ": " + situation + " must miss (triangles are one-sided: seen from behind they are "
                + "invisible); yours returned true");
    }

    public static void missesOutsideAndBehind() {
        mustHitFirst("misses");
        Triangle t = tri();
        IntersectionRecord rec = new IntersectionRecord();
        rec.t = 123;
        for (double[] p : new double[][] {{0.6, 0.6}, {-0.1, 0.5}, {0.5, -0.1}}) {
            String situation = "a ray from (" + p[0] + ", " + p[1] + ", 2) towards -z, outside " + TRI;
            boolean hit = GraderSupport.call(M, situation, () -> t.intersects(new Ray(GraderSupport.v(p[0], p[1], 2), GraderSupport.v(0, 0, -1)), rec, null));
            GraderSupport.expect(!hit, M + ": " + situation + " must miss; yours returned true (check beta >= 0, gamma >= 0, "
                    + "beta + gamma <= 1)");
        }
        String behind = "a ray from (0.25, 0.25, -2) towards -z: " + TRI + " is behind its origin";
        boolean hit = GraderSupport.call(M, behind, () -> t.intersects(new Ray(GraderSupport.v(0.25, 0.25, -2), GraderSupport.v(0, 0, -1)), rec, null));
        GraderSupport.expect(!hit, M + ": " + behind + " must miss; yours returned true (a negative t is not a hit)");
        Ray r = new Ray(GraderSupport.v(0.25, 0.25, 2), GraderSupport.v(0, 0, -1));
        r.tMax = 1.5;
        String span = "a ray from (0.25, 0.25, 2) towards -z with tMax = 1.5 and " + TRI + " (at t = 2)";
        hit = GraderSupport.call(M, span, () -> t.intersects(r, rec, null));
        GraderSupport.expect(!hit, M + ": " + span + " must miss; yours returned true (only t in [tMin, tMax] counts)");
        GraderSupport.expect(rec.t == 123, M + ": on a miss the record must be left alone; yours changed record.t to " + rec.t);
    }
}
