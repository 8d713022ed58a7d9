package ray.parse;

import java.io.IOException;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import javax.vecmath.Vector3d;
import ray.Camera;
import ray.Scene;
import ray.SceneObject;
import ray.light.Light;
import ray.material.Material;
import ray.surface.Surface;

/**
 * Reads the scene format ({@code docs/scene-format.md}): object headers
 * {@code <ObjectType> <ClassName> [name]}, parameter lines {@code <type> <field> <value>} written
 * straight into the object's field, a blank line ending an object, global settings and {@code #}
 * comments. Every mistake is a {@link SceneFormatException} naming the file and line; nothing else
 * escapes. One parser reads one file; its state (the named objects) lives in the instance.
 */
public final class Parser {

    private static final Set<String> GLOBALS = Set.of("BGColor", "AmbientLight", "Width", "Height", "AASamples", "MaxDepth");
    private static final Set<String> TYPES = Set.of("int", "double", "String", "ref", "Vector3d");

    private final String file;
    private final ClassResolver resolver = new ClassResolver(Parser.class.getClassLoader());
    private final Fields fields = new Fields();
    private final Scene scene = new Scene();
    private final Map<String, Object> named = new HashMap<>();
    private final Map<String, Integer> globalLines = new HashMap<>();
    /** Header type to class name to class, and classes to constructors: resolved once per file. */
    private final Map<String, Map<String, Class<?>>> resolved = new HashMap<>();
    private final Map<Class<?>, Constructor<?>> constructors = new HashMap<>();
    private final List<String> warnings = new ArrayList<>();

    // the object being read
    private Object current;
    private String currentType;
    private int currentLine;
    /** Names of the fields the current object has set so far (few: a linear search, no allocation). */
    private String[] currentFields = new String[8];
    private int currentFieldCount;
    private int cameraLine;
    private int degenerate;
    private int firstDegenerateLine;

    private int line;

    private Parser(String file) {
        this.file = file;
    }

    /** Reads and parses {@code path}; the file is named in messages as given. */
    public static Scene parse(Path path) throws SceneFormatException {
        return parse(path, new ArrayList<>());
    }

    /** As {@link #parse(Path)}, adding warnings (e.g. zero-area triangles) as {@code file:line: warning: ...}. */
    public static Scene parse(Path path, List<String> warnings) throws SceneFormatException {
        String name = path.toString();
        byte[] bytes;
        try {
            if (Files.isDirectory(path)) {
                throw new SceneFormatException(name, 0, "is a directory, not a scene file");
            }
            bytes = Files.readAllBytes(path);
        } catch (NoSuchFileException e) {
            throw new SceneFormatException(name, 0, "no such file");
        } catch (IOException | OutOfMemoryError | SecurityException e) {
            throw new SceneFormatException(name, 0, "cannot be read (" + e.getClass().getSimpleName()
                    + (e.getMessage() == null ? "" : ": " + e.getMessage()) + ")");
        }
        return parse(bytes, name, warnings);
    }

