package ray.parse;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ray.Scene;

/**
 * Reads the scene format ({@code scene-format.md}): object headers {@code <ObjectType> <ClassName> [name]},
 * parameter lines {@code <type> <field> <value>} written straight into the object's field, a blank line
 * ending an object, global settings and {@code #} comments. Every mistake is a
 * {@link SceneFormatException} naming the file and line, what was found and what was expected;
 * nothing else escapes (docs/bad-input.md lists them). One parser reads one file.
 *
 * <p>The parser reads lines ({@link Lines}), splits each into words ({@link Words}) and decides what
 * the line is: a header (the class resolved by {@link ClassResolver}), a parameter ({@link Parameters},
 * reading values with {@link Values}), a global ({@link Globals}, the one table of them) or a mistake.
 * Objects live and end in {@link SceneObjects}; what is checked once the file is read is {@link PostPass}.
 * Every line takes this one path: a plain line of a large scene costs no String, by the way the words
 * and values are read, not by a second grammar.
 */
public final class Parser {

    /** The globals' keywords ({@link Globals}: the one table of them). */
    static final List<String> GLOBALS = Globals.NAMES;
    static final List<String> TYPES = List.of("int", "double", "String", "ref", "Vector3d");
    static final String[] TYPE_NAMES = TYPES.toArray(new String[0]);
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
    private final Scene scene = new Scene();
    private final SceneObjects objects;
    private final Parameters parameters;
    private final Words words = new Words();
    private final Map<String, Integer> globalLines = new HashMap<>();
    /** The last header's type, class name (also as chars) and class: a large scene repeats one header line after line. */
    private String lastType, lastClassName;
    private char[] lastTypeChars, lastClassChars;
    private Class<?> lastBase, lastClass;

    private int line;
    /** The scene file when read from one (an input the output must never replace). */
    private Path source;

    private Parser(String file, ClassLoader loader) {
        this.file = file;
        this.resolver = new ClassResolver(loader);
        this.objects = new SceneObjects(file, scene);
        this.parameters = new Parameters(file, objects);
    }

    /** Reads and parses {@code path}; the file is named in messages as given. */
    public static Scene parse(Path path) throws SceneFormatException {
        return parse(path, new ArrayList<>());
    }

    /** As {@link #parse(Path)}, adding warnings (e.g. zero-area triangles) as {@code file:line: warning: ...}. */
    public static Scene parse(Path path, List<String> warnings) throws SceneFormatException {
        return parse(path, warnings, null);
    }

    /**
     * As {@link #parse(Path, List)}, telling {@code beforeFile} (when not null) before each file an object
     * names is read; an Error of its own class that it throws ends the parse and leaves this method unchanged.
     */
    public static Scene parse(Path path, List<String> warnings, BeforeFile beforeFile) throws SceneFormatException {
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
        p.objects.beforeFile = beforeFile;
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
        Words w = words;
        while (lines.advance()) {
            line = lines.line();
            if (!w.split(lines.chars(), lines.length())) {
                if (w.blank) {
                    objects.blankLine(line);      // a blank line ends the object; a comment line does not
                }
                continue;
            }
            any = true;
            statement(w);
        }
        line = Math.max(1, lines.line());
        objects.end();
        if (!any) {
            throw error("empty scene file (expected at least Width, Height and a Camera)");
        }
        return PostPass.finish(file, scene, objects, globalLines, line, warningsOut);
    }

    /** The parameter types' places in {@link #TYPES}. */
    static final int INT = 0, DOUBLE = 1, STRING = 2, REF = 3, VECTOR = 4;
    private static final char[][] TYPE_CHARS = {"int".toCharArray(), "double".toCharArray(), "String".toCharArray(),
        "ref".toCharArray(), "Vector3d".toCharArray()};

