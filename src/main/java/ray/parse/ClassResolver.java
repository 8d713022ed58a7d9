package ray.parse;

import java.lang.reflect.Constructor;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import ray.Camera;
import ray.light.Light;
import ray.material.Material;
import ray.surface.Surface;

/**
 * Finds the class a scene header names, without running any of its code until it is known to be a
 * concrete subclass of the header's type. A simple name is looked up in the default package first (a
 * student's own classes, as in the original course) and then in the built-in packages; a qualified
 * name ({@code my.pkg.Torus}) is taken as it is.
 */
final class ClassResolver {

    /** Header keyword to base class. */
    static final Map<String, Class<?>> BASES = Map.of(
            "Camera", Camera.class, "Surface", Surface.class, "Material", Material.class, "Light", Light.class);

    /** Other names accepted for built-in classes. */
    private static final Map<String, String> ALIASES = Map.of("Glazed", "GlazedMaterial", "Dielectric", "DielectricMaterial");

    private static final String[] PACKAGES = {"ray.surface.", "ray.material.", "ray.light.", "ray."};

    private final ClassLoader loader;
    /** Classes already resolved in this file, by header type and name: a failed lookup costs an exception. */
    private final Map<String, Class<?>> resolved = new HashMap<>();

    ClassResolver(ClassLoader loader) {
        this.loader = loader;
    }

    /** The class for {@code name} under header {@code type}; a message for the user on failure. */
    Class<?> resolve(String type, String name) throws Problem {
        String key = type + " " + name;
        Class<?> c = resolved.get(key);
        if (c == null) {
            c = lookUp(type, name);
            resolved.put(key, c);
        }
        return c;
    }

    private Class<?> lookUp(String type, String name) throws Problem {
        Class<?> base = BASES.get(type);
        if (!isClassName(name)) {
            throw new Problem(Values.quote(name) + " is not a class name" + expected(type));
        }
        String canonical = ALIASES.getOrDefault(name, name);
        Class<?> c = find(canonical);
        if (c == null) {
            List<String> known = new ArrayList<>(List.of(builtIns(type).replace(" (or ", ", ").replace(")", "").split(", ")));
            String hint = Values.caseHint(name, known);
            throw new Problem("unknown " + type + " class " + Values.quote(name) + " (" + hint + "expected " + builtIns(type)
                    + " or a " + type + " class of your own on the class path)");
        }
        // everything up to here only loaded the class; nothing of it has run
        if (!base.isAssignableFrom(c)) {
            String what = kindOf(c);
            throw new Problem(Values.quote(name) + " is " + (what == null ? "not a " + type : "a " + what + ", not a " + type) + expected(type));
        }
        if (c.isInterface() || Modifier.isAbstract(c.getModifiers())) {
            throw new Problem(Values.quote(name) + " is abstract and cannot be created" + expected(type));
        }
        if (!Modifier.isPublic(c.getModifiers())) {
            throw new Problem("class " + Values.quote(name) + " is not public (expected a public class with a public no-argument constructor)");
        }
        try {
            Constructor<?> k = c.getConstructor();
            if (!Modifier.isPublic(k.getModifiers())) {
                throw new NoSuchMethodException();
            }
        } catch (NoSuchMethodException | LinkageError | RuntimeException e) {
            throw new Problem("class " + Values.quote(name) + " has no public no-argument constructor (expected one, as scene objects are created empty)");
        }
        return c;
    }

    /**
     * The end of a message about a header's class: the built-ins it could name. Built only when a message
     * needs it: the list comes from scanning the class path ({@link BuiltIns}), which a scene without
     * mistakes must not pay for at every start.
     */
    private static String expected(String type) {
        return " (expected " + builtIns(type) + " or a " + type + " class of your own)";
    }

