package ray.parse;

import de.javagl.obj.AbstractWritableObj;
import de.javagl.obj.FloatTuple;
import de.javagl.obj.ObjFace;
import de.javagl.obj.ObjReader;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.Reader;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Reads the polygon part of a Wavefront OBJ file (vertices {@code v}, normals {@code vn}, faces
 * {@code f} with {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn} corners, negative indices
 * counting back) with the de.javagl:obj library, checks what it reads, and splits each face of more
 * than three corners into a fan (corners 1, k, k+1). Texture coordinates are only counted (their
 * indices are checked); groups, materials and the other statements of the format are ignored, as
 * the OBJ specification (Wavefront, Appendix B1 of the Advanced Visualizer manual) allows a
 * polygon reader to do.
 *
 * <p>Every mistake is a {@link SceneFormatException} naming the OBJ file and its line: the library
 * reads through a reader that counts the lines it hands out, and each statement the library passes on
 * is checked against the line just read. The library reads coordinates as {@code float}s; they are
 * kept as such (a double is formed from them exactly).
 */
public final class ObjFile {

    /** Vertex positions, 3 floats each. */
    public final float[] positions;
    /** Vertex normals from {@code vn}, 3 floats each, as written (not normalised; never zero). */
    public final float[] normals;
    /** Triangles: 3 vertex indices (0-based) each, faces fanned, in file order. */
    public final int[] triangles;
    /** Per triangle corner the normal index (0-based), or -1; null when no face has normal indices. */
    public final int[] cornerNormals;
    /** Polygons read (before fanning). */
    public final int faces;

    private ObjFile(Builder b) {
        positions = Arrays.copyOf(b.pos, 3 * b.vertices);
        normals = Arrays.copyOf(b.nrm, 3 * b.normalCount);
        triangles = Arrays.copyOf(b.tri, 3 * b.triCount);
        cornerNormals = b.anyNormals ? Arrays.copyOf(b.triN, 3 * b.triCount) : null;
        faces = b.faces;
    }

