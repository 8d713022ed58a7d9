package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The OBJ reader's plain path ({@code ObjFile.readPlain}, no library) against the library's reading of
 * the same file ({@code ObjFile.readByLibrary}): on random files, plain and odd (comments after
 * statements, uppercase keywords, continuations, tabs, form feeds, NULs, non-ASCII, bad numbers and
 * indices, corners written differently, spaces around slashes), {@code ObjFile.read} gives the same
 * arrays bit for bit or the same message, and the plain path reads most of the valid files.
 */
class ObjPlainReadTest {

    @TempDir
    Path dir;

    private static final String[] KEYS = {"v", "vn", "vt", "f", "f", "f", "v", "vn", "V", "F", "VN", "vT", "g", "usemtl",
        "mtllib", "o", "s", "#", "", "vp", "l"};

    @Test
    void readsEveryFileAsTheLibraryDoes() throws IOException {
        Random r = new Random(20);
        Path p = dir.resolve("m.obj");
        int plain = 0, valid = 0;
        for (int k = 0; k < 6000; k++) {
            boolean clean = k % 2 == 0;
            byte[] data = file(r, clean);
            Files.write(p, data);
            String expected = outcome(p, true), got = outcome(p, false);
            String shown = new String(data, StandardCharsets.ISO_8859_1);
            assertEquals(expected, got, () -> shown);
            if (expected.startsWith("read")) {
                valid++;
                if (ObjFile.readPlain(p) != null) {
                    plain++;
                }
            }
        }
        assertTrue(valid > 500 && plain > valid / 2, "valid files " + valid + ", read plain " + plain);
    }

    /** The result's arrays, or the exception's class and message. */
    private static String outcome(Path p, boolean library) {
        try {
            ObjFile o = library ? ObjFile.readByLibrary(p, "m.obj") : ObjFile.read(p, "m.obj");
            int[] pos = new int[o.positions.length], nrm = new int[o.normals.length];
            for (int i = 0; i < pos.length; i++) {
                pos[i] = Float.floatToRawIntBits(o.positions[i]);
            }
            for (int i = 0; i < nrm.length; i++) {
                nrm[i] = Float.floatToRawIntBits(o.normals[i]);
            }
            return "read " + o.faces + " faces " + Arrays.toString(pos) + Arrays.toString(nrm) + Arrays.toString(o.triangles)
                    + Arrays.toString(o.cornerNormals);
        } catch (SceneFormatException | RuntimeException e) {
            return e.getClass().getName() + ": " + e.getMessage();
        }
    }

    private static String number(Random r, boolean clean) {
        switch (r.nextInt(clean ? 5 : 12)) {
            case 0: return String.format(Locale.ROOT, "%.6f", r.nextGaussian());
            case 1: return Float.toString((float) (r.nextGaussian() * Math.pow(10, r.nextInt(20) - 10)));
            case 2: return Integer.toString(r.nextInt(20) - 10);
            case 3: return "-0.000000";
            case 4: return String.format(Locale.ROOT, "%." + r.nextInt(12) + "f", r.nextGaussian() * Math.pow(10, r.nextInt(8) - 3));
            case 5: return Double.toString(r.nextGaussian() * Math.pow(10, r.nextInt(90) - 45));
            case 6: return r.nextBoolean() ? ".5" : "5.";
            case 7: return "+" + r.nextInt(1000) + "." + r.nextInt(100000);
            case 8: return "1e" + (r.nextInt(90) - 45);
            case 9: return r.nextBoolean() ? "0x1p0" : r.nextBoolean() ? "1f" : "NaN";
            case 10: return "0";
            default: return "-" + r.nextInt(99999999) + "." + r.nextInt(999);
        }
    }

