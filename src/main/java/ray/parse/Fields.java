package ray.parse;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.vecmath.Tuple3d;

/**
 * The settable fields of scene classes: non-private, non-static, non-final fields found by exact name
 * up the superclass chain, and the type keyword ({@code int}, {@code double}, {@code String},
 * {@code Vector3d}, {@code ref}) each one takes. Looked up once per (class, name) and kept per class
 * as a short list that a parameter line's field name is compared with where it stands in the line.
 */
final class Fields {

    /**
     * A field a scene names: its name (also as chars), the field, and the type keyword it takes (null:
     * none, a scene cannot set it) with the keyword's place in {@link Parser#TYPES} (-1 for none).
     */
    record Entry(String name, char[] chars, Field field, String keyword, int type, int direct) {
    }

    /**
     * {@link Entry#direct}: a field of the built-in classes a large scene sets line after line, which
     * {@link #setDirect} stores without reflection (0: any other field, set by {@link Field#set}).
     */
    static final int TRIANGLE_V0 = 1, TRIANGLE_V1 = 2, TRIANGLE_V2 = 3, SPHERE_CENTER = 4, SPHERE_RADIUS = 5, SURFACE_MATERIAL = 6;

    /** The {@link Entry#direct} of field {@code f}: by the class that declares it, so a subclass's object gets it too. */
    private static int direct(Field f) {
        Class<?> c = f.getDeclaringClass();
        String n = f.getName();
        if (c == ray.surface.Triangle.class) {
            return n.equals("v0") ? TRIANGLE_V0 : n.equals("v1") ? TRIANGLE_V1 : n.equals("v2") ? TRIANGLE_V2 : 0;
        }
        if (c == ray.surface.Sphere.class) {
            return n.equals("center") ? SPHERE_CENTER : n.equals("radius") ? SPHERE_RADIUS : 0;
        }
        return c == ray.surface.Surface.class && n.equals("material") ? SURFACE_MATERIAL : 0;
    }

    /**
     * Stores {@code v} in the field {@code direct} names of {@code o}, as {@link Field#set} would, and
     * returns true; false (nothing stored) for 0. {@code Field.set} checks the object's class and the
     * value's on every call, two {@code Class.isAssignableFrom} calls, each a call into the VM under C1:
     * a tenth of a 100,000-triangle scene's parse. Here both are known already: the field is the
     * declaring class's own, looked up for the object's class, and the value is of the field's type
     * (the parameter line's type keyword was checked against it, and a ref's object by
     * {@code isInstance}).
     */
    static boolean setDirect(int direct, Object o, Object v) {
        switch (direct) {
            case TRIANGLE_V0: ((ray.surface.Triangle) o).v0 = (javax.vecmath.Vector3d) v; return true;
            case TRIANGLE_V1: ((ray.surface.Triangle) o).v1 = (javax.vecmath.Vector3d) v; return true;
            case TRIANGLE_V2: ((ray.surface.Triangle) o).v2 = (javax.vecmath.Vector3d) v; return true;
            case SPHERE_CENTER: ((ray.surface.Sphere) o).center = (javax.vecmath.Vector3d) v; return true;
            case SURFACE_MATERIAL: ((ray.surface.Surface) o).material = (ray.material.Material) v; return true;
            default: return false;
        }
    }

    /** {@link #setDirect(int, Object, Object)} for a double field, without boxing: as {@link Field#setDouble} would. */
    static boolean setDirect(int direct, Object o, double v) {
        if (direct == SPHERE_RADIUS) {
            ((ray.surface.Sphere) o).radius = v;
            return true;
        }
        return false;
    }

    private final Map<Class<?>, List<Entry>> cache = new HashMap<>();
    /** The class last asked about and its entries: a large scene sets fields of one class line after line. */
    private Class<?> lastClass;
    private List<Entry> lastEntries;

    /** The field chars [from, to) of {@code line} name in {@code c}; a Problem (the message) when it is not settable. */
    Entry find(Class<?> c, char[] line, int from, int to) throws Problem {
        List<Entry> entries = entries(c);
        int n = to - from;
        next:
        for (int i = 0; i < entries.size(); i++) {   // indexed: an iterator per line is garbage
            char[] name = entries.get(i).chars;
            if (name.length != n) {
                continue;
            }
            for (int k = n - 1; k >= 0; k--) {           // from the end: v0, v1, v2 differ there
                if (name[k] != line[from + k]) {
                    continue next;
                }
            }
            return entries.get(i);
        }
        return add(c, entries, new String(line, from, n));
    }