    /** Parses a scene file's bytes (UTF-8 text); {@code name} is used in messages. */
    public static Scene parse(byte[] bytes, String name, List<String> warnings) throws SceneFormatException {
        // The common case first: plain ASCII. Decoding with replacement gives as many chars as bytes and
        // no U+FFFD only when every byte is ASCII (a multi-byte sequence gives fewer chars, a malformed
        // one U+FFFD); both checks are vectorised in the JDK, where the strict decoder below is not.
        String ascii = new String(bytes, StandardCharsets.UTF_8);
        if (ascii.length() == bytes.length && ascii.indexOf('\uFFFD') < 0) {
            int nul = ascii.indexOf(0);
            if (nul >= 0) {
                throw new SceneFormatException(name, lineOf(bytes, nul), "binary data (a NUL byte) in what should be a text scene file");
            }
            return parse(ascii, bytes, name, warnings);
        }
        for (int i = 0; i < bytes.length; i++) {
            if (bytes[i] == 0) {
                throw new SceneFormatException(name, lineOf(bytes, i), "binary data (a NUL byte) in what should be a text scene file");
            }
        }
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new SceneFormatException(name, 1, "not UTF-8 text (is this a scene file?)");
        }
        return parse(text, name, warnings);
    }

    /** Parses scene text; {@code name} is used in messages. */
    public static Scene parse(String text, String name, List<String> warnings) throws SceneFormatException {
        return parse(text, null, name, warnings);
    }

    /** {@code ascii}: the text's bytes when it is plain ASCII (one byte per char), for the fast path; else null. */
    private static Scene parse(String text, byte[] ascii, String name, List<String> warnings) throws SceneFormatException {
        Parser p = new Parser(name);
        try {
            Scene s = p.run(text, ascii);
            warnings.addAll(p.warnings);
            return s;
        } catch (StackOverflowError | OutOfMemoryError e) {
            throw new SceneFormatException(name, p.line, "scene too large or too deeply nested to read ("
                    + e.getClass().getSimpleName() + ")");
        }
    }

    private static int lineOf(byte[] b, int end) {
        int n = 1;
        for (int i = 0; i < end; i++) {
            if (b[i] == '\n') {
                n++;
            }
        }
        return n;
    }

    private Scene run(String text, byte[] ascii) throws SceneFormatException {
        Prescan pre = ascii != null && ascii.length >= Prescan.MIN_BYTES && Runtime.getRuntime().availableProcessors() > 1
                ? new Prescan(text, ascii) : null;
        try {
            if (pre != null) {
                pre.start();
            }
            return run(text, ascii, pre);
        } finally {
            if (pre != null) {
                pre.stop = true;
            }
        }
    }

    // the line loop's state, in fields so that the loop itself is tiny: the interpreter runs a loop
    // for tens of thousands of iterations before the JIT replaces it, but compiles a method called
    // a few hundred times, so the work of a line goes in readLine
    private String text;
    private byte[] ascii;
    private Prescan pre;
    private Prescan.Chunk chunk;
    private int chunkIndex;
    private boolean any;

    private Scene run(String text, byte[] ascii, Prescan pre) throws SceneFormatException {
        this.text = text;
        this.ascii = ascii;
        this.pre = pre;
        int pos = 0, len = text.length();
        while (pos < len || (pos == len && line == 0)) {
            pos = readLine(pos, len);
        }
        endObject();
        if (!any) {
            throw new SceneFormatException(file, Math.max(1, line), "empty scene file (expected Width, Height and a Camera at least)");
        }
        return finish();
    }

    /** Reads the line starting at {@code pos}; returns where the next one starts. */
    private int readLine(int pos, int len) throws SceneFormatException {
        int end;
        Vector3d vec = null;
        long spaces = 0;
        if (pre != null) {
            if (chunk == null || chunkIndex == chunk.count) {
                chunk = pre.next();
                chunkIndex = 0;
            }
            end = chunk.end[chunkIndex];
            vec = chunk.vec[chunkIndex];
            spaces = chunk.spaces[chunkIndex];
            chunkIndex++;
        } else {
            end = text.indexOf('\n', pos);
            if (end < 0) {
                end = len;
            }
        }
        line++;
        if (end - pos > Limits.MAX_LINE) {
            throw error("line is " + (end - pos) + " characters long (at most " + Limits.MAX_LINE + " expected)");
        }
        if (vec != null && fastVector(ascii, pos, end, spaces, vec)) {
            any = true;
            return end + 1;
        }
        if (ascii != null && fastLine(ascii, pos, end)) {
            any |= end > pos;
            return end + 1;
        }
        String raw = text.substring(pos, end);
        String[] words = Tokens.canonicalWords(raw);
        if (words != null) {      // the common case: no comment, single spaces, nothing to strip
            any = true;
            statement(raw, words);
            return end + 1;
        }
        String st = stripComment(raw).strip();
        if (st.isEmpty()) {
            if (raw.strip().isEmpty()) {
                endObject();          // a blank line ends the object; a comment line does not
            }
            return end + 1;
        }
        any = true;
        statement(st, Tokens.split(st, false, 3));
        return end + 1;
    }

    /** Drops a comment: a '#' at the start of the line or after whitespace. */
    private static String stripComment(String s) {
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) == '#' && (i == 0 || Character.isWhitespace(s.charAt(i - 1)))) {
                return s.substring(0, i);
            }
        }
        return s;
    }

    private void statement(String s, String[] tok) throws SceneFormatException {
        String head = tok[0];
        if (current != null && TYPES.contains(head)) {
            parameter(tok, s);
        } else if (ClassResolver.BASES.containsKey(head)) {
            endObject();   // a header right after an object also ends it
            header(tok);
        } else if (GLOBALS.contains(head)) {
            endObject();
            global(head, s.substring(head.length()).strip());
        } else if (TYPES.contains(head)) {
            throw error("parameter line outside an object (expected an object header such as 'Surface Sphere' above it, with no blank line between)");
        } else if (current != null) {
            throw error("unknown parameter type '" + head + "' (expected int, double, String, ref or Vector3d)");
        } else {
            throw error("unknown keyword '" + head + "' (expected Camera, Surface, Material, Light or a global: "
                    + "BGColor, AmbientLight, Width, Height, AASamples, MaxDepth)");
        }
    }

    // ---- the fast path: plain lines of an ASCII file, read from its bytes ----

    private static final String[] HEADS = {"Vector3d", "double", "ref"};
    private static final String[] BASES = {"Surface", "Material", "Light", "Camera"};

    /** Per class: the field names seen on plain lines, as bytes, with their Field. */
    private final Map<Class<?>, List<Object[]>> fastFields = new HashMap<>();
    /** The last plain words looked up: a header's class name, a ref's object name (a name never changes its object). */
    private byte[] lastClassBytes, lastRefBytes;
    private String lastClassName, lastRefName;
    private Object lastRefTarget;

    /**
     * Reads line [from, to) of an ASCII file straight from its bytes when it is one of the three kinds
     * a large scene consists of, written plainly (printable ASCII, single spaces, no comment, nothing to
     * strip): a blank line, an object header of two words, or a Vector3d, double or ref parameter of
     * the current object. Returns false, having changed nothing, for any other line and for any line
     * with a mistake: the general path then reads it and gives the same result or the same message.
     * It does what {@link #statement} would do with the same words, without a String per word.
     */
    private boolean fastLine(byte[] b, int from, int to) throws SceneFormatException {
        if (from == to) {
            endObject();        // a blank line ends the object
            return true;
        }
        long spaces = plainSpaces(b, from, to);
        if (spaces < 0) {
            return false;
        }
        int s1 = (int) (spaces >>> 32) - 1, s2 = (int) spaces - 1;
        if (s1 < 0) {
            return false;
        }
        if (s2 < 0) {
            // two words: a header "Surface Triangle"
            for (String base : BASES) {
                if (equals(b, from, s1, base)) {
                    if (lastClassBytes == null || !equals(b, s1 + 1, to, lastClassBytes)) {
                        lastClassBytes = java.util.Arrays.copyOfRange(b, s1 + 1, to);
                        lastClassName = new String(lastClassBytes, StandardCharsets.ISO_8859_1);
                    }
                    endObject();
                    header(new String[] {base, lastClassName});
                    return true;
                }
            }
            return false;
        }
        if (current == null) {
            return false;
        }
        String head = null;
        for (String h : HEADS) {
            if (equals(b, from, s1, h)) {
                head = h;
            }
        }
        if (head == null) {
            return false;
        }
        Object[] field = fastField(b, s1 + 1, s2);
        if (field == null || fieldSet((String) field[1])) {
            return false;
        }
        String fieldName = (String) field[1];
        Field f = (Field) field[2];
        Class<?> ft = f.getType();
        int v0 = s2 + 1;
        Object v;
        if (head == HEADS[0]) {                                  // Vector3d
            if (field[4] != Boolean.TRUE) {
                return false;
            }
            double[] xyz = Tokens.canonicalVector(b, v0, to);
            if (xyz == null) {
                return false;
            }
            v = new Vector3d(xyz[0], xyz[1], xyz[2]);
        } else if (head == HEADS[1]) {                           // double
            if (!(ft == double.class || ft == Double.class || ft == float.class || ft == Float.class)
                    || !Tokens.isDecimal(b, v0, to)) {
                return false;
            }
            double d = Tokens.parseDecimal(b, v0, to);
            if (!Double.isFinite(d)) {
                return false;
            }
            v = (ft == float.class || ft == Float.class) ? (Object) (float) d : (Object) d;
        } else {                                                 // ref: one word, a name defined earlier
            if (ft.isPrimitive() || ft == String.class) {
                return false;
            }
            if (lastRefBytes == null || !equals(b, v0, to, lastRefBytes)) {
                String name = new String(b, v0, to - v0, StandardCharsets.ISO_8859_1);
                Object target = named.get(name);
                if (target == null) {
                    return false;
                }
                lastRefBytes = java.util.Arrays.copyOfRange(b, v0, to);
                lastRefName = name;
                lastRefTarget = target;
            }
            if (!ft.isInstance(lastRefTarget)) {
                return false;
            }
            v = lastRefTarget;
        }
        addField(fieldName);
        try {
            ((Setter) field[3]).set(f, current, v);
        } catch (IllegalAccessException | RuntimeException e) {
            throw error("cannot set field '" + fieldName + "': " + describe(e));
        }
        return true;
    }

    /**
     * Whether non-empty line [from, to) is plain (printable ASCII and single spaces, no '#', no space at
     * either end): -1 if not, else the positions of its first two spaces (each -1 when absent), plus
     * one, packed as (s1 + 1) << 32 | (s2 + 1).
     */
    static long plainSpaces(byte[] b, int from, int to) {
        if (b[from] == ' ' || b[to - 1] == ' ') {
            return -1;
        }
        int s1 = -1, s2 = -1;
        for (int i = from; i < to; i++) {
            byte c = b[i];
            if (c == ' ') {
                if (b[i - 1] == ' ') {
                    return -1;
                }
                if (s1 < 0) {
                    s1 = i;
                } else if (s2 < 0) {
                    s2 = i;
                }
            } else if (c < 0x21 || c > 0x7E || c == '#') {
                return -1;
            }
        }
        return (long) (s1 + 1) << 32 | (s2 + 1);
    }

    /**
     * {@link #fastLine} for a plain {@code Vector3d <field> [x y z]} line whose vector the prescan has
     * already read: the same checks and the same effect, or false with nothing changed.
     */
    private boolean fastVector(byte[] b, int from, int to, long spaces, Vector3d v) throws SceneFormatException {
        if (current == null) {
            return false;
        }
        int s1 = (int) (spaces >>> 32) - 1, s2 = (int) spaces - 1;
        Object[] field = fastField(b, s1 + 1, s2);
        if (field == null || fieldSet((String) field[1])) {
            return false;
        }
        String fieldName = (String) field[1];
        Field f = (Field) field[2];
        if (field[4] != Boolean.TRUE) {
            return false;
        }
        addField(fieldName);
        try {
            ((Setter) field[3]).set(f, current, v);
        } catch (IllegalAccessException | RuntimeException e) {
            throw error("cannot set field '" + fieldName + "': " + describe(e));
        }
        return true;
    }

    /**
     * Reads a large ASCII file's lines ahead, on a second core, while the parser works through them:
     * where each line ends, and for plain {@code Vector3d <field> [x y z]} lines the vector (three
     * quarters of a triangle mesh's lines). Everything it computes depends on the bytes alone; the
     * parser still makes every decision, in line order, and reads any line the prescan did not (or
     * any line whose vector it cannot use) exactly as without it.
     */
    static final class Prescan extends Thread {
        static final int MIN_BYTES = 1 << 22;
        static final int CHUNK = 4096;

        static final class Chunk {
            final int[] end = new int[CHUNK];
            final long[] spaces = new long[CHUNK];
            final Vector3d[] vec = new Vector3d[CHUNK];
            int count;
        }

        private final String text;
        private final byte[] b;
        private final java.util.concurrent.LinkedBlockingQueue<Object> out = new java.util.concurrent.LinkedBlockingQueue<>();
        volatile boolean stop;

        Prescan(String text, byte[] b) {
            super("scene-prescan");
            setDaemon(true);
            this.text = text;
            this.b = b;
        }

        @Override
        public void run() {
            try {
                int pos = 0, len = b.length, lines = 0;
                // the same line iteration as the parser's, a chunk at a time (a method per chunk, so
                // the JIT compiles it early; see Parser.readLine)
                while ((pos < len || (pos == len && lines == 0)) && !stop) {
                    Chunk c = new Chunk();
                    pos = fill(c, pos, len, lines);
                    lines += c.count;
                    out.add(c);
                }
            } catch (RuntimeException | Error e) {
                out.add(e);
            }
        }

        /** Fills {@code c} with up to CHUNK lines from {@code pos}; returns where the next line starts. */
        private int fill(Chunk c, int pos, int len, int lines) {
            while (c.count < CHUNK && (pos < len || (pos == len && lines + c.count == 0))) {
                pos = scanLine(c, pos, len);
            }
            return pos;
        }

        private int scanLine(Chunk c, int pos, int len) {
            int end = text.indexOf('\n', pos);
            if (end < 0) {
                end = len;
            }
            int k = c.count++;
            c.end[k] = end;
            if (end - pos > 9 && end - pos <= Limits.MAX_LINE && b[pos] == 'V' && Parser.equals(b, pos, pos + 9, "Vector3d ")) {
                long spaces = plainSpaces(b, pos, end);
                int s2 = (int) spaces - 1;
                if (spaces >= 0 && s2 >= 0) {
                    double[] xyz = Tokens.canonicalVector(b, s2 + 1, end);
                    if (xyz != null) {
                        c.spaces[k] = spaces;
                        c.vec[k] = new Vector3d(xyz[0], xyz[1], xyz[2]);
                    }
                }
            }
            return end + 1;
        }

        /** The next chunk of lines, waiting for it if need be. */
        Chunk next() {
            Object o;
            try {
                o = out.take();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while reading the scene", e);
            }
            if (o instanceof Chunk) {
                return (Chunk) o;
            }
            if (o instanceof Error) {
                throw (Error) o;
            }
            throw (RuntimeException) o;
        }
    }

    /** {bytes, name, Field, Setter, takes a Vector3d} of the current object's field named by b[from, to), or null if it has none (the general path reports it). */
    private Object[] fastField(byte[] b, int from, int to) {
        Class<?> c = current.getClass();
        List<Object[]> known = fastFields.get(c);
        if (known == null) {
            known = new ArrayList<>();
            fastFields.put(c, known);
        }
        for (Object[] e : known) {
            if (equals(b, from, to, (byte[]) e[0])) {
                return e;
            }
        }
        String name = new String(b, from, to - from, StandardCharsets.ISO_8859_1);
        Field f;
        try {
            f = fields.find(c, name);
        } catch (ClassResolver.Problem p) {
            return null;
        }
        Object[] e = {java.util.Arrays.copyOfRange(b, from, to), name, f, setterFor(c, f),
            f.getType().isAssignableFrom(Vector3d.class)};   // (a native call: asked once per field)
        known.add(e);
        return e;
    }

    private static boolean equals(byte[] b, int from, int to, String s) {
        if (to - from != s.length()) {
            return false;
        }
        for (int i = 0; i < s.length(); i++) {
            if (b[from + i] != s.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    private static boolean equals(byte[] b, int from, int to, byte[] w) {
        return java.util.Arrays.equals(b, from, to, w, 0, w.length);
    }

    private boolean fieldSet(String name) {
        for (int i = 0; i < currentFieldCount; i++) {
            String f = currentFields[i];
            if (f == name || f.equals(name)) {
                return true;
            }
        }
        return false;
    }

    private void addField(String name) {
        if (currentFieldCount == currentFields.length) {
            currentFields = java.util.Arrays.copyOf(currentFields, 2 * currentFieldCount);
        }
        currentFields[currentFieldCount++] = name;
    }

    /**
     * Sets a field found by {@link Fields#find}: reflection in general; for the fields of the built-in
     * classes that large scenes are made of, a plain assignment (exactly those classes, not subclasses,
     * which may declare fields of the same name). A class with a switch rather than lambdas: each
     * lambda's first use links through method handles, milliseconds of every start-up.
     */
    private static final class Setter {
        static final int REFLECT = 0, TRIANGLE_V0 = 1, TRIANGLE_V1 = 2, TRIANGLE_V2 = 3, SPHERE_CENTER = 4, MATERIAL = 5;
        static final Setter REFLECTIVE = new Setter(REFLECT);
        final int kind;

        Setter(int kind) {
            this.kind = kind;
        }

        void set(Field f, Object o, Object v) throws IllegalAccessException {
            switch (kind) {
                case TRIANGLE_V0: ((ray.surface.Triangle) o).v0 = (Vector3d) v; break;
                case TRIANGLE_V1: ((ray.surface.Triangle) o).v1 = (Vector3d) v; break;
                case TRIANGLE_V2: ((ray.surface.Triangle) o).v2 = (Vector3d) v; break;
                case SPHERE_CENTER: ((ray.surface.Sphere) o).center = (Vector3d) v; break;
                case MATERIAL: ((Surface) o).material = (Material) v; break;
                default: f.set(o, v);
            }
        }
    }

    private static Setter setterFor(Class<?> c, Field f) {
        if (c == ray.surface.Triangle.class && f.getDeclaringClass() == ray.surface.Triangle.class) {
            switch (f.getName()) {
                case "v0": return new Setter(Setter.TRIANGLE_V0);
                case "v1": return new Setter(Setter.TRIANGLE_V1);
                case "v2": return new Setter(Setter.TRIANGLE_V2);
                default: return Setter.REFLECTIVE;
            }
        }
        if (c == ray.surface.Sphere.class && f.getDeclaringClass() == ray.surface.Sphere.class && f.getName().equals("center")) {
            return new Setter(Setter.SPHERE_CENTER);
        }
        if ((c == ray.surface.Triangle.class || c == ray.surface.Sphere.class) && f.getDeclaringClass() == Surface.class
                && f.getName().equals("material")) {
            return new Setter(Setter.MATERIAL);
        }
        return Setter.REFLECTIVE;
    }

    // ---- objects ----

    private void header(String[] tok) throws SceneFormatException {
        String type = tok[0];
        if (tok.length < 2) {
            throw error("'" + type + "' needs a class name (expected '" + type + " <ClassName> [name]', e.g. '"
                    + type + " " + ClassResolver.builtIns(type).split(",")[0] + "')");
        }
        String[] rest = tok.length == 3 ? Tokens.split(tok[2], false, 0) : new String[0];
        if (rest.length > 1) {
            throw error("too many words in the header (expected '" + type + " <ClassName> [name]')");
        }
        Map<String, Class<?>> ofType = resolved.get(type);
        if (ofType == null) {
            ofType = new HashMap<>();
            resolved.put(type, ofType);
        }
        Class<?> c = ofType.get(tok[1]);
        if (c == null) {
            try {
                c = resolver.resolve(type, tok[1]);
            } catch (ClassResolver.Problem p) {
                throw error(p.getMessage());
            }
            ofType.put(tok[1], c);
        }
        String name = rest.length == 1 ? rest[0] : null;
        if (name != null && named.containsKey(name)) {
            throw error("the name '" + name + "' is already used by an earlier object (names must be unique in a file)");
        }
        Object o;
        try {
            if (c == ray.surface.Triangle.class) {
                o = new ray.surface.Triangle();    // the class most objects of a large scene have: no reflection
            } else {
                Constructor<?> k = constructors.get(c);
                if (k == null) {
                    k = c.getConstructor();
                    constructors.put(c, k);
                }
                o = k.newInstance();
            }
        } catch (InvocationTargetException e) {
            throw error("creating " + tok[1] + " failed: " + describe(e.getCause()));
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            throw error("creating " + tok[1] + " failed: " + describe(e));
        }
        current = o;
        currentType = type;
        currentLine = line;
        currentFieldCount = 0;
        if (name != null) {
            named.put(name, o);
        }
    }

    private void parameter(String[] tok, String s) throws SceneFormatException {
        String type = tok[0];
        if (tok.length < 3) {
            throw error("incomplete parameter line (expected '" + type + " <field> <value>')");
        }
        String fieldName = tok[1], value = tok[2].strip();
        Field f;
        try {
            f = fields.find(current.getClass(), fieldName);
        } catch (ClassResolver.Problem p) {
            throw error(p.getMessage());
        }
        if (fieldSet(fieldName)) {
            throw error("field '" + fieldName + "' is set twice in this object");
        }
        addField(fieldName);
        Class<?> ft = f.getType();
        Object v;
        switch (type) {
            case "int":
                requireFieldType(ft == int.class || ft == Integer.class || ft == long.class || ft == Long.class, type, f);
                int iv = parseInt(value, fieldName);
                v = (ft == long.class || ft == Long.class) ? (Object) (long) iv : (Object) iv;
                break;
            case "double":
                requireFieldType(ft == double.class || ft == Double.class || ft == float.class || ft == Float.class, type, f);
                double dv = parseDouble(value, fieldName);
                v = (ft == float.class || ft == Float.class) ? (Object) (float) dv : (Object) dv;
                break;
            case "String":
                requireFieldType(ft == String.class, type, f);
                v = value;
                break;
            case "Vector3d":
                requireFieldType(ft.isAssignableFrom(Vector3d.class), type, f);
                v = parseVector(value, fieldName);
                break;
            default:   // ref
                requireFieldType(!ft.isPrimitive() && ft != String.class, type, f);
                if (Tokens.split(value, false, 0).length > 1) {
                    throw error("'ref " + fieldName + "' takes one object name, got '" + value + "'");
                }
                Object target = named.get(value);
                if (target == null) {
                    throw error("undefined object '" + value + "' (expected the name of an object declared earlier in the file"
                            + (named.isEmpty() ? "; none has a name yet)" : ", such as " + someNames() + ")"));
                }
                if (!ft.isInstance(target)) {
                    throw error("'" + value + "' is a " + target.getClass().getSimpleName() + ", but field '" + fieldName
                            + "' needs a " + ft.getSimpleName());
                }
                v = target;
        }
        try {
            f.set(current, v);
        } catch (IllegalAccessException | RuntimeException e) {
            throw error("cannot set field '" + fieldName + "': " + describe(e));
        }
    }

    private void requireFieldType(boolean ok, String type, Field f) throws SceneFormatException {
        if (!ok) {
            throw error("field '" + f.getName() + "' of " + current.getClass().getSimpleName() + " is a "
                    + f.getType().getSimpleName() + ", not " + ("ref".equals(type) ? "an object reference" : type)
                    + " (expected '" + keywordFor(f.getType()) + " " + f.getName() + " ...')");
        }
    }

    private static String keywordFor(Class<?> t) {
        if (t == int.class || t == Integer.class || t == long.class || t == Long.class) return "int";
        if (t == double.class || t == Double.class || t == float.class || t == Float.class) return "double";
        if (t == String.class) return "String";
        if (t.isAssignableFrom(Vector3d.class)) return "Vector3d";
        return "ref";
    }

    private String someNames() {
        List<String> names = new ArrayList<>(named.keySet());
        names.sort(null);
        return names.size() <= 6 ? String.join(", ", names) : String.join(", ", names.subList(0, 6)) + ", ...";
    }

    /** Ends the current object: validates it (init) and adds it to the scene. */
    private void endObject() throws SceneFormatException {
        if (current == null) {
            return;
        }
        Object o = current;
        current = null;
        int saved = line;
        line = currentLine;
        try {
            ((SceneObject) o).init();
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw error(currentType + " " + o.getClass().getSimpleName() + ": " + e.getMessage());
        } catch (RuntimeException | LinkageError e) {
            throw error(o.getClass().getSimpleName() + ".init() failed: " + describe(e));
        }
        switch (currentType) {
            case "Camera":
                if (scene.camera != null) {
                    throw error("a second camera (the first is at line " + cameraLine + "; a scene has one)");
                }
                scene.camera = (Camera) o;
                cameraLine = line;
                break;
            case "Surface":
                Surface s = (Surface) o;
                if (s.material == null) {
                    throw error(o.getClass().getSimpleName() + " has no material (expected 'ref material <name>')");
                }
                if (s.isDegenerate() && degenerate++ == 0) {
                    firstDegenerateLine = line;
                }
                scene.surfaces.add(s);
                break;
            case "Material":
                scene.materials.add((Material) o);
                break;
            default:
                scene.lights.add((Light) o);
        }
        line = saved;
    }

    // ---- globals ----

    private void global(String key, String value) throws SceneFormatException {
        Integer first = globalLines.put(key, line);
        if (first != null) {
            throw error(key + " is set twice (first at line " + first + ")");
        }
        if (value.isEmpty()) {
            throw error(key + " needs a value");
        }
        switch (key) {
            case "BGColor":
                scene.backgroundColor = parseVector(value, key);
                break;
            case "AmbientLight":
                scene.ambientLight = parseVector(value, key);
                break;
            case "Width":
                scene.width = parseRange(value, key, 1, Limits.MAX_SIDE);
                break;
            case "Height":
                scene.height = parseRange(value, key, 1, Limits.MAX_SIDE);
                break;
            case "AASamples":
                scene.samplesPerPixel = parseRange(value, key, 1, Limits.MAX_AA_SAMPLES);
                break;
            default:
                scene.maxDepth = parseRange(value, key, 0, Limits.MAX_DEPTH);
        }
    }

    private int parseRange(String value, String key, int min, int max) throws SceneFormatException {
        int v = parseInt(value, key);
        if (v < min || v > max) {
            throw error(key + " " + v + " is out of range (expected " + min + " to " + max + ")");
        }
        return v;
    }

    private Scene finish() throws SceneFormatException {
        int last = Math.max(1, line);
        if (!globalLines.containsKey("Width") || !globalLines.containsKey("Height")) {
            throw new SceneFormatException(file, last, "no " + (globalLines.containsKey("Width") ? "Height" : "Width")
                    + " (expected 'Width <pixels>' and 'Height <pixels>' lines)");
        }
        if (scene.camera == null) {
            throw new SceneFormatException(file, last, "no camera (expected a 'Camera Camera' object)");
        }
        long pixels = (long) scene.width * scene.height;
        if (pixels > Limits.maxPixels()) {
            throw new SceneFormatException(file, globalLines.get("Width"), String.format(
                    "Width x Height = %,d pixels needs about %,d MiB, more than this JVM allows (at most %,d pixels; "
                            + "raise the heap with -Xmx, e.g. JAVA_OPTS=-Xmx16g)",
                    pixels, pixels * Limits.BYTES_PER_PIXEL >> 20, Limits.maxPixels()));
        }
        if (Double.isNaN(scene.camera.aspect)) {
            scene.camera.aspect = (double) scene.width / scene.height;
            scene.camera.recalculate();
        }
        if (degenerate > 0) {
            warnings.add(file + ":" + firstDegenerateLine + ": warning: zero-area triangle, never hit"
                    + (degenerate > 1 ? " (and " + (degenerate - 1) + " more)" : ""));
        }
        return scene;
    }

    // ---- values ----

    private int parseInt(String s, String what) throws SceneFormatException {
        if (!Tokens.isInteger(s)) {
            throw error("'" + s + "' is not an integer (expected a whole number for " + what + ")");
        }
        try {
            return Integer.parseInt(s.startsWith("+") ? s.substring(1) : s);
        } catch (NumberFormatException e) {
            throw error("integer '" + s + "' is out of range for " + what);
        }
    }

    private double parseDouble(String s, String what) throws SceneFormatException {
        if (!isDecimal(s)) {
            throw error("'" + s + "' is not a number (expected a decimal number such as 1.5 or -2e3 for " + what + ")");
        }
        double d = Tokens.parseDecimal(s);
        if (!Double.isFinite(d)) {
            throw error("number '" + s + "' is too large (expected a finite number for " + what + ")");
        }
        return d;
    }

    /** [+-] digits [. digits] [e [+-] digits], or starting with the point; no NaN, Infinity, hex or suffix. */
    static boolean isDecimal(String s) {
        int i = 0, n = s.length();
        if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) i++;
        int digits = 0;
        while (i < n && Character.isDigit(s.charAt(i)) && s.charAt(i) < 128) { i++; digits++; }
        if (i < n && s.charAt(i) == '.') {
            i++;
            while (i < n && Character.isDigit(s.charAt(i)) && s.charAt(i) < 128) { i++; digits++; }
        }
        if (digits == 0) return false;
        if (i < n && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            i++;
            if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) i++;
            int e = 0;
            while (i < n && Character.isDigit(s.charAt(i)) && s.charAt(i) < 128) { i++; e++; }
            if (e == 0) return false;
        }
        return i == n;
    }

    private Vector3d parseVector(String s, String what) throws SceneFormatException {
        double[] fast = Tokens.canonicalVector(s);
        if (fast != null) {
            return new Vector3d(fast[0], fast[1], fast[2]);
        }
        String expected = " (expected [x y z] with three numbers for " + what + ")";
        if (!s.startsWith("[") || !s.endsWith("]") || s.length() < 2) {
            throw error("malformed vector '" + s + "'" + expected);
        }
        String[] parts = Tokens.split(s.substring(1, s.length() - 1).strip(), true, 0);
        if (parts.length != 3 || parts[0].isEmpty()) {
            throw error("malformed vector '" + s + "': " + (parts[0].isEmpty() ? 0 : parts.length) + " numbers" + expected);
        }
        double[] v = new double[3];
        for (int i = 0; i < 3; i++) {
            if (!isDecimal(parts[i])) {
                throw error("malformed vector '" + s + "': '" + parts[i] + "' is not a number" + expected);
            }
            v[i] = Tokens.parseDecimal(parts[i]);
            if (!Double.isFinite(v[i])) {
                throw error("vector '" + s + "' has a number too large" + expected);
            }
        }
        return new Vector3d(v[0], v[1], v[2]);
    }

    private SceneFormatException error(String message) {
        return new SceneFormatException(file, line, message);
    }

    private static String describe(Throwable e) {
        return e.getClass().getSimpleName() + (e.getMessage() == null ? "" : " (" + e.getMessage() + ")");
    }
}