    public int vertexCount() {
        return positions.length / 3;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    /**
     * Reads {@code mesh}'s OBJ file (its {@code file} field, relative to {@code folder}, the scene file's
     * folder) and hands the triangles to it. A file that cannot be opened, or a mesh the material refuses,
     * is an {@link IllegalArgumentException}; a mistake inside the file a {@link SceneFormatException}.
     */
    public static void loadInto(ray.surface.Mesh mesh, Path folder) throws SceneFormatException {
        Path path;
        try {
            Path rel = Path.of(mesh.file);
            // a scene reads files beside it only: never /etc/passwd, ../../secret or /proc/self/environ,
            // whose first line an error message would show (scenes are handed round and graded)
            if (rel.isAbsolute() || rel.normalize().startsWith("..") || rel.normalize().toString().isEmpty()) {
                throw new IllegalArgumentException("the OBJ file '" + mesh.file + "' is outside the scene file's folder (expected a path "
                        + "relative to the scene file, inside its folder, e.g. 'String file models/bunny.obj')");
            }
            path = folder.resolve(rel);
        } catch (java.nio.file.InvalidPathException e) {
            throw new IllegalArgumentException("'" + mesh.file + "' is not a file name this system accepts (expected an OBJ file's path)");
        }
        String shown = path.toString();
        ObjFile obj = read(path, shown);
        mesh.setTriangles(obj.positions, obj.normals, obj.triangles, obj.cornerNormals, shown);
    }

    /**
     * Reads {@code path}, naming it {@code shown} in messages. A file that cannot be opened is an
     * {@link IllegalArgumentException} (the scene line that names it is at fault); a mistake inside it
     * a {@link SceneFormatException} at its own line.
     */
    public static ObjFile read(Path path, String shown) throws SceneFormatException {
        if (Files.isDirectory(path)) {
            throw new IllegalArgumentException("cannot read the OBJ file " + shown + ": it is a directory (expected an OBJ file)");
        }
        String special = Parser.notRegular(path);
        if (special != null) {      // a FIFO waits for ever, /dev/zero never ends
            throw new IllegalArgumentException("cannot read the OBJ file " + shown + ": not a regular file (" + special
                    + "; expected an OBJ file)");
        }
        ray.io.InputFiles.read(path);
        ObjFile plain = readPlain(path);
        return plain != null ? plain : readByLibrary(path, shown);
    }

    /** Reads {@code path} line by line through the library, every line checked: what any file gets wrong is said here. */
    static ObjFile readByLibrary(Path path, String shown) throws SceneFormatException {
        LineReader reader = null;
        try (InputStream in = Files.newInputStream(path)) {
            reader = new LineReader(in);
            Builder b = new Builder(reader, shown);
            ObjReader.read(reader, b);
            b.finish();
            return new ObjFile(b);
        } catch (NoSuchFileException e) {
            throw new IllegalArgumentException("cannot read the OBJ file " + shown + ": no such file");
        } catch (AccessDeniedException e) {
            throw new IllegalArgumentException("cannot read the OBJ file " + shown + ": permission denied");
        } catch (Bad e) {
            throw new SceneFormatException(shown, e.line, e.getMessage());
        } catch (IOException | RuntimeException e) {
            // the library's own complaints (a number it cannot read), and anything else it throws on odd input
            int line = reader == null ? 0 : reader.line;
            if (reader == null) {
                throw new IllegalArgumentException("cannot read the OBJ file " + shown + ": " + Parser.describe(e));
            }
            throw new SceneFormatException(shown, line, "cannot read " + Values.quote(reader.text.strip()) + " ("
                    + expected(reader.text) + ")");
        }
    }

    /**
     * The file read without the library, when every line is one the library and the checks would take
     * as it reads them here: null at the first line that is not (or any mistake, or a file that cannot
     * be read), and {@link #read} reads the file again through the library, which says what is wrong
     * as it always has. The lines read here: blank lines; lines whose first word is not a statement
     * read (comments, groups, materials, ...); and lowercase {@code v}, {@code vn}, {@code vt} and
     * {@code f} statements of printable ASCII without a comment or a continuation, whose numbers are
     * plain decimals ({@link Tokens#decimalFloat}, {@code Float.parseFloat}'s value) and whose faces
     * write every corner alike as {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn} with
     * non-zero indices. Their values and checks are the library's and the {@link Builder}'s: the same
     * numbers, the same fan. No String, tokenizer or tuple per line.
     */
    static ObjFile readPlain(Path path) {
        try (InputStream in = Files.newInputStream(path)) {
            LineReader reader = new LineReader(in);
            reader.plain = true;
            Builder b = new Builder(reader, null);
            while (reader.readLine() != null) {
                if (!b.plainLine()) {
                    return null;
                }
            }
            b.finish();
            return new ObjFile(b);
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** What a statement of the line's keyword should look like. */
    static String expected(String line) {
        String s = line.strip();
        String key = s.isEmpty() ? "" : s.split("\\s+", 2)[0].toLowerCase();
        return switch (key) {
            case "v" -> "expected 'v x y z' with three finite decimal numbers";
            case "vn" -> "expected 'vn x y z' with three finite decimal numbers";
            case "vt" -> "expected 'vt u [v [w]]' with decimal numbers";
            case "f" -> "expected 'f' and at least three corners, each v, v/vt, v//vn or v/vt/vn with non-zero whole-number indices";
            default -> "expected an OBJ statement such as 'v x y z' or 'f 1 2 3'";
        };
    }

    /** A mistake found while checking what the library read, at the reader's current line. */
    private static final class Bad extends RuntimeException {
        private static final long serialVersionUID = 1L;
        final int line;

        Bad(int line, String message) {
            super(message, null, false, false);
            this.line = line;
        }
    }

    /**
     * Hands the library one line at a time and remembers which (the library reads only through
     * readLine). Lines are cut from the file's bytes as {@link BufferedReader#readLine} cuts them (at
     * {@code \n}, {@code \r} or {@code \r\n}) and decoded as UTF-8 with malformed bytes replaced, as an
     * {@code InputStreamReader} would: a line of ASCII bytes (every line of a usual OBJ file) becomes a
     * String by a plain copy. The checks read the line's chars from an array kept for the purpose, not
     * through {@code String.charAt} (a million-line file is read before the JIT's second tier).
     */
    private static final class LineReader extends BufferedReader {
        private final InputStream in;
        private byte[] buf = new byte[1 << 16];
        private int pos, end;
        private boolean eof, skipLF;
        int line;
        String text = "";
        /** The current line's chars, tabs as spaces (the library splits at spaces only), and their count. */
        char[] chars = new char[0];
        int length;
        /** The current line is all ASCII; it has a tab; it has a NUL. */
        private boolean ascii, tab, nul;
        /**
         * For a face line of printable ASCII without a comment, what {@link Builder#checkCorners} would
         * find in it: its corners (the words after the 'f') and their common pattern (1: texture index, 2:
         * normal index; -1 when they differ). {@link #cornersKnown} is false for any other line.
         */
        boolean cornersKnown;
        int cornerCount, cornerPattern;
        /** Read for {@link #readPlain}: an ASCII line is left in {@link #chars} only, without a String. */
        boolean plain;

        LineReader(InputStream in) {
            super(Reader.nullReader(), 1);
            this.in = in;
        }

        @Override
        public String readLine() throws IOException {
            String s = nextLine();
            if (s != null) {
                line++;
                if (ascii) {    // the chars are in place already, tabs as spaces
                    text = s;   // "" in plain mode
                    if (nul) {
                        throw new Bad(line, "binary data (byte 0x00), expected a text OBJ file");
                    }
                    if (tab) {
                        s = s.replace('\t', ' ');   // tabs separate like spaces (the library splits at spaces only)
                    }
                } else {
                    if (line == 1 && s.startsWith("\uFEFF")) {
                        s = s.substring(1);      // a UTF-8 byte-order mark (as the scene parser skips it)
                    }
                    text = s;
                    if (s.indexOf('\0') >= 0) {
                        throw new Bad(line, "binary data (byte 0x00), expected a text OBJ file");
                    }
                    s = s.replace('\t', ' ');
                    length = s.length();
                    if (length > chars.length) {
                        chars = new char[length];
                    }
                    s.getChars(0, length, chars, 0);
                }
                exact();
            }
            return s;
        }

        /**
         * The next line of the file without its terminator, or null at the end. A line of ASCII bytes
         * ({@link #ascii}) is also copied into {@link #chars}, tabs as spaces, in the same pass.
         */
        private String nextLine() throws IOException {
            int from = pos;
            boolean plain = true, tabs = false, zero = false;
            while (true) {
                byte[] b = buf;
                if (chars.length < b.length) {
                    chars = Arrays.copyOf(chars, b.length);
                }
                char[] ch = chars;
                int i = pos, e = end;
                if (skipLF && i < e) {
                    skipLF = false;
                    if (b[i] == '\n') {
                        from = ++i;
                    }
                }
                for (; i < e; i++) {
                    byte c = b[i];
                    if (c <= '\r') {   // the rare bytes: line ends, tab, NUL, and every non-ASCII byte
                        if (c == '\n' || c == '\r') {
                            pos = i + 1;
                            skipLF = c == '\r';
                            return line(b, from, i, plain, tabs, zero);
                        }
                        if (c == '\t') {
                            tabs = true;
                            c = ' ';
                        } else if (c == 0) {
                            zero = true;
                        } else if (c < 0) {
                            plain = false;
                        }
                    }
                    ch[i - from] = (char) c;
                }
                pos = i;
                if (!eof) {
                    boolean more = fill(from);
                    from = 0;     // fill moved the line's start to the front
                    if (more) {
                        continue;
                    }
                    eof = true;
                }
                return pos == from ? null : line(buf, from, pos, plain, tabs, zero);   // the last line, without a terminator
            }
        }

        private String line(byte[] b, int from, int to, boolean plainBytes, boolean tabs, boolean zero) {
            ascii = plainBytes;
            tab = tabs;
            nul = zero;
            length = to - from;
            if (plainBytes && plain) {
                return "";     // the chars are all readPlain reads
            }
            return new String(b, from, to - from, plainBytes ? StandardCharsets.ISO_8859_1 : StandardCharsets.UTF_8);
        }

        /**
         * Moves bytes [from, end) to the buffer's front (growing it when they fill it) and reads more after
         * them; false at the end of the file (the bytes moved all the same).
         */
        private boolean fill(int from) throws IOException {
            int kept = end - from;
            if (kept == buf.length) {
                buf = Arrays.copyOf(buf, 2 * buf.length);    // a line longer than the buffer
            } else if (from > 0) {
                System.arraycopy(buf, from, buf, 0, kept);
            }
            pos -= from;
            end = kept;
            int n = in.read(buf, end, buf.length - end);
            while (n == 0) {
                n = in.read(buf, end, buf.length - end);
            }
            if (n < 0) {
                return false;
            }
            end += n;
            return true;
        }

        /**
         * Reads numbers as the scene parser does, before the library does it more loosely: plain decimals
         * in v, vn and vt (no hex {@code 0x1p0}, no {@code 1f}/{@code 1d} suffix, no NaN), whole-number
         * indices in f that fit an int (99999999999 is not wrapped round to 1215752191). The words are the
         * line's runs of non-space characters up to a '#', after stripping (a scan of the characters: a
         * regex compiled per line cost a million-line file seconds).
         */
        private void exact() {
            cornersKnown = false;
            char[] t = chars;
            int n = length, hash = 0;
            boolean printable = ascii;
            while (hash < n && t[hash] != '#') {
                if (t[hash] < ' ') {
                    printable = false;
                }
                hash++;
            }
            int from = stripStart(t, 0, hash), to = stripEnd(t, from, hash);
            int key = from;
            while (key < to && t[key] != ' ') {
                key++;
            }
            boolean decimals;
            int k = key - from;
            char k0 = k > 0 ? t[from] : 0, k1 = k > 1 ? t[from + 1] : 0;
            if (k == 1 && k0 == 'v' || k == 2 && k0 == 'v' && (k1 == 'n' || k1 == 't')) {
                decimals = true;
            } else if (k == 1 && k0 == 'f') {
                decimals = false;
            } else {
                return;     // other statements are ignored
            }
            int corners = 0, pattern = 0;
            for (int i = key; i < to; ) {
                if (t[i] == ' ') {
                    i++;
                    continue;
                }
                int j = i;
                while (j < to && t[j] != ' ') {
                    j++;
                }
                if (decimals) {
                    if (!Tokens.isDecimal(t, i, j)) {
                        throw new Bad(line, "cannot read " + Values.quote(text.strip()) + " (" + expected(text) + ")");
                    }
                } else {
                    int s1 = -1, s2 = -1;       // the corner's first two slashes
                    for (int p = i; p <= j; ) {     // the corner's parts, split at '/' (empty parts kept)
                        int q = p;
                        while (q < j && t[q] != '/') {
                            q++;
                        }
                        if (q < j) {
                            if (s1 < 0) {
                                s1 = q;
                            } else if (s2 < 0) {
                                s2 = q;
                            }
                        }
                        if (tooLarge(t, p, q)) {
                            String part = new String(t, p, q - p);
                            throw new Bad(line, Values.quote(text.strip()) + " has the index " + part
                                    + ", beyond any file's vertices (expected indices from 1 to 2147483647, or negative ones counting back)");
                        }
                        p = q + 1;
                    }
                    // as checkCorners reads a corner: v, v/vt, v//vn, v/vt/vn
                    boolean hasT = s1 >= 0 && (s2 < 0 ? s1 + 1 < j : s2 > s1 + 1);
                    boolean hasN = s2 >= 0 && s2 + 1 < j;
                    int own = (hasT ? 1 : 0) | (hasN ? 2 : 0);
                    pattern = corners++ == 0 || pattern == own ? own : -1;
                }
                i = j;
            }
            // printable ASCII without '#': the words after the 'f' are exactly checkCorners's corners
            if (!decimals && printable && hash == n) {
                cornersKnown = true;
                cornerCount = corners;
                cornerPattern = pattern;
            }
        }

        /** The first index in [from, to) of a char that is not {@link Character#isWhitespace} ({@code String.strip}'s). */
        static int stripStart(char[] t, int from, int to) {
            while (from < to && Character.isWhitespace(t[from])) {
                from++;
            }
            return from;
        }

        /** One past the last index in [from, to) of a char that is not {@link Character#isWhitespace}. */
        static int stripEnd(char[] t, int from, int to) {
            while (to > from && Character.isWhitespace(t[to - 1])) {
                to--;
            }
            return to;
        }

        /** {@code t[from, to)} is a whole number (digits, perhaps after '-') beyond an int: the library would wrap it round. */
        private static boolean tooLarge(char[] t, int from, int to) {
            int i = from < to && t[from] == '-' ? from + 1 : from;
            if (to - i < 10) {
                return false;   // nine digits at most: an int, or not a number (the library's message says so)
            }
            for (int k = i; k < to; k++) {
                if (t[k] < '0' || t[k] > '9') {
                    return false;       // not a number at all: the library's own message says so
                }
            }
            while (i < to - 1 && t[i] == '0') {
                i++;        // leading zeros (keeping one digit)
            }
            if (to - i > 10) {
                return true;
            }
            long v = 0;
            for (int k = i; k < to; k++) {
                v = 10 * v + (t[k] - '0');
            }
            return v > Integer.MAX_VALUE;
        }
    }

    /** Receives the library's statements, checks them and keeps vertices, normals and fanned faces. */
    private static final class Builder extends AbstractWritableObj {
        private final LineReader reader;
        float[] pos = new float[3 * 1024], nrm = new float[0];
        int[] tri = new int[3 * 1024], triN = new int[3 * 1024];
        int vertices, normalCount, texCoords, triCount, faces;
        boolean anyNormals;
        /**
         * Faces referring to vertices not yet read (allowed: checked at the end), each one referring
         * further than all before it: (line, largest index) pairs. The first face out of range is one
         * of them.
         */
        int[] forward = new int[0];
        int forwardCount;

        Builder(LineReader reader, String shown) {
            this.reader = reader;
        }

        private Bad bad(String message) {
            return new Bad(reader.line, Values.quote(reader.text.strip()) + " " + message);
        }

        @Override
        public void addVertex(FloatTuple v) {
            int d = v.getDimensions();     // 1 to 4: a tuple has no y or z to read below 3
            vertex(d, v.getX(), d > 1 ? v.getY() : 0, d > 2 ? v.getZ() : 0);
        }

        /** A {@code v} statement of {@code d} numbers, the first three x, y, z. */
        private void vertex(int d, float x, float y, float z) {
            if (d < 3) {      // a fourth number (w, a weight for curves) is allowed and ignored
                throw coordinates(d, "v");
            }
            pos = append(pos, vertices++, x, y, z, "v");
        }

        @Override
        public void addNormal(FloatTuple n) {
            int d = n.getDimensions();
            normal(d, n.getX(), d > 1 ? n.getY() : 0, d > 2 ? n.getZ() : 0);
        }

        /** A {@code vn} statement of {@code d} numbers, the first three x, y, z. */
        private void normal(int d, float x, float y, float z) {
            if (d != 3) {
                throw coordinates(d, "vn");
            }
            if (x == 0 && y == 0 && z == 0) {
                throw bad("has length 0 (expected 'vn x y z', a direction)");
            }
            nrm = append(nrm, normalCount++, x, y, z, "vn");
        }

        private Bad coordinates(int d, String key) {
            return bad("has " + d + " coordinate" + (d == 1 ? "" : "s") + " (expected '" + key + " x y z')");
        }

        /** Checks x, y, z are finite and stores them as entry {@code i} of {@code a}, grown as needed. */
        private float[] append(float[] a, int i, float x, float y, float z, String key) {
            if (!Float.isFinite(x) || !Float.isFinite(y) || !Float.isFinite(z)) {
                throw bad("has a coordinate that is not a finite float (expected '" + key + " x y z', each within +-3.4e38)");
            }
            float[] out = 3 * i + 3 > a.length ? Arrays.copyOf(a, Math.max(3 * 1024, 2 * a.length)) : a;
            out[3 * i] = x;
            out[3 * i + 1] = y;
            out[3 * i + 2] = z;
            return out;
        }

        @Override
        public void addTexCoord(FloatTuple t) {
            texCoords++;
        }

        @Override
        public void addFace(ObjFace f) {
            int n = f.getNumVertices();
            boolean hasT = f.containsTexCoordIndices(), hasN = f.containsNormalIndices();
            int[] v = new int[n], vt = hasT ? new int[n] : null, vn = hasN ? new int[n] : null;
            for (int i = 0; i < n; i++) {
                v[i] = f.getVertexIndex(i);
                if (hasT) {
                    vt[i] = f.getTexCoordIndex(i);
                }
                if (hasN) {
                    vn[i] = f.getNormalIndex(i);
                }
            }
            face(n, v, vt, vn);
        }

        /**
         * A face of {@code n} corners: their vertex indices, texture coordinate and normal indices (null
         * when the face has none), all 0-based as the library makes them.
         */
        private void face(int n, int[] fv, int[] ft, int[] fn) {
            if (n < 3) {
                throw bad("has " + n + " corner" + (n == 1 ? "" : "s") + " (expected a face of at least three: 'f v1 v2 v3 ...')");
            }
            checkCorners(n, fn != null, ft != null);
            int max = -1;
            for (int i = 0; i < n; i++) {
                int v = fv[i];
                if (v < 0) {
                    throw bad("refers to a vertex before the first (expected indices 1 to " + vertices
                            + ", or -1 to -" + vertices + " counting back from this line)");
                }
                max = Math.max(max, v);
                if (fn != null) {
                    int vn = fn[i];
                    if (vn < 0 || vn >= normalCount) {
                        throw bad("refers to normal " + (vn + 1) + ", but " + normalCount + " normal"
                                + (normalCount == 1 ? " is" : "s are") + " given above it (expected 'vn' lines before the face)");
                    }
                }
                if (ft != null) {
                    int vt = ft[i];
                    if (vt < 0 || vt >= texCoords) {
                        throw bad("refers to texture coordinate " + (vt + 1) + ", but " + texCoords + (texCoords == 1 ? " is" : " are")
                                + " given above it (expected 'vt' lines before the face)");
                    }
                }
            }
            if (max >= vertices && (forwardCount == 0 || max > forward[2 * forwardCount - 1])) {
                if (2 * forwardCount + 2 > forward.length) {
                    forward = Arrays.copyOf(forward, Math.max(16, 2 * forward.length));
                }
                forward[2 * forwardCount] = reader.line;
                forward[2 * forwardCount++ + 1] = max;
            }
            faces++;
            boolean hasN = fn != null;
            anyNormals |= hasN;
            // fan: (0, k, k + 1)
            for (int k = 1; k + 1 < n; k++) {
                if (3 * triCount + 3 > tri.length) {
                    tri = Arrays.copyOf(tri, 2 * tri.length);
                    triN = Arrays.copyOf(triN, 2 * triN.length);
                }
                int o = 3 * triCount++;
                tri[o] = fv[0];
                tri[o + 1] = fv[k];
                tri[o + 2] = fv[k + 1];
                triN[o] = hasN ? fn[0] : -1;
                triN[o + 1] = hasN ? fn[k] : -1;
                triN[o + 2] = hasN ? fn[k + 1] : -1;
            }
        }

        /** The current face's corners for {@link #plainLine}, 0-based; grown as needed. */
        private int[] plainV = new int[8], plainT = new int[8], plainN = new int[8];
        /** The index {@link #index} read last. */
        private int number;

        /**
         * Takes the reader's current line as the library and this builder would (see {@link ObjFile#readPlain}),
         * or returns false when the line is not one of those read here. A mistake throws as the library's
         * reading would; readPlain then leaves the file to the library.
         */
        boolean plainLine() {
            char[] t = reader.chars;
            int from = 0, to = reader.length;
            while (from < to && t[from] <= ' ') {     // String.trim, as the library trims each line
                from++;
            }
            while (to > from && t[to - 1] <= ' ') {
                to--;
            }
            if (from == to) {
                return true;        // a blank line
            }
            if (t[to - 1] == '\\') {
                return false;       // continued on the next line
            }
            int key = from;
            while (key < to && t[key] != ' ') {
                if (t[key] < ' ') {
                    return false;       // a form feed or another control character: tokenized otherwise
                }
                key++;
            }
            int k = key - from;
            char c0 = t[from], c1 = k > 1 ? t[from + 1] : 0;
            int statement = k == 1 && c0 == 'v' ? 0 : k == 2 && c0 == 'v' && c1 == 'n' ? 1 : k == 2 && c0 == 'v' && c1 == 't' ? 2
                    : k == 1 && c0 == 'f' ? 3 : -1;
            if (statement < 0) {
                // the library lowercases the keyword: V, VN, Vt, F are statements too (read by the library);
                // no other character lowercases to these letters. Any other keyword it ignores.
                char l0 = (char) (c0 | 0x20), l1 = (char) (c1 | 0x20);
                return !(k == 1 && (l0 == 'v' || l0 == 'f') || k == 2 && l0 == 'v' && (l1 == 'n' || l1 == 't'));
            }
            for (int i = key; i < to; i++) {
                char c = t[i];
                if (c < ' ' || c > '~' || c == '#') {
                    return false;       // a comment the library would read as a word, or more than printable ASCII
                }
            }
            if (statement == 3) {
                return plainFace(t, key, to);
            }
            // the words: decimals all (exact() checked them), the first three read as the library reads them
            float x = 0, y = 0, z = 0;
            int words = 0;
            for (int i = key; i < to; ) {
                if (t[i] == ' ') {
                    i++;
                    continue;
                }
                int j = i;
                while (j < to && t[j] != ' ') {
                    j++;
                }
                if (words < 3) {
                    float f = Tokens.decimalFloat(t, i, j);
                    if (words == 0) {
                        x = f;
                    } else if (words == 1) {
                        y = f;
                    } else {
                        z = f;
                    }
                }
                words++;
                i = j;
            }
            if (words == 0) {
                return false;       // the library's tokenizer runs out: its own failure
            }
            if (statement == 0) {
                vertex(Math.min(words, 4), x, y, z);
            } else if (statement == 1) {
                normal(Math.min(words, 4), x, y, z);
            } else {
                texCoords++;
            }
            return true;
        }

        /**
         * A face whose corners are all written alike as {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn}
         * with non-zero indices, each followed by a space or the end: read as the library's face parser
         * reads it (indices made 0-based, negative ones counted back from the statements read so far);
         * false for any other face.
         */
        private boolean plainFace(char[] t, int i, int to) {
            int n = 0, shape = -1;
            while (i < to) {
                if (t[i] == ' ') {
                    i++;
                    continue;
                }
                if (n == plainV.length) {
                    plainV = Arrays.copyOf(plainV, 2 * n);
                    plainT = Arrays.copyOf(plainT, 2 * n);
                    plainN = Arrays.copyOf(plainN, 2 * n);
                }
                i = index(t, i, to);
                if (i < 0) {
                    return false;
                }
                plainV[n] = number < 0 ? vertices + number : number - 1;
                int own = 0;
                if (i < to && t[i] == '/') {
                    i++;
                    if (i < to && t[i] == '/') {
                        i = index(t, i + 1, to);
                        own = 2;
                    } else {
                        i = index(t, i, to);
                        if (i < 0) {
                            return false;
                        }
                        plainT[n] = number < 0 ? texCoords + number : number - 1;
                        own = 1;
                        if (i < to && t[i] == '/') {
                            i = index(t, i + 1, to);
                            own = 3;
                        }
                    }
                    if (i < 0) {
                        return false;
                    }
                    if (own >= 2) {
                        plainN[n] = number < 0 ? normalCount + number : number - 1;
                    }
                }
                if (i < to && t[i] != ' ' || shape >= 0 && own != shape) {
                    return false;
                }
                shape = own;
                n++;
            }
            face(n, plainV, (shape & 1) != 0 ? plainT : null, (shape & 2) != 0 ? plainN : null);
            return true;
        }

        /**
         * Reads a non-zero index ({@code -}? digits, within an int) at {@code i} into {@link #number}; returns
         * the index after it, or -1 when there is none.
         */
        private int index(char[] t, int i, int to) {
            boolean neg = i < to && t[i] == '-';
            int j = neg ? i + 1 : i;
            long v = 0;
            int start = j;
            while (j < to && t[j] >= '0' && t[j] <= '9' && j - start < 11) {
                v = 10 * v + (t[j] - '0');
                j++;
            }
            if (j == start || v == 0 || v > Integer.MAX_VALUE || j < to && t[j] >= '0' && t[j] <= '9') {
                return -1;
            }
            number = neg ? (int) -v : (int) v;
            return j;
        }

        /**
         * Every corner of a face written alike: the library fills the indices a corner leaves out with
         * those of an earlier face, so {@code f 1//1 2 3} would silently borrow normals.
         */
        private void checkCorners(int n, boolean normals, boolean texCoords) {
            if (reader.cornersKnown) {      // found by the line's own check
                if (reader.cornerCount == n && reader.cornerPattern != ((texCoords ? 1 : 0) | (normals ? 2 : 0))) {
                    throw bad("writes its corners differently (expected every corner as v, v/vt, v//vn or v/vt/vn alike)");
                }
                return;
            }
            char[] c = reader.chars;
            int len = reader.length;
            int from = LineReader.stripStart(c, 0, len), to = LineReader.stripEnd(c, from, len);
            if (from == to) {
                throw new IllegalStateException("an empty line continues a face");   // read as the library's failure
            }
            from = LineReader.stripStart(c, from + 1, to);      // after the 'f'
            // the corners: runs of characters other than regex \s (scanned: no regex per face)
            int count = from == to ? 1 : 0;
            for (int i = from; i < to; ) {
                int j = cornerEnd(c, i, to);
                count++;
                i = skipSpace(c, j, to);
            }
            if (count != n) {
                return;    // written with spaces around the slashes: the library's own reading stands
            }
            for (int i = from; i < to || (i == from && from == to); ) {
                int end = cornerEnd(c, i, to);
                int a = i;
                while (a < end && c[a] != '/') {
                    a++;
                }
                a = a < end ? a : -1;
                int b = -1;
                if (a >= 0) {
                    b = a + 1;
                    while (b < end && c[b] != '/') {
                        b++;
                    }
                    b = b < end ? b : -1;
                }
                boolean hasT = a >= 0 && (b < 0 ? a + 1 < end : b > a + 1);
                boolean hasN = b >= 0 && b + 1 < end;
                if (hasT != texCoords || hasN != normals) {
                    throw bad("writes its corners differently (expected every corner as v, v/vt, v//vn or v/vt/vn alike)");
                }
                if (from == to) {
                    break;
                }
                i = skipSpace(c, end, to);
            }
        }

        /** The end of the corner starting at {@code i}: the next regex {@code \s} character, or {@code to}. */
        private static int cornerEnd(char[] c, int i, int to) {
            while (i < to && !space(c[i])) {
                i++;
            }
            return i;
        }

        private static int skipSpace(char[] c, int i, int to) {
            while (i < to && space(c[i])) {
                i++;
            }
            return i;
        }

        /** Regex {@code \s}: space, tab, newline, vertical tab, form feed, carriage return. */
        private static boolean space(char ch) {
            return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\u000B' || ch == '\f' || ch == '\r';
        }

        void finish() {
            for (int i = 0; i < forwardCount; i++) {
                if (forward[2 * i + 1] >= vertices) {
                    throw new Bad(forward[2 * i], "a face refers to vertex " + (forward[2 * i + 1] + 1) + ", but the file has "
                            + vertices + " vert" + (vertices == 1 ? "ex" : "ices") + " (expected indices 1 to " + vertices + ")");
                }
            }
        }
    }
}
