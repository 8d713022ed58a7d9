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
 * A scene read from bytes (a file: ASCII lines widened as they are scanned, others decoded as UTF-8)
 * and from a String (text) must mean exactly the same, written plainly or untidily, and every mistake
 * must get the same message on the same line.
 */
class ParserBytesAndTextTest {

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
        "Surface Triangle t1", "ref material t1", "ref material s1", "ref material s9", "Vector3d v0 [1 2 3 4]", "Vector3d v0 [ 1 2 3]",
        "double radius +.5", "double radius 5.", "double radius 1e-400", "double radius NaN", "Vector3d v0 [1 2 Infinity]",
        "ref material m1 ", "  ", "\t", "Vector3d v0 [0 0 0]\r", "Vector3d v\u00e9 [1 2 3]", "# caf\u00e9", "double radius 0x1p3",
        "double exponent 2", "int exponent 2", "ref base m1", "ref base g", "double Radius 1", "Camera Camera",
        "Material Glazed", "Material Diffuse", "Surface Triangle#x", "double radius 1#x", "Surface Sphere\u0001",
    };

    private static final String[][] BLOCKS = {
        {"Surface Triangle", "Vector3d v0 [0 0 0]", "Vector3d v1 [1 0 -0.5]", "Vector3d v2 [0 1 2.5e-1]", "ref material m1"},
        {"Surface Triangle", "Vector3d v0 [0, 0, 0]", "Vector3d  v1 [1 0 0]", "Vector3d v2 [0 1 0]  # c", "ref material m2"},
        {"Surface Sphere", "Vector3d center [0.5 -1 2]", "double radius 0.25", "ref material g"},
        {"Surface Sphere s9", "double radius 3", "ref material m2"},
        {"Material Diffuse", "Vector3d diffuseColor [0.2 0.3 0.4]"},
        {"Material BlinnPhong", "double exponent 20", "ref base m2"},
        {"Light PointLight", "Vector3d position [1 2 3]", "Vector3d intensity [5 5 5]"},
    };

    /** Random scenes of plain, untidy and wrong lines: bytes, text and the messages agree. */
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
            String viaBytes = outcome(() -> Parser.parse(text.getBytes(StandardCharsets.UTF_8), "r.txt", new ArrayList<>()));
            String viaText = outcome(() -> Parser.parse(text, "r.txt", new ArrayList<>()));
            assertEquals(viaText, viaBytes, text);
            if (!viaText.startsWith("error")) {
                ok++;
            }
        }
        assertEquals(true, ok > 100, "some random scenes should be valid: " + ok);
    }

    /** Wrong refs (to the object itself, to an object of the wrong kind, to nothing) after right ones: the full message. */
    @Test
    void plainRefsThatAreWrongGetTheGeneralMessage() {
        String head = "Width 4\nHeight 3\n\nCamera Camera\n\nMaterial Diffuse d\n\nSurface Sphere s\nref material d\n\n";
        String[][] cases = {
            {"Material Glazed b\nref base b\n", "'b' is the object being defined"},
            {"Material Glazed b\nref base s\n", "'s' is a Sphere, but 'ref base' needs a Material"},
            {"Material Glazed b\nref base nobody\n", "undefined object 'nobody'"},
        };
        for (String[] c : cases) {
            String text = head + c[0];
            String viaText = outcome(() -> Parser.parse(text, "r.txt", new ArrayList<>()));
            assertEquals(true, viaText.contains("r.txt:12: " + c[1]), viaText);
            assertEquals(viaText, outcome(() -> Parser.parse(text.getBytes(StandardCharsets.US_ASCII), "r.txt", new ArrayList<>())));
        }
    }

    /** Line ends, a byte-order mark and a non-ASCII line (read by the general path) among plain ones change nothing. */
    @Test
    void lineEndsMarkAndNonAsciiLinesReadTheSame() throws Exception {
        String expected = outcome(() -> Parser.parse(PLAIN, "p.txt", new ArrayList<>()));
        String[] variants = {PLAIN.replace("\n", "\r\n"), PLAIN.replace("\n", "\r"), "\ufeff" + PLAIN,
            PLAIN.replace("Vector3d v1 [1 0 -0.5]", "Vector3d v1 [1 0 -0.5] # caf\u00e9 \u2014 non-ASCII comment")};
        for (String v : variants) {
            assertEquals(expected, outcome(() -> Parser.parse(v.getBytes(StandardCharsets.UTF_8), "p.txt", new ArrayList<>())), v);
        }
    }

    /** The reader copies a line's bytes in runs: lines across its 64 KB buffer, or as long as allowed, read whole. */
    @Test
    void longLinesAcrossTheReadBufferReadWhole() throws Exception {
        String expected = outcome(() -> Parser.parse(PLAIN, "p.txt", new ArrayList<>()));
        for (int pad : new int[] {(1 << 16) - 20, (1 << 16) - 9, Limits.MAX_LINE - 2, 100_000}) {
            String comment = "# " + "x".repeat(Math.min(pad, Limits.MAX_LINE - 2));
            String text = comment + "\n" + PLAIN;
            assertEquals(expected, outcome(() -> Parser.parse(text.getBytes(StandardCharsets.UTF_8), "p.txt", new ArrayList<>())), "pad " + pad);
        }
    }

    /** The limits at a line's length, as the byte-at-a-time reader had them: in chars, and at 3 x MAX_LINE + 1 bytes. */
    @Test
    void lineLengthLimitsAreWhereTheyWere() {
        String ok = "# " + "x".repeat(Limits.MAX_LINE - 2) + "\n" + PLAIN;          // exactly MAX_LINE chars
        assertEquals(outcome(() -> Parser.parse(PLAIN, "p.txt", new ArrayList<>())),
                outcome(() -> Parser.parse(ok.getBytes(StandardCharsets.UTF_8), "p.txt", new ArrayList<>())));
        String tooLong = PLAIN + "# " + "x".repeat(Limits.MAX_LINE - 1) + "\n";     // one char more, on line 16
        SceneFormatException e = assertThrows(SceneFormatException.class,
                () -> Parser.parse(tooLong.getBytes(StandardCharsets.UTF_8), "p.txt", new ArrayList<>()));
        assertEquals("p.txt:16: line is longer than 65,536 characters (expected at most 65,536; is this a scene file?)", e.getMessage());
        // 3 x MAX_LINE + 1 bytes are read before a line is refused unread: a bad byte that is the last of them is not UTF-8
        byte[] head = "# ".getBytes(StandardCharsets.UTF_8);
        byte[] line = new byte[3 * Limits.MAX_LINE + 1 + 1];
        System.arraycopy(head, 0, line, 0, 2);
        for (int i = 2; i < 3 * Limits.MAX_LINE; i += 2) {
            line[i] = (byte) 0xC3;                // \u00e9, two bytes
            line[i + 1] = (byte) 0xA9;
        }
        line[3 * Limits.MAX_LINE] = (byte) 0xC3;  // a lead byte with nothing after it
        line[3 * Limits.MAX_LINE + 1] = '\n';
        SceneFormatException bad = assertThrows(SceneFormatException.class, () -> Parser.parse(line, "p.txt", new ArrayList<>()));
        assertEquals("p.txt:1: not UTF-8 text (byte 0xC3); expected a text scene file saved as UTF-8", bad.getMessage());
        // one more byte on that line and it is refused as too long
        byte[] longer = java.util.Arrays.copyOf(line, line.length + 1);
        longer[longer.length - 2] = 'x';
        longer[longer.length - 1] = '\n';
        SceneFormatException tooMany = assertThrows(SceneFormatException.class, () -> Parser.parse(longer, "p.txt", new ArrayList<>()));
        assertEquals("p.txt:1: line is longer than 65,536 characters (expected at most 65,536; is this a scene file?)", tooMany.getMessage());
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
