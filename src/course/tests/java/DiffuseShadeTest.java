import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** The lights here are test lights with a fixed intensity and direction, not your PointLight. */
@ExtendWith(NamesTheMethod.class)
@Order(6)
@Tag("method:Diffuse.shade")
@DisplayName("6. Diffuse.shade")
class DiffuseShadeTest {

    static final String M = "Diffuse.shade";

    static Diffuse diffuse(Vector3d ka, Vector3d kd) {
        Diffuse d = new Diffuse();
        d.ambientColor = ka;
        d.diffuseColor = kd;
        return d;
    }

    static Vector3d shade(Material m, Scene s) {
        return m.shade(Expect.ray(0, 0, 5, 0, 0, -1), Doubles.record(Expect.v(0, 0, 0), Expect.v(0, 0, 1)), s);
    }

    @Test
    @DisplayName("ambient only: k_a I_a, per channel")
    void ambient() {
        Scene s = Doubles.scene();
        s.ambientLight = Expect.v(0.5, 0.5, 1);
        Expect.color(Expect.v(0.05, 0.1, 0.3), shade(diffuse(Expect.v(0.1, 0.2, 0.3), Expect.v(1, 1, 1)), s), M,
                "k_a (0.1, 0.2, 0.3), ambient light (0.5, 0.5, 1) and no lights (k_a I_a, red times red and so on)");
    }

    @Test
    @DisplayName("a light along the normal: k_d I")
    void headOn() {
        Scene s = Doubles.scene();
        s.lights.add(new Doubles.FixedLight(Expect.v(2, 2, 2), Expect.v(0, 0, 1)));
        Expect.color(Expect.v(1, 0.5, 0.2), shade(diffuse(Expect.v(0, 0, 0), Expect.v(0.5, 0.25, 0.1)), s), M,
                "k_d (0.5, 0.25, 0.1), a light (2, 2, 2) arriving along the normal (n.l = 1)");
    }

    @Test
    @DisplayName("an oblique light: k_d I (n.l)")
    void oblique() {
        Scene s = Doubles.scene();
        s.lights.add(new Doubles.FixedLight(Expect.v(1, 1, 1), Expect.v(Math.sqrt(3), 0, 1)));
        Expect.color(Expect.v(0.25, 0.25, 0.25), shade(diffuse(Expect.v(0, 0, 0), Expect.v(0.5, 0.5, 0.5)), s), M,
                "k_d 0.5 and a light (1, 1, 1) arriving 60 degrees from the normal (n.l = 0.5)");
    }

    @Test
    @DisplayName("a light behind the surface adds nothing")
    void lightBehind() {
        Scene s = Doubles.scene();
        s.ambientLight = Expect.v(1, 1, 1);
        s.lights.add(new Doubles.FixedLight(Expect.v(5, 5, 5), Expect.v(0.2, 0, -1)));
        Expect.color(Expect.v(0.1, 0.1, 0.1), shade(diffuse(Expect.v(0.1, 0.1, 0.1), Expect.v(1, 1, 1)), s), M,
                "a light arriving from behind the surface (n.l < 0: max(0, n.l) = 0, only the ambient (0.1, 0.1, 0.1) remains)");
    }

    @Test
    @DisplayName("several coloured lights add up, with ambient")
    void severalLights() {
        Scene s = Doubles.scene();
        s.ambientLight = Expect.v(0.2, 0.2, 0.2);
        s.lights.add(new Doubles.FixedLight(Expect.v(1, 0, 0), Expect.v(0, 0, 1)));
        s.lights.add(new Doubles.FixedLight(Expect.v(0, 2, 0), Expect.v(0, Math.sqrt(3), 1)));
        s.lights.add(new Doubles.FixedLight(Expect.v(0, 0, 0), Expect.v(0, 0, 1)));
        Expect.color(Expect.v(0.55, 0.55, 0.05), shade(diffuse(Expect.v(0.25, 0.25, 0.25), Expect.v(0.5, 0.5, 0.5)), s), M,
                "ambient (0.2, 0.2, 0.2) x k_a 0.25, a red light (1, 0, 0) along the normal, a green light (0, 2, 0) at 60 degrees"
                        + " and a light in shadow (getIntensity black), k_d 0.5");
    }

    @Test
    @DisplayName("returns a new vector, leaving the material's colours alone")
    void newVector() {
        Diffuse d = diffuse(Expect.v(0.1, 0.2, 0.3), Expect.v(0.5, 0.5, 0.5));
        Scene s = Doubles.scene();
        s.ambientLight = Expect.v(1, 1, 1);
        Vector3d c = shade(d, s);
        Expect.that(c != null && c != d.ambientColor && c != d.diffuseColor && c != s.ambientLight, M,
                "it must return a new Vector3d, not one of the material's or the scene's fields", "returned " + Expect.show(c));
        Expect.near(Expect.v(0.1, 0.2, 0.3), d.ambientColor, M, "ambientColor after shade (it must not change)");
        Expect.near(Expect.v(1, 1, 1), s.ambientLight, M, "scene.ambientLight after shade (it must not change)");
    }
}
