package ray.parse;

import java.lang.reflect.Constructor;
import java.lang.reflect.Modifier;
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
    private static final Map<String, String> ALIASES = Map.of("Glazed", "GlazedMaterial");

    private static final String[] PACKAGES = {"ray.surface.", "ray.material.", "ray.light.", "ray."};

    private final ClassLoader loader;

    ClassResolver(ClassLoader loader) {
        this.loader = loader;
    }

    /** The class for {@code name} under header {@code type}; a message for the user on failure. */
    Class<?> resolve(String type, String name) throws Problem {
        Class<?> base = BASES.get(type);
        if (!name.matches("[A-Za-z_$][A-Za-z0-9_$]*(\\.[A-Za-z_$][A-Za-z0-9_$]*)*")) {
            throw new Problem("'" + name + "' is not a class name (expected a " + type + " class such as "
                    + example(type) + ")");
        }
        String canonical = ALIASES.getOrDefault(name, name);
        Class<?> c = find(canonical);
        if (c == null) {
            throw new Problem("unknown " + type + " class '" + name + "' (built-in: " + builtIns(type)
                    + "; or a class of your own on the class path)");
        }
        if (!base.isAssignableFrom(c)) {
            String what = kindOf(c);
            throw new Problem("'" + name + "' is " + (what == null ? "not a " + type : "a " + what + ", not a " + type)
                    + " (expected a " + type + " class such as " + example(type) + ")");
        }
        if (c.isInterface() || Modifier.isAbstract(c.getModifiers())) {
            throw new Problem("'" + name + "' is abstract and cannot be created (expected a concrete " + type
                    + " class such as " + example(type) + ")");
        }
        if (!Modifier.isPublic(c.getModifiers())) {
            throw new Problem("class '" + name + "' is not public (scene classes must be public with a public no-argument constructor)");
        }
        try {
            Constructor<?> k = c.getConstructor();
            if (!Modifier.isPublic(k.getModifiers())) {
                throw new NoSuchMethodException();
            }
        } catch (NoSuchMethodException | LinkageError e) {
            throw new Problem("class '" + name + "' has no public no-argument constructor");
        }
        return c;
    }

    private Class<?> find(String name) {
        if (name.contains(".")) {
            return load(name);
        }
        Class<?> c = load(name);          // default package: the user's own classes
        for (int i = 0; c == null && i < PACKAGES.length; i++) {
            c = load(PACKAGES[i] + name);
        }
        return c;
    }

    private Class<?> load(String qualified) {
        try {
            return Class.forName(qualified, false, loader);   // never initialised here
        } catch (ClassNotFoundException | LinkageError e) {
            return null;
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

    static String builtIns(String type) {
        switch (type) {
            case "Camera": return "Camera";
            case "Surface": return "Sphere, Triangle";
            case "Material": return "Diffuse, BlinnPhong, GlazedMaterial (or Glazed)";
            default: return "PointLight";
        }
    }

    private static String example(String type) {
        return builtIns(type).split(",")[0];
    }

    /** A user-facing message, turned into a located {@link SceneFormatException} by the parser. */
    static final class Problem extends Exception {
        private static final long serialVersionUID = 1L;

        Problem(String message) {
            super(message, null, false, false);
        }
    }
}
