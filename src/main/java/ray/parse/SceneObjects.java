package ray.parse;

import java.lang.reflect.Constructor;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import ray.Camera;
import ray.Scene;
import ray.SceneObject;
import ray.light.Light;
import ray.material.Material;
import ray.surface.Surface;

/**
 * The life cycle of a scene file's objects: created empty at their header ({@link #begin}), their
 * fields set by {@link Parameters} while they are the object being read, named for later {@code ref}
 * lines, and ended ({@link #end}) at the next header, global or the end of the file: {@code init()},
 * their own files read, plausibility warnings noted, and added to the {@link Scene} by kind. What the
 * post-pass needs (CSG operands, zero-area triangles, warnings) is kept here for {@link PostPass}.
 */
final class SceneObjects {

    private final String file;
    private final Scene scene;
    /** Scene classes' no-argument constructors, looked up once per file. */
    private final Map<Class<?>, Constructor<?>> constructors = new HashMap<>();
    private final Map<String, Object> named = new HashMap<>();
    private final Map<String, Integer> namedLines = new HashMap<>();

    // the object being read
    private Object current;
    private String currentType;
    /** The base class of its type (Camera, Surface, Material or Light: {@link ClassResolver#BASES}). */
    private Class<?> currentBase;
    private int currentLine;
    private int blankAfter;            // the blank line that ended it (0: still open)
    private final FieldLines currentFields = new FieldLines();

    private int cameraLine;
    /** Zero-area surfaces: how many, and the first one's line. */
    int degenerate, firstDegenerateLine;
    /** Surfaces other surfaces are built from (CSG operands): left out of the scene by the post-pass. */
    final Set<Surface> operands = Collections.newSetFromMap(new IdentityHashMap<>());
    /** Surfaces whose operands are known to lead back to none of them (checked once: {@link OperandGraph}). */
    private final Set<Surface> acyclic = Collections.newSetFromMap(new IdentityHashMap<>());
    /** Plausibility warnings ({@link Plausibility}), in the order of their objects. */
    final List<String> plausibility = new ArrayList<>();
    /** Told before a Mesh's OBJ file is read (null: nobody asked); what it throws is let through. */
    BeforeFile beforeFile;

    SceneObjects(String file, Scene scene) {
        this.file = file;
        this.scene = scene;
    }

    /** The object being read, or null before the first header and after the last one ended. */
    Object current() {
        return current;
    }

    /** Whether an object is being read and no blank line has ended it. */
    boolean open() {
        return current != null && blankAfter == 0;
    }

    /** The blank line that ended the object being read (0: none). */
    int blankAfter() {
        return blankAfter;
    }

    /** A blank line at {@code line}: it ends the object being read, if any (a comment line does not). */
    void blankLine(int line) {
        if (current != null && blankAfter == 0) {
            blankAfter = line;
        }
    }

    /** The fields the object being read has set, with their lines. */
    FieldLines currentFields() {
        return currentFields;
    }

    /** "the Surface Sphere of line 12": the object being read, for messages. */
    String describeCurrent() {
        return currentType + " " + current.getClass().getSimpleName() + " of line " + currentLine;
    }

    /** The object named {@code name}, or null. */
    Object named(String name) {
        return named.get(name);
    }

    /** The names given so far, sorted (for "expected ..." messages). */
    List<String> names() {
        List<String> names = new ArrayList<>(named.keySet());
        names.sort(null);
        return names;
    }

    /** "the Sphere at line 12": what {@code name} names, for a message about using it twice; null when unused. */
    String nameUse(String name) {
        Object o = named.get(name);
        return o == null ? null : "the " + o.getClass().getSimpleName() + " at line " + namedLines.get(name);
    }

    /**
     * Creates the object of a header at {@code line} and makes it the one being read: {@code type} is
     * the header's first word, {@code base} its class in {@link ClassResolver#BASES}, {@code c} the
     * resolved class named {@code className}.
     */
    void begin(String type, Class<?> base, String className, Class<?> c, String name, int line) throws SceneFormatException {
        Object o;
        if (c == ray.surface.Triangle.class) {          // the classes a large scene repeats, made without reflection:
            o = new ray.surface.Triangle();            // past 15 reflective calls the JDK generates an accessor class
        } else if (c == ray.surface.Sphere.class) {     // (its generator's 17 classes load outside the CDS archive)
            o = new ray.surface.Sphere();
        } else {
            o = create(c, className, line);
        }
        current = o;
        currentType = type;
        currentBase = base;
        currentLine = line;
        blankAfter = 0;
        currentFields.clear();
        if (name != null) {
            named.put(name, o);
            namedLines.put(name, line);
            scene.name(o, name);
        }
    }

