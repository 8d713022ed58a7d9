import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** scene.trace here is a test stand-in that returns a fixed colour and remembers the mirror ray. */
@ExtendWith(NamesTheMethod.class)
@Order(8)
@Tag("method:GlazedMaterial.shade")
@DisplayName("8. GlazedMaterial.shade")
class GlazedMaterialShadeTest {

    static final String M = "GlazedMaterial.shade";

    static GlazedMaterial glazed(Material base, double km) {
        GlazedMaterial g = new GlazedMaterial();
        g.base = base;
        g.mirrorCoefficient = km;
        return g;
    }

    /** A ray arriving at the origin along (1, -1, 0) / sqrt 2, the normal +y. */
    static Vector3d shade(Material m, Scene s, int depth) {
        Ray r = new Ray(Expect.v(-1, 1, 0), Expect.unit(1, -1, 0));
        r.depth = depth;
        return m.shade(r, Doubles.record(Expect.v(0, 0, 0), Expect.v(0, 1, 0)), s);
    }

    @Test
    @DisplayName("a Glazed without a base: k_m times what the mirror ray sees")
    void withoutBase() {
        Doubles.TracingScene s = new Doubles.TracingScene(Expect.v(0.2, 0.4, 0.6));
        Vector3d c;
        try {
            c = shade(glazed(null, 0.5), s, 0);
        } catch (NullPointerException e) {
            throw new org.opentest4j.AssertionFailedError(M + ": a Glazed without a base (base == null) must shade as if the base"
                    + " were black; yours threw " + e, e);
        }
        Expect.color(Expect.v(0.1, 0.2, 0.3), c, M, "no base, k_m 0.5, the mirror ray seeing (0.2, 0.4, 0.6)");
    }

    @Test
    @DisplayName("with a base: L_base + k_m L_mirror")
    void withBase() {
        Doubles.TracingScene s = new Doubles.TracingScene(Expect.v(1, 1, 1));
        Expect.color(Expect.v(0.3, 0.35, 0.4), shade(glazed(new Doubles.FixedMaterial(Expect.v(0.1, 0.15, 0.2)), 0.2), s, 0), M,
                "a base shading (0.1, 0.15, 0.2), k_m 0.2, the mirror ray seeing (1, 1, 1)");
    }

    @Test
    @DisplayName("the mirror ray: from the hit point, r = d - 2 (d.n) n, one bounce deeper")
    void mirrorRay() {
        Doubles.TracingScene s = new Doubles.TracingScene(Expect.v(0, 0, 0));
        shade(glazed(null, 0.5), s, 2);
        Expect.that(s.rays.size() == 1, M, "it must trace exactly one mirror ray with scene.trace", "traced " + s.rays.size());
        Ray r = s.rays.get(0);
        Expect.near(Expect.v(0, 0, 0), r.origin, M, "the mirror ray's origin (the hit point, record.location)");
        Vector3d d = new Vector3d(r.direction);
        d.normalize();
        Expect.near(Expect.unit(1, 1, 0), d, M, "the mirror ray's direction for a ray along (1, -1, 0) hitting a surface with normal +y");
        Expect.that(r.depth == 3, M, "the mirror ray of a ray of depth 2 must have depth 3 (ray.depth + 1), so Scene.trace can stop"
                + " at MaxDepth", "has depth " + r.depth);
    }

    @Test
    @DisplayName("the base's colour is not changed in place")
    void baseColourUntouched() {
        Doubles.FixedMaterial base = new Doubles.FixedMaterial(Expect.v(0.1, 0.1, 0.1));
        Doubles.TracingScene s = new Doubles.TracingScene(Expect.v(1, 1, 1));
        shade(glazed(base, 0.5), s, 0);
        Vector3d c = shade(glazed(base, 0.5), s, 0);
        Expect.near(Expect.v(0.1, 0.1, 0.1), base.fixed, M, "the vector the base returned, after shade (add into a new vector, do not"
                + " change the base's: it may be a field of the base)");
        Expect.color(Expect.v(0.6, 0.6, 0.6), c, M, "a second shade of the same point (base (0.1, 0.1, 0.1) + 0.5 (1, 1, 1))");
    }
}
