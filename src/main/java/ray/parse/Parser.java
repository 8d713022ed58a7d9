package ray.parse;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Constructor;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.vecmath.Vector3d;
import ray.Camera;
import ray.Scene;
import ray.SceneObject;
import ray.light.Light;
import ray.material.Material;
import ray.surface.Surface;

/**
 * Reads the scene format ({@code scene-format.md}): object headers {@code <ObjectType> <ClassName> [name]},
 * parameter lines {@code <type> <field> <value>} written straight into the object's field, a blank line
 * ending an object, global settings and {@code #} comments. Every mistake is a
 * {@link SceneFormatException} naming the file and line, what was found and what was expected;
 * nothing else escapes (docs/bad-input.md lists them). One parser reads one file; its state (the
 * named objects) lives in the instance.
 */
public final class Parser {

    /** The globals' keywords ({@link Globals}: the one table of them). */
    static final List<String> GLOBALS = Globals.NAMES;
    static final List<String> TYPES = List.of("int", "double", "String", "ref", "Vector3d");
    /** Every word a line can start with, for "did you mean" hints: headers, globals, parameter types. */
    private static final List<String> KEYWORDS = keywords();

    private static List<String> keywords() {
        List<String> k = new ArrayList<>(List.of("Camera", "Surface", "Material", "Light"));
        k.addAll(GLOBALS);
        k.addAll(TYPES);
        return List.copyOf(k);
    }

    private final String file;
    private final ClassResolver resolver;
    private final Fields fields = new Fields();
    private final Scene scene = new Scene();
    private final Map<String, Object> named = new HashMap<>();
    private final Map<String, Integer> namedLines = new HashMap<>();
    private final Map<String, Integer> globalLines = new HashMap<>();
    /** Scene classes' no-argument constructors, looked up once per file. */
    private final Map<Class<?>, Constructor<?>> constructors = new HashMap<>();
    private final List<String> warnings = new ArrayList<>();

    // the object being read
    private Object current;
    private String currentType;
    private int currentLine;
    private int blankAfter;            // the blank line that ended it (0: still open)
    private final FieldLines currentFields = new FieldLines();
    private int cameraLine;
    private int degenerate;
    /** Surfaces other surfaces are built from (CSG operands): left out of the scene at the end. */
    private final java.util.Set<Surface> operands = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
    /** Surfaces whose operands are known to lead back to none of them (checked once: {@link OperandGraph}). */
    private final java.util.Set<Surface> acyclic = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
    private int firstDegenerateLine;
    /** Plausibility warnings ({@link Plausibility}), in the order of their objects. */
    private final List<String> plausibility = new ArrayList<>();

    private int line;
    /** The scene file when read from one (an input the output must never replace). */
    private Path source;
    /** Lines the fast path read (for the test that it is taken: ParserFastPathTest). */
    private int fastLines;

    private Parser(String file, ClassLoader loader) {
        this.file = file;
        this.resolver = new ClassResolver(loader);
    }

    /** Reads and parses {@code path}; the file is named in messages as given. */
    public static Scene parse(Path path) throws SceneFormatException {
        return parse(path, new ArrayList<>());
    }

    /** As {@link #parse(Path)}, adding warnings (e.g. zero-area triangles) as {@code file:line: warning: ...}. */
    public static Scene parse(Path path, List<String> warnings) throws SceneFormatException {
        String name = path.toString();
        if (name.isEmpty()) {
            throw new SceneFormatException("''", 0, "cannot read the scene: an empty file name (expected a scene file)");
        }
        if (Files.isDirectory(path)) {
            throw new SceneFormatException(name, 0, "cannot read the scene: it is a directory (expected a scene file)");
        }
        String special = notRegular(path);
        if (special != null) {      // a FIFO would wait for a writer for ever, /dev/zero never end: in every mode
            throw new SceneFormatException(name, 0, "cannot read the scene: not a regular file (" + special
                    + "); to read a scene from a pipe give '-' and send it to standard input");
        }
        Parser p = new Parser(name, Parser.class.getClassLoader());
        p.source = path;
        try (InputStream in = Files.newInputStream(path)) {
            return p.run(Lines.of(in, name), warnings);
        } catch (NoSuchFileException e) {
            throw new SceneFormatException(name, 0, "cannot read the scene: no such file");
        } catch (AccessDeniedException e) {
            throw new SceneFormatException(name, 0, "cannot read the scene: permission denied");
        } catch (IOException | SecurityException e) {
            throw new SceneFormatException(name, p.line, "cannot read the scene: " + (e.getMessage() == null
                    ? e.getClass().getSimpleName() : e.getMessage()));
        } catch (OutOfMemoryError e) {
            throw new SceneFormatException(name, p.line, "the scene is too large for this JVM's heap (expected fewer objects, "
                    + "or raise the heap with -Xmx, e.g. JAVA_OPTS=-Xmx16g)");
        }
    }