    /** A new {@code c} by its public no-argument constructor (looked up once per file); a failure is reported at {@code line}. */
    private Object create(Class<?> c, String className, int line) throws SceneFormatException {
        try {
            Constructor<?> k = constructors.get(c);
            if (k == null) {
                k = c.getConstructor();
                constructors.put(c, k);
            }
            return k.newInstance();
        } catch (InvocationTargetException e) {
            throw new SceneFormatException(file, line, "creating " + className + " failed: " + Parser.describe(e.getCause()));
        } catch (ReflectiveOperationException | RuntimeException | LinkageError e) {
            throw new SceneFormatException(file, line, "creating " + className + " failed: " + Parser.describe(e));
        }
    }

    /** Ends the object being read, if any: validates it (init) and adds it to the scene. Problems are reported at its header. */
    void end() throws SceneFormatException {
        if (current == null) {
            return;
        }
        Object o = current;
        current = null;
        int line = currentLine;
        try {
            ((SceneObject) o).init();
            if (o instanceof ReadsFiles r) {
                readFiles(o, r);
            } else if (o instanceof ray.surface.Mesh m) {   // geometry reads no files: the parser reads its OBJ
                if (beforeFile != null) {
                    beforeFile.beforeFile(scene, size(m.file));
                }
                readFiles(o, new ReadsFiles() {                // a class, not a lambda: no lambda on the parse path
                    @Override
                    public void readFiles(Path folder) throws SceneFormatException {
                        ObjFile.loadInto(m, folder);
                    }
                });
            }
        } catch (IllegalArgumentException | IllegalStateException e) {
            throw error(line, currentType + " " + o.getClass().getSimpleName() + ": " + e.getMessage());
        } catch (RuntimeException | LinkageError | AssertionError | StackOverflowError e) {
            throw error(line, o.getClass().getSimpleName() + ".init() failed: " + Parser.describe(e));
        }
        List<String[]> doubts = Plausibility.of(o);
        for (int i = 0; i < doubts.size(); i++) {      // indexed: no iterator per object
            String[] w = doubts.get(i);
            int at = currentFields.lineOf(w[0]);
            plausibility.add(file + ":" + (at > 0 ? at : line) + ": warning: " + o.getClass().getSimpleName() + " " + w[1]);
        }
        if (currentBase == Surface.class) {
            addSurface((Surface) o, line);
        } else if (currentBase == Camera.class) {
            if (scene.camera != null) {
                throw error(line, "a second camera (first at line " + cameraLine + "; expected one camera per scene)");
            }
            scene.camera = (Camera) o;
            cameraLine = line;
        } else if (currentBase == Material.class) {
            scene.materials.add((Material) o);
        } else {
            scene.lights.add((Light) o);
        }
    }

    private void addSurface(Surface s, int line) throws SceneFormatException {
        if (s.material == null) {
            throw error(line, s.getClass().getSimpleName() + " has no material (expected 'ref material <name>' in the object)");
        }
        boolean flat;
        try {
            flat = s.isDegenerate();
        } catch (RuntimeException | LinkageError e) {
            throw error(line, s.getClass().getSimpleName() + ".isDegenerate() failed: " + Parser.describe(e));
        }
        if (flat && degenerate++ == 0) {
            firstDegenerateLine = line;
        }
        try {
            List<Surface> ops = s.operands();
            if (!ops.isEmpty()) {
                String cycle = OperandGraph.cycle(s, acyclic);
                if (cycle != null) {
                    throw error(line, cycle);
                }
                operands.addAll(ops);
            }
        } catch (RuntimeException | LinkageError | StackOverflowError e) {
            throw error(line, s.getClass().getSimpleName() + ".operands() failed: " + Parser.describe(e));
        }
        scene.surfaces.add(s);
    }

    /** Lets an object read its own files; a mistake in one is reported at that file's line, naming this object. */
    private void readFiles(Object o, ReadsFiles r) throws SceneFormatException {
        try {
            r.readFiles(folder());
        } catch (SceneFormatException e) {
            throw new SceneFormatException(e.file(), e.line(), e.problem() + " (read for the " + currentType + " "
                    + o.getClass().getSimpleName() + " at " + file + ":" + currentLine + ")");
        }
    }

    /** The size of the file {@code name} names in the scene file's folder, or -1 (the reader says why, if it matters). */
    private long size(String name) {
        try {
            return java.nio.file.Files.size(folder().resolve(name));
        } catch (java.io.IOException | RuntimeException e) {
            return -1;
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

    private SceneFormatException error(int line, String message) {
        return new SceneFormatException(file, line, message);
    }
}
