package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.surface.Triangle;

/**
 * Plain lines take the parser's fast paths (the String one for any text, the byte one for ASCII
 * files); the same scene written untidily, or read by the general path alone, must mean exactly the
 * same, and every mistake must get the same message on the same line.
 */
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
        Scene a = Parser.parse(PLAIN.getBytes(StandardCharsets.US_ASCII), "plain.txt", new ArrayList<>());
        Scene b = Parser.parse(UNTIDY, "untidy.txt", new ArrayList<>());
        assertEquals(describe(b), describe(a));
        Triangle ta = (Triangle) a.surfaces.get(0);
        assertEquals(0.25, ta.v2.z);              // 2.5e-1 read exactly
        assertEquals(-0.5, ta.v1.z);
    }

    /** A plain line with a mistake must still get the general path's message, with its line number. */
    @Test
    void plainLineWithABadNumberIsReportedOnItsLine() {
        String bad = PLAIN.replace("Vector3d v1 [1 0 -0.5]", "Vector3d v1 [1 0 x]");
        SceneFormatException e = assertThrows(SceneFormatException.class,
                () -> Parser.parse(bad.getBytes(StandardCharsets.US_ASCII), "bad.txt", new ArrayList<>()));
        assertEquals(13, e.line());
    }

    private static final String[] LINES = {
        "", "", "", "Surface Triangle", "Surface Sphere", "Surface Sphere s1", "Material Diffuse m1", "Material BlinnPhong m2",
        "Material Glazed g", "Light PointLight", "Surface Nope", "Material Triangle", "Vector3d v0 [0 0 0]",
        "Vector3d v1 [1 0 0]", "Vector3d v2 [0 1 0]", "Vector3d v2 [0 1e400 0]", "Vector3d v1 [1, 0, 0]", "Vector3d v0 [1 0]",
        "Vector3d center [0.5 -1 2]", "double radius 0.25", "double radius -1", "double radius 1e999", "double radius x",
        "double v0 1", "ref material m1", "ref material m2", "ref material g", "ref material nobody", "ref material m1 m2",
        "ref base m2", "double mirrorCoefficient 0.5", "Vector3d diffuseColor [0.2 0.3 0.4]", "double exponent 20",
        "Vector3d position [1 2 3]", "Vector3d intensity [5 5 5]", "int radius 3", "String v0 hello", "Vector3d nofield [1 2 3]",
        "Vector3d  v0 [0 0 0]", "Vector3d v0 [0 0 0] ", "# comment", "Vector3d v0 [0 0 0] # c", "double\tradius 2", "Width 9",
        "double radius 2.5", "Surface  Triangle", "Surface Triangle extra words", "ref material", "Vector3d v1",
    };

    private static final String[][] BLOCKS = {
        {"Surface Triangle", "Vector3d v0 [0 0 0]", "Vector3d v1 [1 0 -0.5]", "Vector3d v2 [0 1 2.5e-1]", "ref material m1"},
        {"Surface Triangle", "Vector3d v0 [0, 0, 0]", "Vector3d  v1 [1 0 0]", "Vector3d v2 [0 1 0]  # c", "ref material m2"},
        {"Surface Sphere", "Vector3d center [0.5 -1 2]", "double radius 0.25", "ref material g"},
        {"Surface Sphere", "double radius 3", "ref material m2"},
        {"Material Diffuse", "Vector3d diffuseColor [0.2 0.3 0.4]"},
        {"Material BlinnPhong", "double exponent 20", "Vector3d specularColor [1 1 1]"},
        {"Light PointLight", "Vector3d position [1 2 3]", "Vector3d intensity [5 5 5]"},
    };

    /** Random scenes of plain, untidy and wrong lines: the byte fast path, the String path and the messages agree. */
    @Test
    void randomScenesReadTheSameOnEveryPath() throws Exception {
        Random r = new Random(99);
        int ok = 0;
        for (int k = 0; k < 3000; k++) {
            StringBuilder b = new StringBuilder("Width 8\nHeight 6\n\nCamera Camera\n\nMaterial Diffuse m1\n\nMaterial BlinnPhong m2\n\nMaterial Glazed g\n\n");
            int objects = 1 + r.nextInt(6);
            for (int o = 0; o < objects; o++) {
                String[] block = BLOCKS[r.nextInt(BLOCKS.length)];
                for (String line : block) {
                    // mostly the block's own lines; now and then a wrong, untidy or stray one
                    b.append(r.nextInt(12) == 0 ? LINES[r.nextInt(LINES.length)] : line).append('\n');
                }
                b.append('\n');
            }
            String text = b.toString();
            String viaBytes = outcome(() -> Parser.parse(text.getBytes(StandardCharsets.US_ASCII), "r.txt", new ArrayList<>()));
            String viaText = outcome(() -> Parser.parse(text, "r.txt", new ArrayList<>()));
            assertEquals(viaText, viaBytes, text);
            if (!viaText.startsWith("error")) {
                ok++;
            }
        }
        assertEquals(true, ok > 100, "some random scenes should be valid: " + ok);
    }

    /** A file big enough for the prescan thread: the same scene, or the same message, as the String path. */
    @Test
    void largeFilesReadTheSameWithTheLineReaderThread() throws Exception {
        Random r = new Random(100);
        int valid = 0;
        for (int k = 0; k < 6; k++) {
            StringBuilder b = new StringBuilder("Width 8\nHeight 6\n\nCamera Camera\n\nMaterial Diffuse m1\n\nMaterial BlinnPhong m2\n\nMaterial Glazed g\n\n");
            boolean corrupt = k % 3 != 0;
            while (b.length() < Parser.Prescan.MIN_BYTES + 50_000) {
                String[] block = BLOCKS[r.nextInt(BLOCKS.length)];
                for (String line : block) {
                    b.append(corrupt && r.nextInt(20_000) == 0 ? LINES[r.nextInt(LINES.length)] : line).append('\n');
                }
                b.append('\n');
            }
            if (k % 4 == 1) {
                b.setLength(b.length() - 1);   // no newline at the end
            }
            String text = b.toString();
            String viaBytes = outcome(() -> Parser.parse(text.getBytes(StandardCharsets.US_ASCII), "big.txt", new ArrayList<>()));
            String viaText = outcome(() -> Parser.parse(text, "big.txt", new ArrayList<>()));
            assertEquals(viaText, viaBytes);
            if (!viaText.startsWith("error")) {
                valid++;
            }
        }
        assertEquals(true, valid >= 2, "the uncorrupted files must be valid scenes: " + valid);
    }

    private interface Parse {
        Scene run() throws SceneFormatException;
    }

    private static String outcome(Parse p) {
        try {
            return describe(p.run());
        } catch (SceneFormatException e) {
            return "error " + e.getMessage();
        }
    }

    /** Every public field of every object of the scene, objects referred to by their place in the scene. */
    private static String describe(Scene s) {
        List<Object> objects = new ArrayList<>();
        objects.add(s.camera);
        objects.addAll(s.materials);
        objects.addAll(s.lights);
        objects.addAll(s.surfaces);
        StringBuilder b = new StringBuilder(s.width + "x" + s.height + "\n");
        for (Object o : objects) {
            b.append(o.getClass().getSimpleName()).append(':');
            for (Class<?> c = o.getClass(); c != Object.class; c = c.getSuperclass()) {
                for (Field f : c.getDeclaredFields()) {
                    if (Modifier.isStatic(f.getModifiers()) || !Modifier.isPublic(f.getModifiers())) {
                        continue;
                    }
                    try {
                        Object v = f.get(o);
                        int idx = objects.indexOf(v);
                        b.append(' ').append(f.getName()).append('=').append(idx >= 0 && !(v instanceof javax.vecmath.Vector3d) ? "#" + idx : String.valueOf(v));
                    } catch (IllegalAccessException e) {
                        throw new AssertionError(e);
                    }
                }
            }
            b.append('\n');
        }
        return b.toString();
    }
}