    /**
     * Reads and parses a scene from a stream (standard input for the scene {@code -}) line by line, as a
     * file is: a mistake is reported at its line as soon as it is read, and no more than one line is
     * held before it is checked (`yes 'Width 10' | raytracer -` fails at line 2, at once).
     */
    public static Scene parse(InputStream in, String name, List<String> warnings) throws SceneFormatException {
        Parser p = new Parser(name, Parser.class.getClassLoader());
        try {
            return p.run(Lines.of(in, name), warnings);
        } catch (IOException e) {
            throw new SceneFormatException(name, p.line, "cannot read the scene: " + (e.getMessage() == null
                    ? e.getClass().getSimpleName() : e.getMessage()));
        } catch (OutOfMemoryError e) {
            throw new SceneFormatException(name, p.line, "the scene is too large for this JVM's heap (expected fewer objects, "
                    + "or raise the heap with -Xmx, e.g. JAVA_OPTS=-Xmx16g)");
        }
    }

    /** "a FIFO", "a character device", ... when {@code path} exists and is neither a regular file nor a folder; else null. */
    static String notRegular(Path path) {
        java.nio.file.attribute.BasicFileAttributes a;
        try {
            a = Files.readAttributes(path, java.nio.file.attribute.BasicFileAttributes.class);
        } catch (IOException | SecurityException e) {
            return null;       // missing or unreadable: opening it says which
        }
        return a.isRegularFile() || a.isDirectory() ? null : ray.io.OutputFile.kind(path);
    }

    /** Parses a scene file's bytes (UTF-8 text); {@code name} is used in messages. */
    public static Scene parse(byte[] bytes, String name, List<String> warnings) throws SceneFormatException {
        Parser p = new Parser(name, Parser.class.getClassLoader());
        try {
            return p.run(Lines.of(new java.io.ByteArrayInputStream(bytes), name), warnings);
        } catch (IOException e) {
            throw new AssertionError(e);     // a byte array cannot fail to read
        }
    }

    /** For tests: how many lines of a scene file's bytes the fast path read (the rest took the general path). */
    static int fastLineCount(byte[] bytes, String name) throws SceneFormatException {
        Parser p = new Parser(name, Parser.class.getClassLoader());
        try {
            p.run(Lines.of(new java.io.ByteArrayInputStream(bytes), name), new ArrayList<>());
        } catch (IOException e) {
            throw new AssertionError(e);     // a byte array cannot fail to read
        }
        return p.fastLines;
    }

    /** Parses scene text; {@code name} is used in messages. */
    public static Scene parse(String text, String name, List<String> warnings) throws SceneFormatException {
        return parse(text, name, warnings, Parser.class.getClassLoader());
    }

    /** As {@link #parse(String, String, List)}, finding the scene's classes through {@code loader}. */
    static Scene parse(String text, String name, List<String> warnings, ClassLoader loader) throws SceneFormatException {
        try {
            return new Parser(name, loader).run(Lines.of(text, name), warnings);
        } catch (IOException e) {
            throw new AssertionError(e);     // text cannot fail to read
        }
    }

    /**
     * Parses, recording every file read meanwhile (the scene file, the objects' own files) as the
     * scene's inputs ({@link ray.io.InputFiles}): nothing the program writes may replace one of them.
     */
    private Scene run(Lines lines, List<String> warningsOut) throws SceneFormatException, IOException {
        List<Path> outer = ray.io.InputFiles.begin();
        Scene s = null;
        try {
            if (source != null) {
                ray.io.InputFiles.read(source);
            }
            s = runLines(lines, warningsOut);
            return s;
        } finally {
            ray.io.InputFiles.end(s, outer);
        }
    }

