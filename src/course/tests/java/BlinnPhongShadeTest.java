import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** The lights here are test lights with a fixed intensity and direction, not your PointLight. */
@ExtendWith(NamesTheMethod.class)
@Order(7)
@Tag("method:BlinnPhong.shade")
@DisplayName("7. BlinnPhong.shade")
class BlinnPhongShadeTest {

    static final String M = "BlinnPhong.shade";

    static BlinnPhong material(Vector3d ka, Vector3d kd, Vector3d ks, double p) {
        BlinnPhong b = new BlinnPhong();
        b.ambientColor = ka;
        b.diffuseColor = kd;
        b.specularColor = ks;
        b.exponent = p;
        return b;
    }

    /** Shades the point (0, 0, 0), normal +z, seen along {@code d}. */
    static Vector3d shade(Material m, Scene s, Vector3d d) {
        return m.shade(new Ray(Expect.v(0, 0, 5), d), Doubles.record(Expect.v(0, 0, 0), Expect.v(0, 0, 1)), s);
    }

    static Scene lit(Vector3d intensity, Vector3d l) {
        Scene s = Doubles.scene();
        s.lights.add(new Doubles.FixedLight(intensity, l));
        return s;
    }

    @Test
    @DisplayName("the brightest highlight: light and viewer along the normal")
    void headOn() {
        Expect.color(Expect.v(1.5, 1.5, 1.5), shade(material(Expect.v(0, 0, 0), Expect.v(0.5, 0.5, 0.5), Expect.v(1, 1, 1), 20),
                lit(Expect.v(1, 1, 1), Expect.v(0, 0, 1)), Expect.v(0, 0, -1)), M,
                "light (1, 1, 1) and viewer both along the normal, k_d 0.5, k_s 1 (n.l = 1, h = n, n.h = 1: 0.5 + 1)");
    }

    @Test
    @DisplayName("the half vector h = normalize(l + v), not Phong's reflection vector")
    void halfVector() {
        // light 60 degrees from the normal, viewer along the normal: h is 30 degrees from n
        double expected = Math.pow(Math.cos(Math.toRadians(30)), 10);
        double phong = Math.pow(Math.cos(Math.toRadians(60)), 10);
        Vector3d c = shade(material(Expect.v(0, 0, 0), Expect.v(0, 0, 0), Expect.v(1, 1, 1), 10),
                lit(Expect.v(1, 1, 1), Expect.v(Math.sqrt(3), 0, 1)), Expect.v(0, 0, -1));
        String hint = c != null && Math.abs(c.x - phong) < 1e-6 ? " (yours is Phong's (r.v)^p: use h = normalize(l + v) and (n.h)^p)" : "";
        Expect.color(Expect.v(expected, expected, expected), c, M,
                "k_d 0, k_s 1, p 10, a light 60 degrees from the normal and the viewer along it (n.h = cos 30 degrees)" + hint);
    }

    @Test
    @DisplayName("v is made unit length from the ray's direction")
    void viewerUnitLength() {
        double expected = Math.pow(Math.cos(Math.toRadians(30)), 10);
        Expect.color(Expect.v(expected, expected, expected), shade(material(Expect.v(0, 0, 0), Expect.v(0, 0, 0), Expect.v(1, 1, 1), 10),
                lit(Expect.v(1, 1, 1), Expect.v(Math.sqrt(3), 0, 1)), Expect.v(0, 0, -7)), M,
                "the same light seen along a ray direction (0, 0, -7) of length 7 (v = -d / |d|)");
    }

    @Test
    @DisplayName("a light behind the surface adds no highlight either")
    void lightBehind() {
        Scene s = lit(Expect.v(1, 1, 1), Expect.v(1, 0, -0.1));
        s.ambientLight = Expect.v(1, 1, 1);
        Expect.color(Expect.v(0.1, 0.1, 0.1), shade(material(Expect.v(0.1, 0.1, 0.1), Expect.v(1, 1, 1), Expect.v(1, 1, 1), 2),
                s, Expect.v(0, 0, -1)), M,
                "a light just behind the surface (n.l < 0), k_a 0.1 under ambient (1, 1, 1): n.h is still > 0 there, but the light"
                        + " adds nothing, highlight included");
    }

    @Test
    @DisplayName("ambient + diffuse + coloured highlight, per channel")
    void allTerms() {
        Scene s = lit(Expect.v(2, 1, 0.5), Expect.v(0, 0, 1));
        s.ambientLight = Expect.v(1, 1, 1);
        Expect.color(Expect.v(0.1 + 2 * (0.2 + 0.5), 0.1 + 1 * (0.2 + 0.25), 0.1 + 0.5 * (0.2 + 0)),
                shade(material(Expect.v(0.1, 0.1, 0.1), Expect.v(0.2, 0.2, 0.2), Expect.v(0.5, 0.25, 0), 50), s, Expect.v(0, 0, -1)), M,
                "k_a 0.1 under ambient (1, 1, 1), k_d 0.2, k_s (0.5, 0.25, 0), a light (2, 1, 0.5) along the normal seen head-on");
    }

    @Test
    @DisplayName("the exponent narrows the highlight")
    void exponent() {
        double nh = Math.cos(Math.toRadians(30));
        for (double p : new double[] {1, 100}) {
            double e = Math.pow(nh, p);
            Expect.color(Expect.v(e, e, e), shade(material(Expect.v(0, 0, 0), Expect.v(0, 0, 0), Expect.v(1, 1, 1), p),
                    lit(Expect.v(1, 1, 1), Expect.v(Math.sqrt(3), 0, 1)), Expect.v(0, 0, -1)), M,
                    "exponent " + Expect.num(p) + " with n.h = cos 30 degrees ((n.h)^p)");
        }
    }
}
