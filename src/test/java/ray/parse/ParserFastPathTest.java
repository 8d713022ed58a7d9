package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.surface.Triangle;

/** Plain lines take the parser's fast path; the same scene written untidily must mean the same. */
class ParserFastPathTest {

    private static final String PLAIN = String.join("\n",
            "Width 4", "Height 3", "", "Camera Camera", "Vector3d eye [0 0 5]", "double yFOV 40", "",
            "Material Diffuse red", "Vector3d diffuseColor [0.8 0.125 0]", "",
            "Surface Triangle", "Vector3d v0 [0 0 0]", "Vector3d v1 [1 0 -0.5]", "Vector3d v2 [0 1 2.5e-1]",
            "ref material red", "");

    private static final String UNTIDY = String.join("\n",
            "Width\t4", "Height 3   # comment", "", "Camera  Camera", "  Vector3d eye [0, 0, 5]", "double yFOV   40", "",
            "Material Diffuse red", "Vector3d diffuseColor [ 0.8\t0.125 0 ]", "",
            "Surface Triangle", "Vector3d v0 [0 0 0]", "Vector3d\tv1 [1 0 -0.5]  ", "Vector3d v2 [0,1,2.5e-1]",
            "ref  material red", "");

    @Test
    void untidyWhitespaceAndCommentsReadTheSameAsPlainLines() throws Exception {
        Scene a = Parser.parse(PLAIN, "plain.txt", new ArrayList<>());
        Scene b = Parser.parse(UNTIDY, "untidy.txt", new ArrayList<>());
        assertEquals(a.camera.eye, b.camera.eye);
        assertEquals(a.camera.yFOV, b.camera.yFOV);
        Triangle ta = (Triangle) a.surfaces.get(0), tb = (Triangle) b.surfaces.get(0);
        assertEquals(ta.v1, tb.v1);
        assertEquals(ta.v2, tb.v2);
        assertEquals(0.25, ta.v2.z);              // 2.5e-1 read exactly
        assertEquals(-0.5, ta.v1.z);
    }

    /** A plain line with a mistake must still get the general path's message, with its line number. */
    @Test
    void plainLineWithABadNumberIsReportedOnItsLine() {
        String bad = PLAIN.replace("Vector3d v1 [1 0 -0.5]", "Vector3d v1 [1 0 x]");
        SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(bad, "bad.txt", new ArrayList<>()));
        assertEquals(13, e.line());
    }
}