    /** A Java class name, simple or qualified: identifiers separated by single dots, not absurdly long. */
    static boolean isClassName(String name) {
        if (name.isEmpty() || name.length() > 200) {
            return false;
        }
        boolean start = true;
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            if (c == '.') {
                if (start) {
                    return false;
                }
                start = true;
            } else if (start ? Character.isJavaIdentifierStart(c) : Character.isJavaIdentifierPart(c)) {
                if (Character.isIdentifierIgnorable(c)) {
                    return false;
                }
                start = false;
            } else {
                return false;
            }
        }
        return !start;
    }

    private Class<?> find(String name) throws Problem {
        if (name.contains(".")) {
            return load(name);
        }
        Class<?> c = load(name);          // default package: the user's own classes
        for (int i = 0; c == null && i < PACKAGES.length; i++) {
            c = load(PACKAGES[i] + name);
        }
        return c;
    }

    /**
     * The class, or null when there is none of that name. A class file that is there but cannot be
     * loaded is a {@link Problem} naming the real cause, not "unknown class": compiled for a newer Java,
     * its superclass or another class it needs missing from the class path, a damaged class file.
     */
    private Class<?> load(String qualified) throws Problem {
        try {
            return Class.forName(qualified, false, loader);   // never initialised here
        } catch (ClassNotFoundException | RuntimeException e) {
            return null;
        } catch (UnsupportedClassVersionError e) {
            throw new Problem("class " + Values.quote(qualified) + " cannot be loaded: it was compiled for a newer Java than this one (Java "
                    + Runtime.version().feature() + "): " + ray.Failures.message(e) + " (expected it recompiled, e.g. javac --release "
                    + Runtime.version().feature() + ")");
        } catch (NoClassDefFoundError e) {
            String m = ray.Failures.message(e);
            if (m != null && m.contains("wrong name")) {
                return null;      // a case-insensitive file system found Sphere.class for 'sphere': no class of that name
            }
            throw new Problem("class " + Values.quote(qualified) + " cannot be loaded: it needs the class " + (m == null ? "?" : m.replace('/', '.'))
                    + ", which is not on the class path (expected every class it extends or uses compiled beside it)");
        } catch (LinkageError e) {
            throw new Problem("class " + Values.quote(qualified) + " cannot be loaded: " + ray.Failures.simpleName(e.getClass())
                    + (ray.Failures.message(e) == null ? "" : " (" + ray.Failures.message(e) + ")") + " (expected a class file javac wrote)");
        }
    }

    private static String kindOf(Class<?> c) {
        for (Map.Entry<String, Class<?>> e : BASES.entrySet()) {
            if (e.getValue().isAssignableFrom(c)) {
                return e.getKey();
            }
        }
        return null;
    }

    /**
     * The built-in classes a header of {@code type} can name, for messages: the framework's own first (as
     * the course names them), then the others by name, aliases in parentheses. Derived from the classes
     * in the base class's package on the class path (each a concrete public subclass with a public no-arg
     * constructor, exactly what {@link #resolve} accepts), never kept by hand.
     */
    static String builtIns(String type) {
        return BuiltIns.LISTS.getOrDefault(type, "");
    }

    /** The lists, found once on first use (only messages need them). */
    private static final class BuiltIns {
        /** The framework's classes, listed first in this order; the rest follow by name. */
        private static final List<String> FIRST = List.of("Sphere", "Triangle", "Diffuse", "BlinnPhong", "GlazedMaterial", "PointLight");
        static final Map<String, String> LISTS = scan();

        private static Map<String, String> scan() {
            Map<String, String> out = new HashMap<>();
            for (Map.Entry<String, Class<?>> e : BASES.entrySet()) {
                List<String> names = new ArrayList<>();
                for (String n : classesBeside(e.getValue())) {
                    if (acceptable(e.getValue(), e.getValue().getPackageName() + "." + n)) {
                        names.add(n);
                    }
                }
                names.sort(java.util.Comparator.comparingInt((String n) -> FIRST.contains(n) ? FIRST.indexOf(n) : FIRST.size())
                        .thenComparing(String.CASE_INSENSITIVE_ORDER));
                List<String> shown = new ArrayList<>();
                for (String n : names) {
                    String alias = null;
                    for (Map.Entry<String, String> a : ALIASES.entrySet()) {
                        if (a.getValue().equals(n)) {
                            alias = a.getKey();
                        }
                    }
                    shown.add(alias == null ? n : n + " (or " + alias + ")");
                }
                out.put(e.getKey(), String.join(", ", shown));
            }
            return Map.copyOf(out);
        }

        private static boolean acceptable(Class<?> base, String qualified) {
            try {
                Class<?> c = Class.forName(qualified, false, base.getClassLoader());
                return base.isAssignableFrom(c) && !c.isInterface() && !Modifier.isAbstract(c.getModifiers())
                        && Modifier.isPublic(c.getModifiers()) && Modifier.isPublic(c.getConstructor().getModifiers());
            } catch (ClassNotFoundException | NoSuchMethodException | LinkageError | RuntimeException e) {
                return false;
            }
        }

        /** The simple names of the top-level classes in {@code base}'s package, from where {@code base} was loaded (a folder or a jar). */
        private static List<String> classesBeside(Class<?> base) {
            List<String> names = new ArrayList<>();
            String dir = base.getPackageName().replace('.', '/') + "/";
            try {
                java.net.URL where = base.getProtectionDomain().getCodeSource().getLocation();
                java.nio.file.Path root = java.nio.file.Path.of(where.toURI());
                if (java.nio.file.Files.isDirectory(root)) {
                    try (java.util.stream.Stream<java.nio.file.Path> files = java.nio.file.Files.list(root.resolve(dir))) {
                        files.forEach(f -> addClass(f.getFileName().toString(), names));
                    }
                } else {
                    try (java.util.jar.JarFile jar = new java.util.jar.JarFile(root.toFile())) {
                        jar.stream().map(java.util.jar.JarEntry::getName)
                                .filter(n -> n.startsWith(dir) && n.indexOf('/', dir.length()) < 0)
                                .forEach(n -> addClass(n.substring(dir.length()), names));
                    }
                }
            } catch (java.io.IOException | java.net.URISyntaxException | RuntimeException e) {
                names.add(base.getSimpleName());   // nowhere to look: at least the base's own name
            }
            return names;
        }

        private static void addClass(String file, List<String> names) {
            if (file.endsWith(".class") && file.indexOf('$') < 0 && !file.equals("package-info.class")) {
                names.add(file.substring(0, file.length() - ".class".length()));
            }
        }
    }
}
