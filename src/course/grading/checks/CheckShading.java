import javax.vecmath.Vector3d;

/** Diffuse.shade (6), BlinnPhong.shade (7) and GlazedMaterial.shade (8), each alone (the grader's own lights). */
public final class CheckShading {

    static final String D = "Diffuse.shade";
    static final String B = "BlinnPhong.shade";
    static final String G = "GlazedMaterial.shade";

    /** A light that arrives with a fixed intensity from a fixed direction. */
    static final class FixedLight extends Light {
        final Vector3d intensity, direction;

        FixedLight(Vector3d intensity, Vector3d direction) {
            this.intensity = intensity;
            this.direction = new Vector3d(direction);
            this.direction.normalize();
        }

        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return new Vector3d(intensity);
        }

        @Override
        public Vector3d getDirection(IntersectionRecord record) {
            return new Vector3d(direction);
        }
    }

    static IntersectionRecord up() {
        IntersectionRecord r = new IntersectionRecord();
        r.location = GraderSupport.v(0, 0, 0);
        r.normal = GraderSupport.v(0, 0, 1);
        r.t = 1;
        return r;
    }

    static Scene scene(Light... lights) {
        Scene s = new Scene();
        s.ambientLight = GraderSupport.v(0.5, 0.5, 0.5);
        for (Light l : lights) {
            s.lights.add(l);
        }
        return s;
    }

    public static void diffuseLambert() {
        Diffuse d = new Diffuse();
        d.ambientColor = GraderSupport.v(0.2, 0.4, 0);
        d.diffuseColor = GraderSupport.v(0.5, 0.25, 1);
        Scene s = scene(new FixedLight(GraderSupport.v(2, 2, 1), GraderSupport.v(0, 0.6, 0.8)));
        String situation = "k_a (0.2, 0.4, 0), I_a (0.5, 0.5, 0.5), k_d (0.5, 0.25, 1), one light of (2, 2, 1) with n.l = 0.8";
        Vector3d got = GraderSupport.call(D, situation, () -> d.shade(new Ray(GraderSupport.v(0, 0, 1), GraderSupport.v(0, 0, -1)), up(), s));
        GraderSupport.expectVector(D, situation, "L = k_a I_a + k_d I (n.l)", got, GraderSupport.v(0.1 + 0.8, 0.2 + 0.4, 0.8), 1e-6);
    }

    public static void diffuseLightsAddAndBackIgnored() {
        Diffuse d = new Diffuse();
        d.ambientColor = GraderSupport.v(0, 0, 0);
        d.diffuseColor = GraderSupport.v(1, 1, 1);
        Scene s = scene(new FixedLight(GraderSupport.v(1, 0, 0), GraderSupport.v(0, 0, 1)),
                new FixedLight(GraderSupport.v(0, 1, 0), GraderSupport.v(0, 0.6, 0.8)),
                new FixedLight(GraderSupport.v(5, 5, 5), GraderSupport.v(0, 0, -1)));
        String situation = "k_d (1, 1, 1), a red light overhead, a green one at n.l = 0.8 and a white one BEHIND the surface";
        Vector3d got = GraderSupport.call(D, situation, () -> d.shade(new Ray(GraderSupport.v(0, 0, 1), GraderSupport.v(0, 0, -1)), up(), s));
        GraderSupport.expectVector(D, situation, "L (lights add up; a light behind adds nothing)", got, GraderSupport.v(1, 0.8, 0), 1e-6);
    }

    static BlinnPhong phong() {
        BlinnPhong b = new BlinnPhong();
        b.ambientColor = GraderSupport.v(0, 0, 0);
        b.diffuseColor = GraderSupport.v(0, 0, 0);
        b.specularColor = GraderSupport.v(1, 1, 1);
        b.exponent = 10;
        return b;
    }

    public static void blinnPhongHalfVector() {
        BlinnPhong b = phong();
        Scene s = scene(new FixedLight(GraderSupport.v(1, 1, 1), GraderSupport.v(0, 0, 1)));
        // viewer at 45 degrees: h is at 22.5 degrees from n, the mirror direction of l at 45 degrees from v
        double nh = Math.pow(Math.cos(Math.PI / 8), 10);
        String situation = "k_s (1, 1, 1), exponent 10, a light straight above, the viewer at 45 degrees";
        Vector3d got = GraderSupport.call(B, situation, () -> b.shade(new Ray(GraderSupport.v(-1, 0, 1), GraderSupport.v(1, 0, -1)), up(), s));
        if (got != null && GraderSupport.near(got.x, Math.pow(Math.cos(Math.PI / 4), 10), 1e-3)) {
            throw GraderSupport.fail(B + ": " + situation + ": the highlight must be k_s I max(0, n.h)^p = " + GraderSupport.str(nh)
                    + " with the HALF vector h = normalize(l + v); yours is " + GraderSupport.str(got.x)
                    + ", which is Phong's (r.v)^p with the reflection vector");
        }
        GraderSupport.expectVector(B, situation, "L = k_s I (n.h)^p", got, GraderSupport.v(nh, nh, nh), 1e-6);
    }

    public static void blinnPhongFull() {
        BlinnPhong b = phong();
        b.ambientColor = GraderSupport.v(0.2, 0.2, 0.2);
        b.diffuseColor = GraderSupport.v(0.5, 0, 0);
        b.specularColor = GraderSupport.v(0, 0, 1);
        b.exponent = 4;
        Scene s = scene(new FixedLight(GraderSupport.v(2, 2, 2), GraderSupport.v(0, 0.6, 0.8)),
                new FixedLight(GraderSupport.v(9, 9, 9), GraderSupport.v(0, 0, -1)));
        // viewer straight above along a long direction: h = normalize(l + v)
        Vector3d h = GraderSupport.v(0, 0.6, 1.8);
        h.normalize();
        double spec = 2 * Math.pow(h.z, 4);
        String situation = "k_a (0.2, 0.2, 0.2), k_d (0.5, 0, 0), k_s (0, 0, 1), p = 4, a light of (2, 2, 2) at n.l = 0.8, one "
                + "BEHIND the surface, the ray's direction (0, 0, -3) (not unit length)";
        Vector3d got = GraderSupport.call(B, situation, () -> b.shade(new Ray(GraderSupport.v(0, 0, 3), GraderSupport.v(0, 0, -3)), up(), s));
        GraderSupport.expectVector(B, situation, "L = k_a I_a + k_d I (n.l) + k_s I (n.h)^p", got,
                GraderSupport.v(0.1 + 0.8, 0.1, 0.1 + spec), 1e-6);
    }

    /** A material that returns a fixed colour (a fresh copy each time). */
    static final class Flat extends Material {
        final Vector3d color;
        Vector3d returned;

        Flat(Vector3d color) {
            this.color = color;
        }

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            returned = new Vector3d(color);
            return returned;
        }
    }

    /** A scene whose trace returns a fixed colour and remembers the ray it was asked about. */
    static final class MirrorWorld extends Scene {
        Ray asked;

        @Override
        public Vector3d trace(Ray ray) {
            asked = ray;
            return GraderSupport.v(0.5, 0.25, 1);
        }
    }

    public static void glazedWithoutBase() {
        GlazedMaterial g = new GlazedMaterial();
        g.base = null;
        g.mirrorCoefficient = 0.8;
        MirrorWorld s = new MirrorWorld();
        Ray in = new Ray(GraderSupport.v(-1, 0, 1), GraderSupport.v(1, 0, -1));
        in.depth = 2;
        String situation = "no base (base = null), k_m 0.8, a ray arriving along (1, 0, -1), what the mirror ray sees (0.5, 0.25, 1)";
        Vector3d got = GraderSupport.call(G, situation, () -> g.shade(in, up(), s));
        GraderSupport.expectVector(G, situation, "L = k_m L_mirror (no base: L_base is black)", got, GraderSupport.v(0.4, 0.2, 0.8), 1e-6);
        mirrorRay(s.asked, situation, 3);
    }

    static void mirrorRay(Ray asked, String situation, int depth) {
        if (asked == null) {
            throw GraderSupport.fail(G + ": " + situation + ": never called scene.trace with the mirror ray");
        }
        Vector3d d = new Vector3d(asked.direction);
        d.normalize();
        Vector3d want = GraderSupport.v(1, 0, 1);
        want.normalize();
        GraderSupport.expectVector(G, situation, "the mirror ray's direction (normalized) r = d - 2 (d.n) n", d, want, 1e-6);
        GraderSupport.expectVector(G, situation, "the mirror ray's origin (record.location)", asked.origin, GraderSupport.v(0, 0, 0), 1e-9);
        GraderSupport.expect(asked.depth == depth, G + ": " + situation + ": the mirror ray's depth must be ray.depth + 1 = " + depth + "; yours is "
                + asked.depth);
    }

    public static void glazedWithBase() {
        GlazedMaterial g = new GlazedMaterial();
        Flat base = new Flat(GraderSupport.v(0.1, 0.2, 0.3));
        g.base = base;
        g.mirrorCoefficient = 0.5;
        MirrorWorld s = new MirrorWorld();
        Ray in = new Ray(GraderSupport.v(-1, 0, 1), GraderSupport.v(1, 0, -1));
        String situation = "a base that shades (0.1, 0.2, 0.3), k_m 0.5, what the mirror ray sees (0.5, 0.25, 1)";
        Vector3d got = GraderSupport.call(G, situation, () -> g.shade(in, up(), s));
        GraderSupport.expectVector(G, situation, "L = L_base + k_m L_mirror", got, GraderSupport.v(0.35, 0.325, 0.8), 1e-6);
        mirrorRay(s.asked, situation, 1);
    }
}
