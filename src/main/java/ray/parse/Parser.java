package ray.parse;

import java.io.IOException;
import java.io.InputStream;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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

    static final List<String> GLOBALS = List.of("BGColor", "AmbientLight", "Width", "Height", "AASamples", "MaxDepth");
    static final List<String> TYPES = List.of("int", "double", "String", "ref", "Vector3d");
    private static final List<String> KEYWORDS = List.of("Camera", "Surface", "Material", "Light",
            "BGColor", "AmbientLight", "Width", "Height", "AASamples", "MaxDepth", "int", "double", "String", "ref", "Vector3d");

    private final String file;
    private final ClassResolver resolver;
    private final Fields fields = new Fields();
    private final Scene scene = new Scene();
    private final Map<String, Object> named = new HashMap<>();
    private final Map<String, Integer> namedLines = new HashMap<>();
    private final Map<String, Integer> globalLines = new HashMap<>();
    private final List<String> warnings = new ArrayList<>();

    // the object being read
    private Object current;
    private String currentType;
    private int currentLine;
    private int blankAfter;            // the blank line that ended it (0: still open)
    private final Map<String, Integer> currentFields = new HashMap<>();
    private int cameraLine;
    private int degenerate;
    private int firstDegenerateLine;

    private int line;

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
        if (Files.isDirectory(path)) {
            throw new SceneFormatException(name, 0, "cannot read the scene: it is a directory (expected a scene file)");
        }
        Parser p = new Parser(name, Parser.class.getClassLoader());
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

    /** Parses a scene file's bytes (UTF-8 text); {@code name} is used in messages. */
    public static Scene parse(byte[] bytes, String name, List<String> warnings) throws SceneFormatException {
        Parser p = new Parser(name, Parser.class.getClassLoader());
        try {
            return p.run(Lines.of(new java.io.ByteArrayInputStream(bytes), name), warnings);
        } catch (IOException e) {
            throw new AssertionError(e);     // a byte array cannot fail to read
        }
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

    private Scene run(Lines lines, List<String> warningsOut) throws SceneFormatException, IOException {
        boolean any = false;
        for (String raw = lines.next(); raw != null; raw = lines.next()) {
            line = lines.line();
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
        Object o;
        try {
            o = c.getConstructor().newInstance();
        } catch (InvocationTargetException e) {
            throw error("creating " + w[1] + " failed: " + describe(e.getCause()));
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            throw error("creating " + w[1] + " failed: " + describe(e));
        }
        current = o;
        currentType = type;
        currentLine = line;
        blankAfter = 0;
        currentFields.clear();
        if (name != null) {
            named.put(name, o);
            namedLines.put(name, line);
        }
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
        String cls = o.getClass().getSimpleName();
        try {
            ((SceneObject) o).init();
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw error(currentType + " " + cls + ": " + e.getMessage());
        } catch (RuntimeException | LinkageError | AssertionError | StackOverflowError e) {
            throw error(cls + ".init() failed: " + describe(e));
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
                    throw error(cls + " has no material (expected 'ref material <name>' in the object)");
                }
                boolean flat;
                try {
                    flat = s.isDegenerate();
                } catch (RuntimeException | LinkageError e) {
                    throw error(cls + ".isDegenerate() failed: " + describe(e));
                }
                if (flat && degenerate++ == 0) {
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
        boolean vector = key.equals("BGColor") || key.equals("AmbientLight");
        Integer first = globalLines.put(key, line);
        if (first != null) {
            throw error(key + " is set twice (first at line " + first + "; expected each setting once)");
        }
        if (value.isEmpty()) {
            throw error("'" + key + "' needs a value (expected '" + key + " " + (vector ? "[r g b]" : key.equals("AASamples") ? "<n>"
                    : key.equals("MaxDepth") ? "<bounces>" : "<pixels>") + "')");
        }
        try {
            switch (key) {
                case "BGColor" -> scene.backgroundColor = Values.parseVector(value, key);
                case "AmbientLight" -> scene.ambientLight = Values.parseVector(value, key);
                case "Width" -> scene.width = range(value, key, 1, Limits.MAX_SIDE);
                case "Height" -> scene.height = range(value, key, 1, Limits.MAX_SIDE);
                case "AASamples" -> scene.samplesPerPixel = range(value, key, 1, Limits.MAX_AA_SAMPLES);
                default -> scene.maxDepth = range(value, key, 0, Limits.MAX_DEPTH);
            }
        } catch (Problem p) {
            throw error(p.getMessage());
        }
    }

    private static int range(String value, String key, int min, int max) throws Problem {
        String expected = " (expected " + min + " to " + max + ")";
        if (!Values.isWhole(value)) {
            throw new Problem(Values.quote(value) + " is not a whole number for " + key + expected);
        }
        Long v = Values.wholeValue(value);
        if (v == null || v < min || v > max) {
            throw new Problem(Values.quote(key + " " + value) + " is out of range" + expected);
        }
        return (int) (long) v;
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
        long pixels = (long) scene.width * scene.height;
        if (pixels > Limits.maxPixels()) {
            line = globalLines.get("Width");
            String why = Limits.maxPixels() < Limits.heapPixels()
                    ? String.format("at most %,d pixels, the most one image array holds", Limits.MAX_ARRAY_PIXELS)
                    : String.format("at most %,d pixels, half of this JVM's %,d MiB heap at %d bytes a pixel; raise the heap with -Xmx, "
                            + "e.g. JAVA_OPTS=-Xmx16g", Limits.maxPixels(), Runtime.getRuntime().maxMemory() >> 20, Limits.BYTES_PER_PIXEL);
            throw error(String.format("Width %d x Height %d = %,d pixels would need about %,d MiB (expected %s)",
                    scene.width, scene.height, pixels, pixels * Limits.BYTES_PER_PIXEL >> 20, why));
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

    // ---- shared with Parameters ----

    Object current() {
        return current;
    }

    Fields fields() {
        return fields;
    }

    Map<String, Integer> currentFields() {
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