    private Scene runLines(Lines lines, List<String> warningsOut) throws SceneFormatException, IOException {
        boolean any = false;
        while (lines.advance()) {
            line = lines.line();
            if (lines.ascii() && fastLine(lines.bytes(), lines.length())) {
                any |= lines.length() > 0;
                fastLines++;
                continue;
            }
            String raw = lines.text();
            String s = stripComment(raw).strip();
            if (s.isEmpty()) {
                if (raw.isBlank() && current != null && blankAfter == 0) {
                    blankAfter = line;        // a blank line ends the object; a comment line does not
                }
                continue;
            }
            any = true;
            statement(s);
        }
        line = Math.max(1, lines.line());
        endObject();
        if (!any) {
            throw error("empty scene file (expected at least Width, Height and a Camera)");
        }
        Scene s = finish();
        warningsOut.addAll(warnings);
        return s;
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

    /** At most three words: the first two, and the rest of the line. {@code s} is stripped and not empty. */
    static String[] words(String s) {
        String[] out = new String[3];
        int n = 0, i = 0, len = s.length();
        while (n < 2) {
            int start = i;
            while (i < len && !Character.isWhitespace(s.charAt(i))) i++;
            out[n++] = s.substring(start, i);
            while (i < len && Character.isWhitespace(s.charAt(i))) i++;
            if (i == len) {
                return java.util.Arrays.copyOf(out, n);
            }
        }
        out[2] = s.substring(i);
        return out;
    }

    private void statement(String s) throws SceneFormatException {
        String[] w = words(s);
        String head = w[0];
        boolean inObject = current != null && blankAfter == 0;
        if (TYPES.contains(head)) {
            if (current == null) {
                throw error("parameter line outside an object (expected an object header such as 'Surface Sphere' above it, with no blank line between)");
            }
            if (!inObject) {
                throw error("parameter line outside an object: the blank line at line " + blankAfter + " ended the " + currentType + " "
                        + current.getClass().getSimpleName() + " of line " + currentLine + " (expected no blank line inside an object)");
            }
            new Parameters(this).parameter(w);
            return;
        }
        if (inObject && !ClassResolver.BASES.containsKey(head) && !GLOBALS.contains(head)) {
            if (Fields.settableNames(current.getClass()).contains(head)) {
                throw error(Values.quote(s) + " has no type (expected " + Values.quote(keywordOf(head) + " " + s) + ")");
            }
            throw error("unknown parameter type " + Values.quote(head) + " (" + Values.caseHint(head, KEYWORDS)
                    + "expected int, double, String, ref or Vector3d, or a new object header)");
        }
        endObject();
        if (ClassResolver.BASES.containsKey(head)) {
            header(w, s);
        } else if (GLOBALS.contains(head)) {
            global(head, w.length > 1 ? s.substring(head.length()).strip() : "");
        } else {
            throw error("unknown keyword " + Values.quote(head) + " (" + Values.caseHint(head, KEYWORDS)
                    + "expected Camera, Surface, Material, Light or a global: " + String.join(", ", GLOBALS) + ")");
        }
    }

    private String keywordOf(String fieldName) {
        try {
            return Fields.keyword(fields.find(current.getClass(), fieldName).getType());
        } catch (Problem p) {
            return "<type>";
        }
    }

    // ---- objects ----

    private void header(String[] w, String s) throws SceneFormatException {
        String type = w[0];
        String form = "'" + type + " <ClassName> [name]'";
        if (w.length < 2) {
            throw error("'" + type + "' needs a class name (expected " + form + ", e.g. '" + type + " "
                    + ClassResolver.builtIns(type).split(",")[0] + "')");
        }
        if (w.length == 3 && words(w[2]).length > 1) {
            throw error("too many words in " + Values.quote(s) + " (expected " + form + ")");
        }
        Class<?> c;
        try {
            c = resolver.resolve(type, w[1]);
        } catch (Problem p) {
            throw error(p.getMessage());
        }
        String name = w.length == 3 ? w[2] : null;
        if (name != null && named.containsKey(name)) {
            throw error("the name " + Values.quote(name) + " is already used by the " + named.get(name).getClass().getSimpleName()
                    + " at line " + namedLines.get(name) + " (expected a name used once in the file)");
        }
        begin(type, w[1], c, name);
        lastType = type;
        lastClassName = w[1];
        lastClass = c;
    }

    /** Creates the object of a header and makes it the one being read. */
    private void begin(String type, String className, Class<?> c, String name) throws SceneFormatException {
        Object o;
        try {
            Constructor<?> k = constructors.get(c);
            if (k == null) {
                k = c.getConstructor();
                constructors.put(c, k);
            }
            o = k.newInstance();
        } catch (InvocationTargetException e) {
            throw error("creating " + className + " failed: " + describe(e.getCause()));
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            throw error("creating " + className + " failed: " + describe(e));
        }
        current = o;
        currentType = type;
        currentLine = line;
        blankAfter = 0;
        currentFields.clear();
        if (name != null) {
            named.put(name, o);
            namedLines.put(name, line);
            scene.name(o, name);
        }
    }

    // ---- the fast path: the plain lines a large scene consists of, read from their bytes ----

    /** The last header the general path read: its type, class name and class. */
    private String lastType, lastClassName;
    private Class<?> lastClass;
    /** Per class, the fields plain parameter lines have set: name, Field and type keyword. */
    private final Map<Class<?>, List<FastField>> fastFields = new HashMap<>();
    private Class<?> fastClass;
    /** The fast path's vector, read into this and copied into the field's new Vector3d. */
    private final double[] xyz = new double[3];
    private List<FastField> fastClassFields;
    /** The object name a plain ref line last named and its object (a name never changes its object). */
    private String lastRefName;
    private Object lastRefTarget;

    private static final int VECTOR = 0, DOUBLE = 1, REF = 2;
    private static final String[] FAST_TYPES = {"Vector3d", "double", "ref"};

    private record FastField(String name, Field field, String keyword) {
    }

    /**
     * Reads an ASCII line [0, n) of {@code b} when it is one of the kinds a large scene consists of,
     * written plainly (printable ASCII and single spaces, no comment, nothing to strip): a blank line,
     * an unnamed object header of a class the general path has already read a header of, or a
     * Vector3d, double or ref parameter of the object being read. Does exactly what the general path
     * does with the same line, without a String per word. Returns false, having changed nothing, for
     * any other line and for any line with a mistake: the general path then reads it and reports it.
     */
    private boolean fastLine(byte[] b, int n) throws SceneFormatException {
        if (n == 0) {
            if (current != null && blankAfter == 0) {
                blankAfter = line;        // a blank line ends the object
            }
            return true;
        }
        if (b[0] == ' ' || b[n - 1] == ' ') {
            return false;
        }
        int s1 = -1, s2 = -1;
        for (int i = 0; i < n; i++) {
            byte c = b[i];
            if (c == ' ') {
                if (b[i - 1] == ' ') {
                    return false;
                }
                if (s1 < 0) {
                    s1 = i;
                } else if (s2 < 0) {
                    s2 = i;
                }
            } else if (c < 0x21 || c == 0x7f || c == '#') {     // ASCII only: no byte is above 0x7f
                return false;
            }
        }
        if (s1 < 0) {
            return false;
        }
        if (s2 < 0) {                     // two words: a header such as "Surface Triangle"
            if (lastType == null || !equals(b, 0, s1, lastType) || !equals(b, s1 + 1, n, lastClassName)) {
                return false;
            }
            endObject();
            begin(lastType, lastClassName, lastClass, null);
            return true;
        }
        if (current == null || blankAfter != 0) {
            return false;
        }
        int kind = equals(b, 0, s1, "Vector3d") ? VECTOR : equals(b, 0, s1, "double") ? DOUBLE : equals(b, 0, s1, "ref") ? REF : -1;
        if (kind < 0) {
            return false;
        }
        FastField ff = fastField(b, s1 + 1, s2);
        if (ff == null || !ff.keyword.equals(FAST_TYPES[kind]) || currentFields.contains(ff.name)) {
            return false;
        }
        Field f = ff.field;
        int v0 = s2 + 1;
        Object v;
        if (kind == VECTOR) {
            double[] xyz = this.xyz;
            if (!Tokens.canonicalVector(b, v0, n, xyz)) {
                return false;
            }
            v = new Vector3d(xyz[0], xyz[1], xyz[2]);
        } else if (kind == DOUBLE) {
            Class<?> ft = f.getType();
            if ((ft != double.class && ft != Double.class) || !Tokens.isDecimal(b, v0, n)) {
                return false;
            }
            double d = Tokens.parseDecimal(b, v0, n);
            if (!Double.isFinite(d)) {
                return false;
            }
            v = d;
        } else {                          // ref: one word, the name of an earlier object
            if (lastRefName == null || !equals(b, v0, n, lastRefName)) {
                for (int i = v0; i < n; i++) {
                    if (b[i] == ' ') {
                        return false;
                    }
                }
                String name = new String(b, v0, n - v0, StandardCharsets.ISO_8859_1);
                Object target = named.get(name);
                if (target == null) {
                    return false;
                }
                lastRefName = name;
                lastRefTarget = target;
            }
            if (lastRefTarget == current || !f.getType().isInstance(lastRefTarget)) {
                return false;
            }
            v = lastRefTarget;
        }
        try {
            f.set(current, v);
        } catch (IllegalAccessException | RuntimeException e) {
            return false;                 // the general path sets it again and reports what fails
        }
        currentFields.putIfAbsent(ff.name, line);
        return true;
    }

    /** The settable field [from, to) of {@code b} names in the current object's class, or null. */
    private FastField fastField(byte[] b, int from, int to) {
        Class<?> c = current.getClass();
        if (c != fastClass) {
            fastClass = c;
            fastClassFields = fastFields.computeIfAbsent(c, k -> new ArrayList<>());
        }
        for (int i = 0; i < fastClassFields.size(); i++) {   // indexed: an iterator per line is garbage
            FastField e = fastClassFields.get(i);
            if (equals(b, from, to, e.name)) {
                return e;
            }
        }
        String name = new String(b, from, to - from, StandardCharsets.ISO_8859_1);
        Field f;
        try {
            f = fields.find(c, name);
        } catch (Problem p) {
            return null;
        }
        String keyword = Fields.keyword(f.getType());
        if (keyword == null) {
            return null;
        }
        FastField e = new FastField(name, f, keyword);
        fastClassFields.add(e);
        return e;
    }

    /** Whether bytes [from, to) of {@code b} are the chars of {@code s} (all ASCII). */
    private static boolean equals(byte[] b, int from, int to, String s) {
        if (to - from != s.length()) {
            return false;
        }
        for (int i = 0; i < to - from; i++) {
            if (b[from + i] != s.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    /** Ends the current object: validates it (init) and adds it to the scene. Problems are reported at its header. */
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
            if (o instanceof ReadsFiles r) {
                readFiles(o, r);
            } else if (o instanceof ray.surface.Mesh m) {   // geometry reads no files: the parser reads its OBJ
                readFiles(o, folder -> ObjFile.loadInto(m, folder));
            }
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw error(currentType + " " + o.getClass().getSimpleName() + ": " + e.getMessage());
        } catch (RuntimeException | LinkageError | AssertionError | StackOverflowError e) {
            throw error(o.getClass().getSimpleName() + ".init() failed: " + describe(e));
        }
        for (String[] w : Plausibility.of(o)) {
            int at = currentFields.lineOf(w[0]);
            plausibility.add(file + ":" + (at > 0 ? at : line) + ": warning: " + o.getClass().getSimpleName() + " " + w[1]);
        }
        switch (currentType) {
            case "Camera":
                if (scene.camera != null) {
                    throw error("a second camera (first at line " + cameraLine + "; expected one camera per scene)");
                }
                scene.camera = (Camera) o;
                cameraLine = line;
                break;
            case "Surface":
                Surface s = (Surface) o;
                if (s.material == null) {
                    throw error(o.getClass().getSimpleName() + " has no material (expected 'ref material <name>' in the object)");
                }
                boolean flat;
                try {
                    flat = s.isDegenerate();
                } catch (RuntimeException | LinkageError e) {
                    throw error(o.getClass().getSimpleName() + ".isDegenerate() failed: " + describe(e));
                }
                if (flat && degenerate++ == 0) {
                    firstDegenerateLine = line;
                }
                try {
                    List<Surface> ops = s.operands();
                    if (!ops.isEmpty()) {
                        String cycle = OperandGraph.cycle(s, acyclic);
                        if (cycle != null) {
                            throw error(cycle);
                        }
                        operands.addAll(ops);
                    }
                } catch (RuntimeException | LinkageError | StackOverflowError e) {
                    throw error(o.getClass().getSimpleName() + ".operands() failed: " + describe(e));
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

    /** Lets an object read its own files; a mistake in one is reported at that file's line, naming this object. */
    private void readFiles(Object o, ReadsFiles r) throws SceneFormatException {
        try {
            r.readFiles(folder());
        } catch (SceneFormatException e) {
            throw new SceneFormatException(e.file(), e.line(), e.problem() + " (read for the " + currentType + " "
                    + o.getClass().getSimpleName() + " at " + file + ":" + line + ")");
        }
    }

    /** The scene file's folder (the working directory for a scene without one, or read from text). */
    private Path folder() {
        try {
            Path p = Path.of(file).getParent();
            return p == null ? Path.of("") : p;
        } catch (java.nio.file.InvalidPathException e) {
            return Path.of("");
        }
    }

    // ---- globals ----

    private void global(String key, String value) throws SceneFormatException {
        Globals g = Globals.of(key);
        Integer first = globalLines.put(key, line);
        if (first != null) {
            throw error(key + " is set twice (first at line " + first + "; expected each setting once)");
        }
        if (value.isEmpty()) {
            throw error("'" + key + "' needs a value (expected '" + key + " " + g.hint + "')");
        }
        try {
            g.read(value, scene);
        } catch (Problem p) {
            throw error(p.getMessage());
        }
    }

    private Scene finish() throws SceneFormatException {
        for (String side : new String[] {"Width", "Height"}) {
            if (!globalLines.containsKey(side)) {
                throw error("no " + side + " (expected '" + side + " <pixels>', e.g. '" + side + (side.equals("Width") ? " 640')" : " 480')"));
            }
        }
        if (scene.camera == null) {
            throw error("no camera (expected a 'Camera Camera' object)");
        }
        // the pixel limit of the scene's own sampler (a film costs more than the grid; the render checks
        // again with a sampler the command line or the viewer chose: ray.render.Renderer)
        String tooLarge = ray.settings.PixelBudget.refusal(scene.width, scene.height, scene.sampler);
        if (tooLarge != null) {
            line = globalLines.get("Width");
            throw error(tooLarge);
        }
        if (Double.isNaN(scene.camera.aspect)) {
            scene.camera.aspect = (double) scene.width / scene.height;
            scene.camera.recalculate();
        }
        if (!operands.isEmpty()) {
            List<Surface> rendered = new ArrayList<>(scene.surfaces.size());
            for (Surface s : scene.surfaces) {
                if (!operands.contains(s)) {
                    rendered.add(s);
                }
            }
            scene.surfaces = rendered;
        }
        warnings.addAll(plausibility);
        if (degenerate > 0) {
            warnings.add(file + ":" + firstDegenerateLine + ": warning: zero-area triangle, never hit"
                    + (degenerate > 1 ? " (and " + (degenerate - 1) + " more)" : ""));
        }
        return scene;
    }

    // ---- shared with Parameters ----

    Object current() {
        return current;
    }

    Fields fields() {
        return fields;
    }

    FieldLines currentFields() {
        return currentFields;
    }

    Map<String, Object> named() {
        return named;
    }

    int line() {
        return line;
    }

    SceneFormatException error(String message) {
        return new SceneFormatException(file, line, message);
    }

    static String describe(Throwable e) {
        return e.getClass().getSimpleName() + (e.getMessage() == null ? "" : " (" + e.getMessage() + ")");
    }
}
