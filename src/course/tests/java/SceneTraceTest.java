import javax.vecmath.Vector3d;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;

/** The surfaces here are test surfaces hit at a fixed t, the materials fixed colours. */
@ExtendWith(NamesTheMethod.class)
@Order(9)
@Tag("method:Scene.trace")
@DisplayName("9. Scene.trace")
class SceneTraceTest {

    static final String M = "Scene.trace";

    static Doubles.FixedSurface surface(double t, Vector3d color) {
        return new Doubles.FixedSurface(t, new Doubles.FixedMaterial(color));
    }

    @Test
    @DisplayName("nothing hit: the background colour")
    void background() {
        Scene s = Doubles.scene();
        s.backgroundColor = Expect.v(0.1, 0.2, 0.3);
        Vector3d c = s.trace(Expect.ray(0, 0, 0, 0, 0, -1));
        Expect.color(Expect.v(0.1, 0.2, 0.3), c, M, "a ray that hits nothing with BGColor (0.1, 0.2, 0.3)");
        Expect.that(c != s.backgroundColor, M, "it must return a copy of the background colour, not the field itself",
                "returned scene.backgroundColor");
    }

    @Test
    @DisplayName("the closest hit wins, whatever the order of the surfaces")
    void closest() {
        Scene s = Doubles.scene();
        s.surfaces.add(surface(5, Expect.v(1, 0, 0)));
        s.surfaces.add(surface(2, Expect.v(0, 1, 0)));
        s.surfaces.add(surface(7, Expect.v(0, 0, 1)));
        Vector3d c = s.trace(Expect.ray(0, 0, 0, 0, 0, -1));
        String hint = c != null && c.z == 1 ? " (yours kept the last hit: keep the hit with the smallest t)"
                : c != null && c.x == 1 ? " (yours kept the first hit: keep the hit with the smallest t)" : "";
        Expect.color(Expect.v(0, 1, 0), c, M, "three surfaces hit at t = 5 (red), 2 (green) and 7 (blue): the green one, closest" + hint);
    }

    @Test
    @DisplayName("the closest surface's material shades the hit record of that surface")
    void shadesTheRecord() {
        Scene s = Doubles.scene();
        Doubles.FixedSurface far = surface(6, Expect.v(1, 0, 0)), near = surface(3, Expect.v(0, 1, 0));
        s.surfaces.add(far);
        s.surfaces.add(near);
        s.trace(Expect.ray(0, 0, 0, 0, 0, -1));
        Doubles.FixedMaterial m = (Doubles.FixedMaterial) near.material;
        Expect.that(m.records.size() == 1, M, "it must call shade once, on the closest surface's material", "called it "
                + m.records.size() + " times (and the far one's " + ((Doubles.FixedMaterial) far.material).records.size() + " times)");
        IntersectionRecord r = m.records.get(0);
        Expect.that(r.surface == near, M, "the record given to shade must be the closest hit's (record.surface the closest surface)",
                "gave record.surface " + r.surface);
        Expect.near(3, r.t, M, "record.t of the record given to shade");
    }

    @Test
    @DisplayName("rays deeper than MaxDepth are not followed: black")
    void maxDepth() {
        Scene s = Doubles.scene();
        s.maxDepth = 2;
        s.surfaces.add(surface(1, Expect.v(1, 1, 1)));
        Ray r = Expect.ray(0, 0, 0, 0, 0, -1);
        r.depth = 2;
        Expect.color(Expect.v(1, 1, 1), s.trace(r), M, "a ray of depth 2 with MaxDepth 2 (followed: depth <= MaxDepth)");
        r.depth = 3;
        Expect.color(Expect.v(0, 0, 0), s.trace(r), M, "a ray of depth 3 with MaxDepth 2 (deeper than MaxDepth: not followed, black)");
    }

    @Test
    @DisplayName("the ray's span counts: surfaces before tMin or after tMax are not seen")
    void span() {
        Scene s = Doubles.scene();
        s.backgroundColor = Expect.v(0.5, 0.5, 0.5);
        s.surfaces.add(surface(9, Expect.v(1, 0, 0)));
        Ray r = Expect.ray(0, 0, 0, 0, 0, -1);
        r.tMax = 4;
        Expect.color(Expect.v(0.5, 0.5, 0.5), s.trace(r), M, "a ray with tMax 4 and a surface at t = 9 only (the background)");
    }
}
