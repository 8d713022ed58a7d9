import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** The blockers here are test walls (planes z = const), not your Sphere or Triangle. */
@ExtendWith(NamesTheMethod.class)
@Order(5)
@Tag("method:PointLight.getIntensity")
@DisplayName("5. PointLight.getIntensity")
class PointLightGetIntensityTest {

    static final String M = "PointLight.getIntensity";

    /** A light at (0, 0, 3) with intensity (9, 18, 27), lighting the point (0, 0, 0) (normal +z). */
    static PointLight light() {
        PointLight l = new PointLight();
        l.position = Expect.v(0, 0, 3);
        l.intensity = Expect.v(9, 18, 27);
        return l;
    }

    static Vector3d at(PointLight l, Scene s, Vector3d point) {
        return l.getIntensity(Doubles.record(point, Expect.v(0, 0, 1)), s);
    }

    @Test
    @DisplayName("unshadowed: I / r^2")
    void falloff() {
        Expect.color(Expect.v(1, 2, 3), at(light(), Doubles.scene(), Expect.v(0, 0, 0)), M,
                "a light of intensity (9, 18, 27) at distance 3 with nothing between (I / r^2 = I / 9)");
        Expect.color(Expect.v(9 / 4.0, 18 / 4.0, 27 / 4.0), at(light(), Doubles.scene(), Expect.v(0, 0, 1)), M,
                "the same light at distance 2 (I / r^2, not I / r)");
    }

    @Test
    @DisplayName("a surface between the point and the light casts a shadow (a light behind an object)")
    void shadow() {
        Scene s = Doubles.scene();
        s.surfaces.add(new Doubles.Wall(1.5));
        Expect.color(Expect.v(0, 0, 0), at(light(), s, Expect.v(0, 0, 0)), M,
                "the point (0, 0, 0) with a wall at z = 1.5 between it and the light at (0, 0, 3) (in shadow: black)");
    }

    @Test
    @DisplayName("every surface of the scene is tested for the shadow, not only the first")
    void allSurfaces() {
        Scene s = Doubles.scene();
        s.surfaces.add(new Doubles.Wall(-2));
        s.surfaces.add(new Doubles.Wall(7));
        s.surfaces.add(new Doubles.Wall(2));
        Expect.color(Expect.v(0, 0, 0), at(light(), s, Expect.v(0, 0, 0)), M,
                "walls at z = -2, 7 and 2, the last between the point (0, 0, 0) and the light at (0, 0, 3) (black)");
    }

    @Test
    @DisplayName("surfaces beyond the light or behind the point cast no shadow on it")
    void onlyBetween() {
        Scene s = Doubles.scene();
        s.surfaces.add(new Doubles.Wall(4));
        s.surfaces.add(new Doubles.Wall(-1));
        Expect.color(Expect.v(1, 2, 3), at(light(), s, Expect.v(0, 0, 0)), M,
                "the point (0, 0, 0), the light at (0, 0, 3), walls at z = 4 (beyond the light) and z = -1 (behind the point):"
                        + " neither is between them, so the light arrives unshadowed");
    }

    @Test
    @DisplayName("the point's own surface does not shadow it (shadow acne)")
    void ownSurface() {
        Scene s = Doubles.scene();
        s.surfaces.add(new Doubles.Wall(0));
        Expect.color(Expect.v(1, 2, 3), at(light(), s, Expect.v(0, 0, 0)), M,
                "the point (0, 0, 0) lying on a wall z = 0 (the shadow ray starts on that wall at t = 0: it must start at"
                        + " t = Ray.EPSILON or later, or every lit point is in its own shadow)");
    }

    @Test
    @DisplayName("a surface the light sits on does not shadow it")
    void lightOnASurface() {
        Scene s = Doubles.scene();
        s.surfaces.add(new Doubles.Wall(3));
        Expect.color(Expect.v(1, 2, 3), at(light(), s, Expect.v(0, 0, 0)), M,
                "the light at (0, 0, 3) sitting on a wall z = 3 (end the shadow ray just short of the light: tMax = 1 - Ray.EPSILON"
                        + " with direction = position - location)");
    }

    @Test
    @DisplayName("returns a new vector and leaves the light's intensity alone")
    void newVector() {
        PointLight l = light();
        Vector3d got = at(l, Doubles.scene(), Expect.v(0, 0, 0));
        Expect.color(Expect.v(1, 2, 3), got, M, "a light of intensity (9, 18, 27) at distance 3 with nothing between");
        Expect.that(got != l.intensity, M, "it must return a new Vector3d, not the light's own intensity field", "returned the field");
        Expect.near(Expect.v(9, 18, 27), l.intensity, M, "the light's intensity after getIntensity (it must not change)");
    }
}