    /** The field {@code name} names in {@code c}; a Problem (the message) when it is not settable. */
    Entry find(Class<?> c, String name) throws Problem {
        List<Entry> entries = entries(c);
        for (Entry e : entries) {
            if (e.name.equals(name)) {
                return e;
            }
        }
        return add(c, entries, name);
    }

    private List<Entry> entries(Class<?> c) {
        if (c != lastClass) {
            List<Entry> e = cache.get(c);      // get/put, not computeIfAbsent: no lambda on the parse path (StartupClassesTest)
            if (e == null) {
                e = new ArrayList<>();
                cache.put(c, e);
            }
            lastEntries = e;
            lastClass = c;
        }
        return lastEntries;
    }

    private static Entry add(Class<?> c, List<Entry> entries, String name) throws Problem {
        Field f = lookUp(c, name);
        String k = keyword(f.getType());
        Entry e = new Entry(name, name.toCharArray(), f, k, k == null ? -1 : Parser.TYPES.indexOf(k), direct(f));
        entries.add(e);
        return e;
    }

    private static Field lookUp(Class<?> c, String name) throws Problem {
        String owner = c.getSimpleName();
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            Field d;
            try {
                d = k.getDeclaredField(name);
            } catch (NoSuchFieldException e) {
                continue;
            } catch (LinkageError | RuntimeException e) {
                break;
            }
            int m = d.getModifiers();
            String why = Modifier.isPrivate(m) ? "private" : Modifier.isStatic(m) ? "static" : Modifier.isFinal(m) ? "final"
                    : d.isSynthetic() ? "synthetic" : null;
            if (why != null) {
                throw new Problem("field " + Values.quote(name) + " of " + owner + " is " + why
                        + " and cannot be set from a scene (expected one of: " + settable(c) + ")");
            }
            try {
                d.setAccessible(true);
            } catch (RuntimeException e) {
                throw new Problem("field " + Values.quote(name) + " of " + owner + " cannot be accessed (" + e.getClass().getSimpleName() + ")");
            }
            return d;
        }
        List<String> names = settableNames(c);
        throw new Problem(owner + " has no field " + Values.quote(name) + " (" + Values.caseHint(name, names) + "expected one of: "
                + (names.isEmpty() ? "none" : String.join(", ", names)) + ")");
    }

    /** The names a scene may set on {@code c}, for error messages. */
    static String settable(Class<?> c) {
        List<String> names = settableNames(c);
        return names.isEmpty() ? "none" : String.join(", ", names);
    }

    static List<String> settableNames(Class<?> c) {
        List<String> names = new ArrayList<>();
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            try {
                for (Field f : k.getDeclaredFields()) {
                    int m = f.getModifiers();
                    if (!Modifier.isPrivate(m) && !Modifier.isStatic(m) && !Modifier.isFinal(m) && !f.isSynthetic()
                            && keyword(f.getType()) != null && !names.contains(f.getName())) {
                        names.add(f.getName());
                    }
                }
            } catch (LinkageError | RuntimeException e) {
                break;
            }
        }
        return names;
    }

    /** The type keyword a field of type {@code t} takes, or null when a scene cannot set such a field. */
    static String keyword(Class<?> t) {
        if (t == int.class || t == Integer.class || t == long.class || t == Long.class) return "int";
        if (t == double.class || t == Double.class || t == float.class || t == Float.class) return "double";
        if (t == String.class) return "String";
        if (t == javax.vecmath.Vector3d.class || t == Tuple3d.class) return "Vector3d";
        if (t.isPrimitive() || t.isArray() || Number.class.isAssignableFrom(t) || t == Boolean.class || t == Character.class
                || Tuple3d.class.isAssignableFrom(t) || CharSequence.class.isAssignableFrom(t)) {
            return null;
        }
        return "ref";
    }

    /** How a value of keyword {@code k} is written, for "expected" messages. */
    static String placeholder(String k) {
        switch (k) {
            case "int": return "<whole number>";
            case "double": return "<number>";
            case "String": return "<text>";
            case "Vector3d": return "[x y z]";
            default: return "<name>";
        }
    }
}
