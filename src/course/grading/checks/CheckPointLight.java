import javax.vecmath.Vector3d;

/** PointLight.getIntensity (method 5), alone: the blockers are the grader's own surfaces. */
public final class CheckPointLight {

    static final String M = "PointLight.getIntensity";

    /** A blocker at a fixed parameter t along whatever ray asks (a hit when t is in the ray's span). */
    static final class BlockAt extends Surface {
        final double fraction;
        int asked;

        BlockAt(double fraction) {
            this.fraction = fraction;
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            asked++;
            // the blocker sits `fraction` of the way from the ray's origin to the light (t in units of the light's distance)
            double len = ray.direction.length();
            double t = fraction * DIST / len;
            if (t < ray.tMin || t > ray.tMax) {
                return false;
            }
            record.t = t;
            record.location.set(ray.evaluate(t));
            record.normal.set(0, 0, 1);
            record.surface = this;
            return true;
        }
    }

    static final double DIST = 2;

    static PointLight light() {
        PointLight l = new PointLight();
        l.position = GraderSupport.v(0, 0, 2);
        l.intensity = GraderSupport.v(8, 4, 2);
        return l;
    }

    static IntersectionRecord at() {
        IntersectionRecord r = new IntersectionRecord();
        r.location = GraderSupport.v(0, 0, 0);
        r.normal = GraderSupport.v(0, 0, 1);
        r.t = 1;
        return r;
    }

    public static void inverseSquare() {
        PointLight l = light();
        Scene s = new Scene();
        String situation = "a light of intensity (8, 4, 2) at distance 2, nothing in between";
        Vector3d got = GraderSupport.call(M, situation, () -> l.getIntensity(at(), s));
        GraderSupport.expectVector(M, situation, "the light arriving (I / r^2)", got, GraderSupport.v(2, 1, 0.5), 1e-6);
        GraderSupport.expectVector(M, situation + " (afterwards)", "the light's own intensity field (must not change)", l.intensity,
                GraderSupport.v(8, 4, 2), 0);
    }

    public static void shadowed() {
        PointLight l = light();
        Scene s = new Scene();
        BlockAt b = new BlockAt(0.5);
        s.surfaces.add(b);
        String situation = "a light at distance 2 and a surface halfway between the point and the light";
        Vector3d got = GraderSupport.call(M, situation, () -> l.getIntensity(at(), s));
        if (b.asked == 0) {
            throw GraderSupport.fail(M + ": " + situation + ": the point is in shadow, so the light must be black; yours never asked "
                    + "the scene's surfaces (send a shadow ray towards the light)");
        }
        GraderSupport.expectVector(M, situation, "the light arriving (in shadow)", got, GraderSupport.v(0, 0, 0), 1e-9);
    }

    public static void blockerBeyondLight() {
        PointLight l = light();
        Scene s = new Scene();
        s.surfaces.add(new BlockAt(1.5));
        String situation = "a light at distance 2 and a surface BEYOND the light (at 1.5 times its distance)";
        Vector3d got = GraderSupport.call(M, situation, () -> l.getIntensity(at(), s));
        GraderSupport.expectVector(M, situation, "the light arriving (nothing beyond the light casts a shadow)", got,
                GraderSupport.v(2, 1, 0.5), 1e-6);
    }

    public static void noSelfShadow() {
        PointLight l = light();
        Scene s = new Scene();
        s.surfaces.add(new BlockAt(1e-9));
        String situation = "a light at distance 2 and a surface touching the point itself (t = 1e-9, below Ray.EPSILON)";
        Vector3d got = GraderSupport.call(M, situation, () -> l.getIntensity(at(), s));
        GraderSupport.expectVector(M, situation, "the light arriving (the point's own surface must not shadow it: shadow rays start "
                + "at tMin = Ray.EPSILON)", got, GraderSupport.v(2, 1, 0.5), 1e-6);
    }
}
