package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import ray.Scene;
import ray.surface.Box;
import ray.surface.Cone;
import ray.surface.Cylinder;
import ray.surface.Disc;
import ray.surface.Plane;
import ray.surface.Surface;
import ray.surface.Torus;

/** The new primitives by name from a scene, and each value they refuse as one line naming the object's header. */
class PrimitiveBadInputTest {

    private static final String HEAD = "Width 4\nHeight 3\n\nCamera Camera\n\nMaterial Diffuse m\n\n";

    private static String scene(String cls, String field) {
        return HEAD + "Surface " + cls + "\n" + field + "\nref material m\n";
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', value = {
        "Plane    | Vector3d normal [0 0 0]    | plane normal must have a non-zero length, got (0.0, 0.0, 0.0)",
        "Disc     | Vector3d normal [0 0 0]    | disc normal must have a non-zero length, got (0.0, 0.0, 0.0)",
        "Disc     | double radius 0            | disc radius must be a positive number, got 0.0",
        "Box      | Vector3d minPoint [1 0 0]  | box minPoint must be below maxPoint in every coordinate, got (1.0, 0.0, 0.0) and (1.0, 1.0, 1.0)",
        "Cylinder | Vector3d axis [0 0 0]      | cylinder axis must have a non-zero length, got (0.0, 0.0, 0.0)",
        "Cylinder | double radius -2           | cylinder radius must be a positive number, got -2.0",
        "Cone     | Vector3d axis [0 0 0]      | cone axis must have a non-zero length, got (0.0, 0.0, 0.0)",
        "Cone     | double radius 0            | cone radius must be a positive number, got 0.0",
        "Torus    | Vector3d axis [0 0 0]      | torus axis must have a non-zero length, got (0.0, 0.0, 0.0)",
        "Torus    | double majorRadius 0       | torus majorRadius must be a positive number, got 0.0",
        "Torus    | double minorRadius -1      | torus minorRadius must be a positive number, got -1.0",
        "Torus    | double minorRadius 1       | torus minorRadius must be below majorRadius (a ring torus; a horn or spindle torus intersects itself), got minorRadius 1.0 and majorRadius 1.0",
    })
    void refusedValueIsOneLineNamingTheHeader(String cls, String field, String message) {
        SceneFormatException e = assertThrows(SceneFormatException.class,
                () -> Parser.parse(scene(cls, field), "scene.txt", new ArrayList<>()));
        assertEquals("scene.txt:8: Surface " + cls + ": " + message, e.getMessage());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"Plane", "Disc", "Box", "Cylinder", "Cone", "Torus"})
    void builtInPrimitiveIsFoundByItsSimpleName(String cls) throws Exception {
        Scene s = Parser.parse(scene(cls, "# defaults"), "scene.txt", new ArrayList<>());
        Surface surface = s.surfaces.get(0);
        Class<?> expected = switch (cls) {
            case "Plane" -> Plane.class;
            case "Disc" -> Disc.class;
            case "Box" -> Box.class;
            case "Cylinder" -> Cylinder.class;
            case "Cone" -> Cone.class;
            default -> Torus.class;
        };
        assertSame(expected, surface.getClass());
    }

    /** Box, Cylinder, Cone and Torus are closed (CSG operands); Plane and Disc are not. */
    @ParameterizedTest(name = "{0} minus {1}")
    @CsvSource({"Box, Torus, true", "Cylinder, Cone, true", "Plane, Box, false", "Box, Disc, false"})
    void closedPrimitivesAreCsgOperandsAndFlatOnesAreNot(String left, String right, boolean closed) throws Exception {
        String text = HEAD + "Surface " + left + " a\nref material m\n\nSurface " + right + " b\nref material m\n\n"
                + "Surface CSG\nString operation difference\nref left a\nref right b\nref material m\n";
        if (closed) {
            Scene s = Parser.parse(text, "scene.txt", new ArrayList<>());
            assertEquals(1, s.surfaces.size());
        } else {
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(text, "scene.txt", new ArrayList<>()));
            String flat = left.equals("Box") ? right : left;
            String side = left.equals("Box") ? "right" : "left";
            assertEquals("scene.txt:14: Surface CSG: " + side + " operand " + flat + " is not a closed surface (expected Sphere, Box,"
                    + " Cylinder, Cone, Torus, CSG or a closed two-sided Mesh)", e.getMessage());
        }
    }
}
