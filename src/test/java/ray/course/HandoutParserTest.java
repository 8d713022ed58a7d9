package ray.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.InvocationTargetException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import ray.parse.Parser;
import ray.parse.SceneFormatException;

/**
 * The handout's parser (src/course/solution/java/Parser.java, given to students) reports a scene's mistakes as
 * the engine's does: the same file:line and the same words. Where the message lists the built-in classes or
 * globals (the handout has only the 2003 ones), the words up to that list are the same.
 */
class HandoutParserTest {

    static final String GOOD = "Width 8\nHeight 6\n\nCamera Camera\n\nMaterial Diffuse m\n\n";

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
        "unknown keyword|Widht 10|(",
        "no Width|Height 6\\n\\nCamera Camera\\n|",
        "no camera|Width 8\\nHeight 6\\n|",
        "a second camera|" + "Width 8\\nHeight 6\\n\\nCamera Camera\\n\\nCamera Camera\\n|",
        "unknown field|@Surface Sphere\\nVector3d centre [0 0 0]\\nref material m\\n|",
        "short vector|@Surface Sphere\\nVector3d center [1 2]\\nref material m\\n|",
        "not a number|@Surface Sphere\\ndouble radius abc\\nref material m\\n|",
        "NaN|@Surface Sphere\\ndouble radius NaN\\nref material m\\n|",
        "undefined ref|@Surface Sphere\\nref material nothing\\n|",
        "ref of a wrong kind|@Light PointLight l\\n\\nSurface Sphere\\nref material l\\n|",
        "parameter outside an object|@double radius 2\\n|",
        "blank line inside an object|@Surface Sphere\\n\\nref material m\\n|",
        "name used twice|@Material Diffuse m\\n|",
        "setting twice|Width 8\\nWidth 9\\n|",
        "no material|@Surface Sphere\\ndouble radius 2\\n|",
        "eye at the target|Width 8\\nHeight 6\\n\\nCamera Camera\\nVector3d eye [0 0 0]\\n|",
        "up along the view|Width 8\\nHeight 6\\n\\nCamera Camera\\nVector3d up [0 0 1]\\n|",
        "wrong type keyword|@Surface Sphere\\nint radius 2\\nref material m\\n|",
        "no type|@Surface Sphere\\nradius 2\\nref material m\\n|",
        "unknown class|@Surface Spher\\n|(",
        "a material as a surface|@Surface Diffuse\\n|(",
        "negative radius|@Surface Sphere\\ndouble radius -1\\nref material m\\n|",
        "Width 0|Width 0\\nHeight 6\\n|",
        "AASamples not whole|Width 8\\nHeight 6\\nAASamples 2.5\\n|",
        "field set twice|@Surface Sphere\\ndouble radius 1\\ndouble radius 2\\n|",
        "yFOV out of range|Width 8\\nHeight 6\\n\\nCamera Camera\\ndouble yFOV 180\\n|",
        "empty file||",
        "case hint|@surface Sphere\\n|(",
    })
    void sameMessageAsTheEngine(String what, String text, String cutAt) throws Exception {
        text = text == null ? "" : text;
        String scene = (text.startsWith("@") ? GOOD + text.substring(1) : text).replace("\\n", "\n");
        String engine;
        try {
            Parser.parse(scene.getBytes(StandardCharsets.UTF_8), "s.txt", new ArrayList<>());
            engine = "(no error)";
        } catch (SceneFormatException e) {
            engine = e.getMessage();
        }
        String handout;
        try {
            Course.loader(Course.SOLUTION_CLASSES).loadClass("Parser").getMethod("parse", String.class, String.class).invoke(null, scene, "s.txt");
            handout = "(no error)";
        } catch (InvocationTargetException e) {
            handout = e.getCause().getMessage();
        }
        assertTrue(engine.startsWith("s.txt:"), what + ": the engine refuses it: " + engine);
        if (cutAt == null || cutAt.isEmpty()) {
            assertEquals(engine, handout, what);
        } else {
            assertEquals(engine.substring(0, engine.indexOf(cutAt)), handout.substring(0, Math.max(0, handout.indexOf(cutAt))), what);
        }
    }
}