    private static String index(Random r, int count, boolean clean) {
        switch (r.nextInt(clean ? 60 : 12)) {
            case 0: return Integer.toString(-1 - r.nextInt(count + 1));
            case 1: return "0";
            case 2: return r.nextBoolean() ? "2147483648" : "99999999999";
            case 3: return Integer.toString(1 + r.nextInt(count + 3));
            case 4: return "00" + (1 + r.nextInt(Math.max(1, count)));
            default: return Integer.toString(1 + r.nextInt(Math.max(1, count)));
        }
    }

    private static byte[] file(Random r, boolean clean) {
        StringBuilder sb = new StringBuilder();
        int vertices = 0, normals = 0, texCoords = 0;
        int shape = r.nextInt(4);
        boolean messy = r.nextInt(clean ? 8 : 3) == 0;
        String eol = r.nextInt(5) == 0 ? "\r\n" : r.nextInt(10) == 0 ? "\r" : "\n";
        if (r.nextInt(30) == 0) {
            sb.append('\uFEFF');
        }
        for (int l = 0, lines = 1 + r.nextInt(25); l < lines; l++) {
            String key = clean && r.nextInt(4) != 0 ? (vertices < 3 || r.nextBoolean() ? "v" : r.nextInt(3) == 0 ? "vn" : "f")
                    : KEYS[r.nextInt(KEYS.length)];
            StringBuilder line = new StringBuilder();
            if (messy && r.nextInt(5) == 0) {
                line.append(r.nextBoolean() ? " " : "\t");
            }
            line.append(key);
            if (key.equalsIgnoreCase("v") || key.equalsIgnoreCase("vn") || key.equalsIgnoreCase("vt")) {
                for (int i = 0, n = r.nextInt(10) == 0 ? r.nextInt(6) : 3; i < n; i++) {
                    line.append(messy && r.nextInt(6) == 0 ? "  " : " ").append(number(r, clean));
                }
                if (key.equals("v")) {
                    vertices++;
                } else if (key.equals("vn")) {
                    normals++;
                } else if (key.equals("vt")) {
                    texCoords++;
                }
            } else if (key.equalsIgnoreCase("f")) {
                for (int i = 0, n = r.nextInt(8) == 0 ? r.nextInt(3) : 3 + r.nextInt(3); i < n; i++) {
                    int s = messy && r.nextInt(3) == 0 ? r.nextInt(4) : shape;
                    line.append(messy && r.nextInt(8) == 0 ? "  " : " ").append(index(r, vertices, clean));
                    String slash = messy && r.nextInt(15) == 0 ? " / " : "/";
                    if (s == 1) {
                        line.append(slash).append(index(r, texCoords, clean));
                    } else if (s == 2) {
                        line.append("//").append(index(r, normals, clean));
                    } else if (s == 3) {
                        line.append(slash).append(index(r, texCoords, clean)).append('/').append(index(r, normals, clean));
                    }
                }
            } else if (key.equals("#")) {
                line.append(" comment ").append(r.nextBoolean() ? "\u00e9\u00a9" : "x");
            } else {
                line.append(" name").append(r.nextInt(3));
            }
            if (messy) {
                switch (r.nextInt(30)) {
                    case 0: line.append(" # after"); break;
                    case 1: line.append(" \\"); break;
                    case 2: line.append('\0'); break;
                    case 3: line.append('\f'); break;
                    case 4: line.append('\t'); break;
                    case 5: line.insert(0, '\u00a0'); break;
                    case 6: line.append(" \u00e9"); break;
                    case 7: line.insert(0, '\u2003'); break;
                    case 8: line.setLength(Math.max(0, line.length() - 1 - r.nextInt(3))); break;
                    default: break;
                }
            }
            sb.append(line).append(r.nextInt(40) == 0 ? "" : eol);
            if (r.nextInt(20) == 0) {
                sb.append(eol);
            }
        }
        byte[] b = sb.toString().getBytes(StandardCharsets.UTF_8);
        if (messy && r.nextInt(10) == 0 && b.length > 0) {
            b[r.nextInt(b.length)] = (byte) (0x80 + r.nextInt(128));
        }
        return b;
    }
}
