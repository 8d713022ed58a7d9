import java.io.File;
import java.io.IOException;
import java.lang.reflect.Field;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Modifier;
import java.math.BigInteger;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.vecmath.Vector3d;

/**
 * Reads a scene file into a {@link Scene}. Given: not one of the methods you write.
 *
 * <p>The format (the same as the full ray tracer's):
 *
 * <pre>
 * Width 240                  # global settings: Width, Height (required), BGColor, AmbientLight,
 * Height 180                 #   AASamples, MaxDepth
 *
 * Camera Camera              # an object: &lt;Camera|Surface|Material|Light&gt; &lt;ClassName&gt; [name]
 * Vector3d eye [0 0 5]       # then its fields: &lt;int|double|String|Vector3d|ref&gt; &lt;field&gt; &lt;value&gt;
 *                            # a blank line ends the object
 * Material Diffuse red
 * Vector3d diffuseColor [0.8 0 0]
 *
 * Surface Sphere
 * ref material red           # ref: an object named earlier in the file
 * </pre>
 *
 * <p>The parser is reflective: {@code Surface MySurface} creates your own class {@code MySurface}
 * (public, with a public no-argument constructor, a subclass of Surface) and writes each field line
 * into the field of that name. A mistake stops it with one line, {@code file:line: what was found
 * (what was expected)}.
 */
public class Parser {

    /** A mistake in a scene file: the message is one line, {@code file:line: problem}. */
    public static class SceneFormatException extends Exception {
        private static final long serialVersionUID = 1L;

        public SceneFormatException(String file, int line, String problem) {
            super(oneLine(line > 0 ? file + ":" + line + ": " + problem : file + ": " + problem));
        }
    }

    private static final List<String> GLOBALS = List.of("BGColor", "AmbientLight", "Width", "Height", "AASamples", "MaxDepth");
    private static final List<String> TYPES = List.of("int", "double", "String", "ref", "Vector3d");
    private static final List<String> KEYWORDS = List.of("Camera", "Surface", "Material", "Light",
            "BGColor", "AmbientLight", "Width", "Height", "AASamples", "MaxDepth", "int", "double", "String", "ref", "Vector3d");
    private static final Map<String, Class<?>> BASES = Map.of(
            "Camera", Camera.class, "Surface", Surface.class, "Material", Material.class, "Light", Light.class);
    private static final int MAX_SIDE = 1 << 16, MAX_AA_SAMPLES = 64, MAX_DEPTH = 1000, QUOTE_MAX = 60;

    private final String file;
    private final Scene scene = new Scene();
    private int line;
    /** The object being read, its header keyword and line; the line of the blank line that ended it (0: none yet). */
    private Object current;
    private String currentType;
    private int currentLine, blankAfter;
    private final Map<String, Integer> currentFields = new HashMap<>();
    private final Map<String, Object> named = new HashMap<>();
    private final Map<String, Integer> namedLines = new HashMap<>();
    private final Map<String, Integer> globalLines = new HashMap<>();
    private int cameraLine;
    private boolean aspectSet;

    private Parser(String file) {
        this.file = file;
    }

    /** Reads the scene file {@code fileName}. */
    public static Scene parse(String fileName) throws SceneFormatException {
        return parse(new File(fileName));
    }

