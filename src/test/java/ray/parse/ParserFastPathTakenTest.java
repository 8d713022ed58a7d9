package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.surface.Triangle;

/**
 * The fast path is what keeps a million-triangle scene quick to read, and it must actually be taken:
 * in a plainly written file every line after the first object of each kind is read from its bytes, and
 * a line the fast path cannot read exactly (an untidy space, a comment, a number it does not read
 * itself) goes the general path. Counted with {@link Parser#fastLineCount}.
 */
class ParserFastPathTakenTest {

    private static final int TRIANGLES = 50;

    private static String plainScene(String vertexLine) {
        StringBuilder sb = new StringBuilder();
        sb.append("Width 4\n").append("Height 3\n").append("Camera Camera\n").append("Vector3d eye [0 0 5]\n").append("double yFOV 40\n").append('\n');
        sb.append("Material Diffuse red\n").append("Vector3d diffuseColor [1 0 0]\n").append('\n');
        for (int i = 0; i < TRIANGLES; i++) {
            sb.append("Surface Triangle\n")
              .append("Vector3d v0 [").append(i).append(" 0 0]\n")
              .append(vertexLine.replace("I", Integer.toString(i))).append('\n')
              .append("Vector3d v2 [").append(i).append(" 1 0.25]\n")
              .append("ref material red\n")
              .append('\n');
        }
        return sb.toString();
    }

    private static int lines(String text) {
        return text.split("\n", -1).length - 1;
    }

    @Test
    void plainLinesAfterTheFirstHeaderOfEachKindTakeTheFastPath() throws Exception {
        String text = plainScene("Vector3d v1 [I.5 0 -0.5]");
        byte[] bytes = text.getBytes(StandardCharsets.US_ASCII);
        // the general path reads only the two globals and the three headers that start a new kind of object
        assertEquals(lines(text) - 5, Parser.fastLineCount(bytes, "plain.txt"), text);
        // and what it read is the scene the general path reads from the same text
        Scene fast = Parser.parse(bytes, "plain.txt", new ArrayList<>());
        Scene general = Parser.parse(text, "plain.txt", new ArrayList<>());
        assertEquals(TRIANGLES, fast.surfaces.size());
        for (int i = 0; i < TRIANGLES; i++) {
            Triangle a = (Triangle) fast.surfaces.get(i), b = (Triangle) general.surfaces.get(i);
            assertEquals(b.v0, a.v0);
            assertEquals(b.v1, a.v1);
            assertEquals(b.v2, a.v2);
            assertEquals(i + 0.5, a.v1.x, 0);
            assertEquals(b.material, general.surfaces.get(0).material);
            assertEquals(a.material, fast.surfaces.get(0).material);
        }
    }

    @Test
    void linesTheFastPathCannotReadExactlyGoTheGeneralPath() throws Exception {
        int plain = Parser.fastLineCount(plainScene("Vector3d v1 [I.5 0 -0.5]").getBytes(StandardCharsets.US_ASCII), "a.txt");
        for (String untidy : new String[] {
                "Vector3d v1  [I.5 0 -0.5]",          // two spaces
                "Vector3d v1 [I.5 0 -0.5] # comment",  // a comment
                "Vector3d v1 [I.5 0 -0.5] ",           // a trailing space
                "Vector3d\tv1 [I.5 0 -0.5]",          // a tab
                " Vector3d v1 [I.5 0 -0.5]"}) {        // a leading space
            String text = plainScene(untidy);
            assertEquals(plain - TRIANGLES, Parser.fastLineCount(text.getBytes(StandardCharsets.US_ASCII), "b.txt"),
                    "each '" + untidy + "' line goes the general path, the rest stay fast");
            Scene s = Parser.parse(text.getBytes(StandardCharsets.US_ASCII), "b.txt", new ArrayList<>());
            assertEquals(TRIANGLES - 1 + 0.5, ((Triangle) s.surfaces.get(TRIANGLES - 1)).v1.x, 0, untidy);
        }
    }
}