    /** The place in {@link #TYPES} of the type keyword the line starts with, or -1. */
    private static int typeOf(Words w) {
        switch (w.to0 - w.from0) {      // by length first: most lines are Vector3d, double or ref
            case 8:
                return w.firstIs(TYPE_CHARS[VECTOR]) ? VECTOR : -1;
            case 6:
                return w.firstIs(TYPE_CHARS[DOUBLE]) ? DOUBLE : w.firstIs(TYPE_CHARS[STRING]) ? STRING : -1;
            case 3:
                return w.firstIs(TYPE_CHARS[REF]) ? REF : w.firstIs(TYPE_CHARS[INT]) ? INT : -1;
            default:
                return -1;
        }
    }

    private void statement(Words w) throws SceneFormatException {
        int type = typeOf(w);
        if (type >= 0) {
            if (objects.current() == null) {
                throw error("parameter line outside an object (expected an object header such as 'Surface Sphere' above it, with no blank line between)");
            }
            if (!objects.open()) {
                throw error("parameter line outside an object: the blank line at line " + objects.blankAfter() + " ended the "
                        + objects.describeCurrent() + " (expected no blank line inside an object)");
            }
            parameters.parameter(w, type, line);
            return;
        }
        if (w.count == 2 && lastType != null && w.firstIs(lastTypeChars) && Words.same(w.line, w.from1, w.to1, lastClassChars)) {
            objects.end();               // the header the line before last read: its class is known
            objects.begin(lastType, lastBase, lastClassName, lastClass, null, line);
            return;
        }
        String head = w.first();
        if (objects.open() && !ClassResolver.BASES.containsKey(head) && !GLOBALS.contains(head)) {
            if (Fields.settableNames(objects.current().getClass()).contains(head)) {
                String s = w.statement();
                throw error(Values.quote(s) + " has no type (expected " + Values.quote(parameters.keywordOf(head) + " " + s) + ")");
            }
            throw error("unknown parameter type " + Values.quote(head) + " (" + Values.caseHint(head, KEYWORDS)
                    + "expected int, double, String, ref or Vector3d, or a new object header)");
        }
        objects.end();
        if (ClassResolver.BASES.containsKey(head)) {
            header(w, head);
        } else if (GLOBALS.contains(head)) {
            global(head, w.count > 1 ? w.afterFirst() : "");
        } else {
            throw error("unknown keyword " + Values.quote(head) + " (" + Values.caseHint(head, KEYWORDS)
                    + "expected Camera, Surface, Material, Light or a global: " + String.join(", ", GLOBALS) + ")");
        }
    }

    private void header(Words w, String type) throws SceneFormatException {
        String form = "'" + type + " <ClassName> [name]'";
        if (w.count < 2) {
            throw error("'" + type + "' needs a class name (expected " + form + ", e.g. '" + type + " "
                    + ClassResolver.builtIns(type).split(",")[0] + "')");
        }
        if (w.count == 3 && !w.restIsOneWord()) {
            throw error("too many words in " + Values.quote(w.statement()) + " (expected " + form + ")");
        }
        String className = w.second();
        Class<?> c;
        try {
            c = resolver.resolve(type, className);
        } catch (Problem p) {
            throw error(p.getMessage());
        }
        String name = w.count == 3 ? w.rest() : null;
        String used = name == null ? null : objects.nameUse(name);
        if (used != null) {
            throw error("the name " + Values.quote(name) + " is already used by " + used + " (expected a name used once in the file)");
        }
        Class<?> base = ClassResolver.BASES.get(type);
        objects.begin(type, base, className, c, name, line);
        if (!type.equals(lastType) || !className.equals(lastClassName)) {
            lastType = type;
            lastClassName = className;
            lastTypeChars = type.toCharArray();
            lastClassChars = className.toCharArray();
        }
        lastBase = base;
        lastClass = c;
    }

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

    private SceneFormatException error(String message) {
        return new SceneFormatException(file, line, message);
    }

    static String describe(Throwable e) {
        return e.getClass().getSimpleName() + (e.getMessage() == null ? "" : " (" + e.getMessage() + ")");
    }
}