    /** Reads the scene file {@code f}; the file is named in messages as given. */
    public static Scene parse(File f) throws SceneFormatException {
        String name = f.getPath();
        if (f.isDirectory()) {
            throw new SceneFormatException(name, 0, "cannot read the scene: it is a directory (expected a scene file)");
        }
        String text;
        try {
            text = new String(Files.readAllBytes(f.toPath()), StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new SceneFormatException(name, 0, "cannot read the scene: no such file");
        } catch (AccessDeniedException e) {
            throw new SceneFormatException(name, 0, "cannot read the scene: permission denied");
        } catch (IOException e) {
            throw new SceneFormatException(name, 0, "cannot read the scene: " + e.getMessage());
        }
        return parse(text, name);
    }

    /** Parses the text of a scene file; {@code name} is used in messages. */
    public static Scene parse(String text, String name) throws SceneFormatException {
        return new Parser(name).run(text);
    }

    private Scene run(String text) throws SceneFormatException {
        if (text.startsWith("\uFEFF")) {
            text = text.substring(1);
        }
        boolean any = false;
        String[] lines = text.split("\r\n|\r|\n", -1);
        for (int i = 0; i < lines.length; i++) {
            line = i + 1;
            String raw = lines[i];
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
        line = Math.max(1, lines.length - (text.endsWith("\n") ? 1 : 0));
        endObject();
        if (!any) {
            throw error("empty scene file (expected at least Width, Height and a Camera)");
        }
        return finish();
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

    /** At most three words: the first two, and the rest of the line. */
    private static String[] words(String s) {
        String[] parts = s.strip().split("\\s+", 3);
        return parts.length == 1 && parts[0].isEmpty() ? new String[0] : parts;
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
            parameter(w);
            return;
        }
        if (inObject && !BASES.containsKey(head) && !GLOBALS.contains(head)) {
            if (settableNames(current.getClass()).contains(head)) {
                throw error(quote(s) + " has no type (expected " + quote(keywordOf(head) + " " + s) + ")");
            }
            throw error("unknown parameter type " + quote(head) + " (" + caseHint(head, KEYWORDS)
                    + "expected int, double, String, ref or Vector3d, or a new object header)");
        }
        endObject();
        if (BASES.containsKey(head)) {
            header(w, s);
        } else if (GLOBALS.contains(head)) {
            global(head, w.length > 1 ? s.substring(head.length()).strip() : "");
        } else {
            throw error("unknown keyword " + quote(head) + " (" + caseHint(head, KEYWORDS)
                    + "expected Camera, Surface, Material, Light or a global: " + String.join(", ", GLOBALS) + ")");
        }
    }

    // ---- objects ----

    private void header(String[] w, String s) throws SceneFormatException {
        String type = w[0];
        String form = "'" + type + " <ClassName> [name]'";
        if (w.length < 2) {
            throw error("'" + type + "' needs a class name (expected " + form + ", e.g. '" + type + " " + builtIns(type).split(",")[0] + "')");
        }
        if (w.length == 3 && words(w[2]).length > 1) {
            throw error("too many words in " + quote(s) + " (expected " + form + ")");
        }
        Class<?> c = resolve(type, w[1]);
        String name = w.length == 3 ? w[2] : null;
        if (name != null && named.containsKey(name)) {
            throw error("the name " + quote(name) + " is already used by the " + named.get(name).getClass().getSimpleName()
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

    /** The class a header names: a class in the default package (yours or the framework's). */
    private Class<?> resolve(String type, String name) throws SceneFormatException {
        Class<?> base = BASES.get(type);
        String expected = " (expected " + builtIns(type) + " or a " + type + " class of your own)";
        if (!name.matches("[\\p{javaJavaIdentifierStart}][\\p{javaJavaIdentifierPart}]*(\\.[\\p{javaJavaIdentifierStart}][\\p{javaJavaIdentifierPart}]*)*")
                || name.length() > 200) {
            throw error(quote(name) + " is not a class name" + expected);
        }
        Class<?> c;
        try {
            c = Class.forName(name.equals("Glazed") ? "GlazedMaterial" : name, false, Parser.class.getClassLoader());
        } catch (ClassNotFoundException | LinkageError e) {
            List<String> known = new ArrayList<>(List.of(builtIns(type).replace(" (or ", ", ").replace(")", "").split(", ")));
            throw error("unknown " + type + " class " + quote(name) + " (" + caseHint(name, known) + "expected " + builtIns(type)
                    + " or a " + type + " class of your own on the class path)");
        }
        if (!base.isAssignableFrom(c)) {
            String what = null;
            for (Map.Entry<String, Class<?>> e : BASES.entrySet()) {
                if (e.getValue().isAssignableFrom(c)) {
                    what = e.getKey();
                }
            }
            throw error(quote(name) + " is " + (what == null ? "not a " + type : "a " + what + ", not a " + type) + expected);
        }
        if (c.isInterface() || Modifier.isAbstract(c.getModifiers())) {
            throw error(quote(name) + " is abstract and cannot be created" + expected);
        }
        if (!Modifier.isPublic(c.getModifiers())) {
            throw error("class " + quote(name) + " is not public (expected a public class with a public no-argument constructor)");
        }
        try {
            c.getConstructor();
        } catch (NoSuchMethodException | LinkageError | RuntimeException e) {
            throw error("class " + quote(name) + " has no public no-argument constructor (expected one, as scene objects are created empty)");
        }
        return c;
    }

    private static String builtIns(String type) {
        switch (type) {
            case "Camera": return "Camera";
            case "Surface": return "Sphere, Triangle";
            case "Material": return "Diffuse, BlinnPhong, GlazedMaterial (or Glazed)";
            default: return "PointLight";
        }
    }

    /** Ends the object being read: checks it and adds it to the scene. Problems are reported at its header. */
    private void endObject() throws SceneFormatException {
        if (current == null) {
            return;
        }
        Object o = current;
        current = null;
        int saved = line;
        line = currentLine;
        String problem = check(o);
        if (problem != null) {
            throw error(currentType + " " + o.getClass().getSimpleName() + ": " + problem);
        }
        switch (currentType) {
            case "Camera":
                if (scene.camera != null) {
                    throw error("a second camera (first at line " + cameraLine + "; expected one camera per scene)");
                }
                scene.camera = (Camera) o;
                cameraLine = line;
                aspectSet = currentFields.containsKey("aspect");
                break;
            case "Surface":
                if (((Surface) o).material == null) {
                    throw error(o.getClass().getSimpleName() + " has no material (expected 'ref material <name>' in the object)");
                }
                scene.surfaces.add((Surface) o);
                break;
            case "Material":
                scene.materials.add((Material) o);
                break;
            default:
                scene.lights.add((Light) o);
        }
        line = saved;
    }

    /** What is wrong with the values of a framework object (the full ray tracer checks the same), or null. */
    private static String check(Object o) {
        if (o instanceof Camera) {
            Camera c = (Camera) o;
            if (!(c.yFOV > 0 && c.yFOV < 180)) {
                return "yFOV must be between 0 and 180 degrees (exclusive), got " + c.yFOV;
            }
            if (!(c.aspect > 0)) {
                return "aspect must be a positive number, got " + c.aspect;
            }
            Vector3d view = new Vector3d(), side = new Vector3d();
            view.sub(c.target, c.eye);
            double distance = view.length();
            if (!(distance > 0)) {
                return "camera eye and target are the same point " + c.eye + "; the view direction is undefined";
            }
            side.cross(view, c.up);
            if (!(side.length() > 1e-12 * c.up.length() * distance)) {
                return "camera up " + c.up + " is zero or parallel to the view direction (eye - target)";
            }
        } else if (o instanceof Sphere && !(((Sphere) o).radius > 0)) {
            return "sphere radius must be a positive number, got " + ((Sphere) o).radius;
        } else if (o instanceof BlinnPhong && !(((BlinnPhong) o).exponent >= 0)) {
            return "exponent must be a number >= 0, got " + ((BlinnPhong) o).exponent;
        } else if (o instanceof GlazedMaterial && ((GlazedMaterial) o).base == o) {
            return "a glazed material cannot be its own base";
        }
        return null;
    }

    // ---- fields ----

    private void parameter(String[] w) throws SceneFormatException {
        String type = w[0];
        String cls = current.getClass().getSimpleName();
        if (w.length < 2) {
            throw error("'" + type + "' needs a field name and a value (expected '" + type + " <field> " + placeholder(type) + "')");
        }
        String name = w[1];
        Field f = field(current.getClass(), name);
        Class<?> ft = f.getType();
        String fits = keyword(ft);
        if (fits == null) {
            throw error("field '" + name + "' of " + cls + " is a " + ft.getSimpleName()
                    + ", which a scene cannot set (expected a field of type int, double, String, Vector3d or an object)");
        }
        if (!fits.equals(type)) {
            throw error("'" + type + " " + name + "' does not fit: " + name + " of " + cls + " is a " + ft.getSimpleName()
                    + " (expected '" + fits + " " + name + " " + placeholder(fits) + "')");
        }
        if (w.length < 3) {
            throw error("'" + type + " " + name + "' has no value (expected '" + type + " " + name + " " + placeholder(type) + "')");
        }
        Integer first = currentFields.putIfAbsent(name, line);
        if (first != null) {
            throw error("field '" + name + "' is set twice (first at line " + first + "; expected each field once per object)");
        }
        Object v = value(type, name, ft, w[2]);
        try {
            f.set(current, v);
        } catch (IllegalAccessException | RuntimeException e) {
            throw error("cannot set field '" + name + "' of " + cls + ": " + describe(e));
        }
    }

    private Object value(String type, String name, Class<?> ft, String value) throws SceneFormatException {
        switch (type) {
            case "int":
                if (ft == long.class || ft == Long.class) {
                    return parseWhole(value, name, Long.MIN_VALUE, Long.MAX_VALUE);
                }
                return (int) parseWhole(value, name, Integer.MIN_VALUE, Integer.MAX_VALUE);
            case "double":
                double d = parseDouble(value, name);
                if (ft == float.class || ft == Float.class) {
                    if (!Float.isFinite((float) d)) {
                        throw error(quote(value) + " is too large for " + name + " (expected a finite float, at most about 3.4e38)");
                    }
                    return (float) d;
                }
                return d;
            case "String":
                return value;
            case "Vector3d":
                return parseVector(value, name);
            default:
                return reference(name, ft, value);
        }
    }

    private Object reference(String name, Class<?> ft, String value) throws SceneFormatException {
        if (words(value).length > 1) {
            throw error("'ref " + name + "' takes one object name, found " + quote(value) + " (expected 'ref " + name + " <name>')");
        }
        Object target = named.get(value);
        if (target == null) {
            List<String> names = new ArrayList<>(named.keySet());
            names.sort(null);
            String some = String.join(", ", names.subList(0, Math.min(6, names.size()))) + (names.size() > 6 ? ", ..." : "");
            throw error("undefined object " + quote(value) + " in 'ref " + name + "' (expected the name of an object "
                    + "declared earlier in the file" + (named.isEmpty() ? "; none has a name yet)" : ", such as " + some + ")"));
        }
        if (target == current) {
            throw error(quote(value) + " is the object being defined (expected an object declared earlier; "
                    + "an object cannot refer to itself)");
        }
        if (!ft.isInstance(target)) {
            throw error(quote(value) + " is a " + target.getClass().getSimpleName() + ", but 'ref " + name + "' needs a " + ft.getSimpleName());
        }
        return target;
    }

    /** A field a scene may set: not private, static or final, found by name up the superclasses. */
    private Field field(Class<?> c, String name) throws SceneFormatException {
        String owner = c.getSimpleName();
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            Field d;
            try {
                d = k.getDeclaredField(name);
            } catch (NoSuchFieldException e) {
                continue;
            }
            int m = d.getModifiers();
            String why = Modifier.isPrivate(m) ? "private" : Modifier.isStatic(m) ? "static" : Modifier.isFinal(m) ? "final"
                    : d.isSynthetic() ? "synthetic" : null;
            if (why != null) {
                List<String> names = settableNames(c);
                throw error("field " + quote(name) + " of " + owner + " is " + why + " and cannot be set from a scene (expected one of: "
                        + (names.isEmpty() ? "none" : String.join(", ", names)) + ")");
            }
            d.setAccessible(true);
            return d;
        }
        List<String> names = settableNames(c);
        throw error(owner + " has no field " + quote(name) + " (" + caseHint(name, names) + "expected one of: "
                + (names.isEmpty() ? "none" : String.join(", ", names)) + ")");
    }

    private static List<String> settableNames(Class<?> c) {
        List<String> names = new ArrayList<>();
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            for (Field f : k.getDeclaredFields()) {
                int m = f.getModifiers();
                if (!Modifier.isPrivate(m) && !Modifier.isStatic(m) && !Modifier.isFinal(m) && !f.isSynthetic()
                        && keyword(f.getType()) != null && !names.contains(f.getName())) {
                    names.add(f.getName());
                }
            }
        }
        return names;
    }

    private String keywordOf(String fieldName) {
        try {
            return keyword(field(current.getClass(), fieldName).getType());
        } catch (SceneFormatException e) {
            return "<type>";
        }
    }

    /** The type keyword a field of type {@code t} takes, or null when a scene cannot set such a field. */
    private static String keyword(Class<?> t) {
        if (t == int.class || t == Integer.class || t == long.class || t == Long.class) return "int";
        if (t == double.class || t == Double.class || t == float.class || t == Float.class) return "double";
        if (t == String.class) return "String";
        if (t == Vector3d.class || t == javax.vecmath.Tuple3d.class) return "Vector3d";
        if (t.isPrimitive() || t.isArray() || Number.class.isAssignableFrom(t) || t == Boolean.class || t == Character.class
                || javax.vecmath.Tuple3d.class.isAssignableFrom(t) || CharSequence.class.isAssignableFrom(t)) {
            return null;
        }
        return "ref";
    }

    private static String placeholder(String k) {
        switch (k) {
            case "int": return "<whole number>";
            case "double": return "<number>";
            case "String": return "<text>";
            case "Vector3d": return "[x y z]";
            default: return "<name>";
        }
    }

    // ---- global settings ----

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
        switch (key) {
            case "BGColor": scene.backgroundColor = parseVector(value, key); break;
            case "AmbientLight": scene.ambientLight = parseVector(value, key); break;
            case "Width": scene.width = range(value, key, 1, MAX_SIDE); break;
            case "Height": scene.height = range(value, key, 1, MAX_SIDE); break;
            case "AASamples": scene.samplesPerPixel = range(value, key, 1, MAX_AA_SAMPLES); break;
            default: scene.maxDepth = range(value, key, 0, MAX_DEPTH);
        }
    }

    private int range(String value, String key, int min, int max) throws SceneFormatException {
        String expected = " (expected " + min + " to " + max + ")";
        if (!isWhole(value)) {
            throw error(quote(value) + " is not a whole number for " + key + expected);
        }
        Long v = wholeValue(value);
        if (v == null || v < min || v > max) {
            throw error(quote(key + " " + value) + " is out of range" + expected);
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
        if (!aspectSet) {
            scene.camera.aspect = (double) scene.width / scene.height;
        }
        return scene;
    }

    // ---- values ----

    private long parseWhole(String s, String what, long min, long max) throws SceneFormatException {
        String expected = " (expected an integer from " + min + " to " + max + ")";
        if (!isWhole(s)) {
            throw error(quote(s) + " is not a whole number for " + what + expected);
        }
        Long v = wholeValue(s);
        if (v == null || v < min || v > max) {
            throw error(quote(s) + " is out of range for " + what + expected);
        }
        return v;
    }

    private static boolean isWhole(String s) {
        return s.matches("[+-]?[0-9]+");
    }

    private static Long wholeValue(String s) {
        BigInteger v = new BigInteger(s.startsWith("+") ? s.substring(1) : s);
        return v.bitLength() < 64 ? v.longValue() : null;
    }

    private double parseDouble(String s, String what) throws SceneFormatException {
        String expected = " (expected a decimal number such as 1.5 or -2e3)";
        if (isNonFiniteWord(s)) {
            throw error(quote(s) + " is not a finite number for " + what + expected);
        }
        if (!isDecimal(s)) {
            throw error(quote(s) + " is not a number for " + what + expected);
        }
        double d = Double.parseDouble(s);
        if (!Double.isFinite(d)) {
            throw error(quote(s) + " is too large for " + what + " (expected a finite number, at most about 1.8e308)");
        }
        return d;
    }

    private static boolean isNonFiniteWord(String s) {
        String t = s.startsWith("+") || s.startsWith("-") ? s.substring(1) : s;
        return t.equalsIgnoreCase("nan") || t.equalsIgnoreCase("infinity") || t.equalsIgnoreCase("inf");
    }

    /** [+-] digits [. digits] [e [+-] digits], or starting with the point; no NaN, Infinity, hex or suffix. */
    private static boolean isDecimal(String s) {
        return s.matches("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?");
    }

    /** {@code [x y z]}: three finite numbers in brackets, separated by spaces or commas. */
    private Vector3d parseVector(String s, String what) throws SceneFormatException {
        String expected = " (expected [x y z], three numbers in brackets)";
        String malformed = "malformed vector " + quote(s) + " for " + what + ": ";
        if (!s.startsWith("[")) {
            throw error(malformed + "missing '['" + expected);
        }
        if (s.length() < 2 || !s.endsWith("]")) {
            throw error(malformed + "missing ']'" + expected);
        }
        String inner = s.substring(1, s.length() - 1).strip();
        String[] parts = inner.isEmpty() ? new String[0] : inner.split("[\\s,]+");
        if (parts.length != 3) {
            throw error(malformed + "found " + parts.length + (parts.length == 1 ? " number" : " numbers") + expected);
        }
        double[] v = new double[3];
        for (int k = 0; k < 3; k++) {
            String p = parts[k];
            if (isNonFiniteWord(p)) {
                throw error(malformed + quote(p) + " is not a finite number" + expected);
            }
            if (!isDecimal(p)) {
                throw error(malformed + quote(p) + " is not a number" + expected);
            }
            v[k] = Double.parseDouble(p);
            if (!Double.isFinite(v[k])) {
                throw error(malformed + quote(p) + " is too large (expected finite numbers, at most about 1.8e308)");
            }
        }
        return new Vector3d(v[0], v[1], v[2]);
    }

    // ---- messages ----

    private SceneFormatException error(String message) {
        return new SceneFormatException(file, line, message);
    }

    /** {@code s} in single quotes, cut to 60 characters, invisible characters escaped. */
    private static String quote(String s) {
        int n = Math.min(s.length(), QUOTE_MAX);
        StringBuilder b = new StringBuilder("'");
        for (int at = 0; at < n; at++) {
            char c = s.charAt(at);
            if (c == '\t') {
                b.append("\\t");
            } else if (c < 0x20 || c == 0x7f || (c >= 0x80 && (Character.isWhitespace(c) || Character.isSpaceChar(c)
                    || Character.getType(c) == Character.FORMAT || Character.getType(c) == Character.CONTROL))) {
                b.append(String.format("\\u%04X", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.append(s.length() > n ? "...'" : "'").toString();
    }

    /** The option equal to {@code s} but for case, as a "did you mean" hint ending in "; ", or "". */
    private static String caseHint(String s, Collection<String> options) {
        for (String o : options) {
            if (o.equalsIgnoreCase(s) && !o.equals(s)) {
                return "did you mean '" + o + "'? names are case-sensitive; ";
            }
        }
        return "";
    }

    private static String describe(Throwable e) {
        return e.getClass().getSimpleName() + (e.getMessage() == null ? "" : " (" + e.getMessage() + ")");
    }

    private static String oneLine(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            b.append(c < 0x20 || c == 0x7f || c == 0x85 || c == 0x2028 || c == 0x2029 ? String.format("\\u%04X", (int) c) : String.valueOf(c));
        }
        return b.toString();
    }
}
