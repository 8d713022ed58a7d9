package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The built-in classes an error message offers are the ones the parser accepts, found on the class path
 * (CSG and Mesh were missing from the hand-kept list), the framework's first; the globals' keywords are
 * the table's.
 */
class BuiltInListTest {

    @Test
    void everyNameOfferedIsAcceptedAndNoneIsMissing() throws Exception {
        String surfaces = ClassResolver.builtIns("Surface");
        assertTrue(surfaces.startsWith("Sphere, Triangle, "), surfaces);
        for (String must : List.of("Box", "CSG", "Cone", "Cylinder", "Disc", "Mesh", "Plane", "Torus")) {
            assertTrue(List.of(surfaces.split(", ")).contains(must), must + " in " + surfaces);
        }
        assertTrue(ClassResolver.builtIns("Material").contains("GlazedMaterial (or Glazed)"), ClassResolver.builtIns("Material"));
        assertTrue(ClassResolver.builtIns("Light").startsWith("PointLight, "), ClassResolver.builtIns("Light"));
        assertEquals("Camera", ClassResolver.builtIns("Camera"));
        ClassResolver r = new ClassResolver(getClass().getClassLoader());
        for (String type : ClassResolver.BASES.keySet()) {
            for (String n : ClassResolver.builtIns(type).replace(" (or ", ", ").replace(")", "").split(", ")) {
                assertTrue(ClassResolver.BASES.get(type).isAssignableFrom(r.resolve(type, n)), type + " " + n);
            }
        }
        String m = assertThrows(SceneFormatException.class,
                () -> Parser.parse("Width 4\nHeight 4\n\nCamera Camera\n\nSurface Sphear\n\n", "s.txt", new ArrayList<>())).getMessage();
        assertTrue(m.contains("expected " + ClassResolver.builtIns("Surface") + " or a Surface class"), m);
    }

    @Test
    void theGlobalsAreTheTables() {
        assertEquals(Parser.GLOBALS, Globals.NAMES);
        for (ray.settings.RenderOption o : ray.settings.RenderOption.values()) {
            assertEquals(o.hint, Globals.of(o.global).hint, o.global);
        }
    }
}
