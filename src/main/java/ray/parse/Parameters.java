package ray.parse;

import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;

/**
 * One parameter line, {@code <type> <field> <value>}: finds the field, checks that the type keyword
 * fits it, reads the value and writes it into the object being read. Reads the words where they stand
 * in the line ({@link Words}), so a plain line of a large scene makes no String: the field's name is
 * matched against the class's known fields, numbers are read from the chars, and a {@code ref} to the
 * object the line before named is not looked up again.
 */
final class Parameters {

    private final String file;
    private final SceneObjects objects;
    private final Fields fields = new Fields();
    /** The name a ref line last named and its object (a name never changes its object). */
    private String lastRefName;
    private char[] lastRefChars;
    private Object lastRefTarget;

    Parameters(String file, SceneObjects objects) {
        this.file = file;
        this.objects = objects;
    }

    /** The type keyword field {@code name} of the object being read takes (for a hint), or "&lt;type&gt;" when it has no such field. */
    String keywordOf(String name) {
        try {
            return fields.find(objects.current().getClass(), name).keyword();
        } catch (Problem p) {
            return "<type>";
        }
    }

    /** The parameter line {@code w} at {@code line}; its first word is the type keyword {@code Parser.TYPES[kind]}. */
    void parameter(Words w, int kind, int line) throws SceneFormatException {
        String type = Parser.TYPE_NAMES[kind];
        Object current = objects.current();
        if (w.count < 2) {
            throw error(line, "'" + type + "' needs a field name and a value (expected '" + type + " <field> "
                    + Fields.placeholder(type) + "')");
        }
        Fields.Entry e;
        try {
            e = fields.find(current.getClass(), w.line, w.from1, w.to1);
        } catch (Problem p) {
            throw error(line, p.getMessage());
        }
        String name = e.name();
        Field f = e.field();
        Class<?> ft = f.getType();
        String fits = e.keyword();
        if (fits == null) {
            throw error(line, "field '" + name + "' of " + cls(current) + " is a " + ft.getSimpleName()
                    + ", which a scene cannot set (expected a field of type int, double, String, Vector3d or an object)");
        }
        if (e.type() != kind) {
            throw error(line, "'" + type + " " + name + "' does not fit: " + name + " of " + cls(current) + " is a " + ft.getSimpleName()
                    + " (expected '" + fits + " " + name + " " + Fields.placeholder(fits) + "')");
        }
        if (w.count < 3) {
            throw error(line, "'" + type + " " + name + "' has no value (expected '" + type + " " + name + " "
                    + Fields.placeholder(type) + "')");
        }
        int first = objects.currentFields().putIfAbsent(name, line);
        if (first >= 0) {
            throw error(line, "field '" + name + "' is set twice (first at line " + first + "; expected each field once per object)");
        }
        try {
            if (ft == double.class) {   // the common case, set without boxing
                double d = Values.parseDouble(w.line, w.from2, w.end, name);
                if (Fields.setDirect(e.direct(), current, d)) {
                    return;
                }
                try {
                    f.setDouble(current, d);
                } catch (IllegalAccessException | RuntimeException x) {
                    throw cannotSet(line, name, current, x);
                }
                return;
            }
            Object v = value(kind, name, ft, w);
            if (Fields.setDirect(e.direct(), current, v)) {
                return;
            }
            try {
                f.set(current, v);
            } catch (IllegalAccessException | RuntimeException x) {
                throw cannotSet(line, name, current, x);
            }
        } catch (Problem p) {
            throw error(line, p.getMessage());
        }
    }

    private Object value(int kind, String name, Class<?> ft, Words w) throws Problem {
        switch (kind) {
            case Parser.INT:
                String whole = w.rest();
                if (ft == long.class || ft == Long.class) {
                    return Values.parseWhole(whole, name, Long.MIN_VALUE, Long.MAX_VALUE);
                }
                return (int) Values.parseWhole(whole, name, Integer.MIN_VALUE, Integer.MAX_VALUE);
            case Parser.DOUBLE:
                double d = Values.parseDouble(w.line, w.from2, w.end, name);
                if (ft == float.class || ft == Float.class) {
                    if (!Float.isFinite((float) d)) {
                        throw new Problem(Values.quote(w.rest()) + " is too large for " + name + " (expected a finite float, at most about 3.4e38)");
                    }
                    return (float) d;
                }
                return d;
            case Parser.STRING:
                return w.rest();
            case Parser.VECTOR:
                return Values.parseVector(w.line, w.from2, w.end, name);
            default:
                return reference(name, ft, w);
        }
    }

    private Object reference(String name, Class<?> ft, Words w) throws Problem {
        Object target;
        String value;
        if (lastRefChars != null && Words.same(w.line, w.from2, w.end, lastRefChars)) {
            value = lastRefName;
            target = lastRefTarget;
        } else {
            value = w.rest();
            if (!w.restIsOneWord()) {
                throw new Problem("'ref " + name + "' takes one object name, found " + Values.quote(value)
                        + " (expected 'ref " + name + " <name>')");
            }
            target = objects.named(value);
            if (target == null) {
                List<String> names = objects.names();
                throw new Problem("undefined object " + Values.quote(value) + " in 'ref " + name + "' (expected the name of an object "
                        + "declared earlier in the file" + (names.isEmpty() ? "; none has a name yet)" : ", such as " + someNames(names) + ")"));
            }
            lastRefName = value;
            lastRefChars = value.toCharArray();
            lastRefTarget = target;
        }
        if (target == objects.current()) {
            throw new Problem(Values.quote(value) + " is the object being defined (expected an object declared earlier; "
                    + "an object cannot refer to itself)");
        }
        if (!ft.isInstance(target)) {
            throw new Problem(Values.quote(value) + " is a " + target.getClass().getSimpleName() + ", but 'ref " + name
                    + "' needs a " + ft.getSimpleName());
        }
        return target;
    }

    private static String someNames(List<String> names) {
        List<String> shown = new ArrayList<>();
        for (String n : names.subList(0, Math.min(6, names.size()))) {
            shown.add(Values.quote(n).substring(1, Values.quote(n).length() - 1));
        }
        return String.join(", ", shown) + (names.size() > 6 ? ", ..." : "");
    }

    private static String cls(Object o) {
        return o.getClass().getSimpleName();
    }

    private SceneFormatException cannotSet(int line, String name, Object current, Exception e) {
        return error(line, "cannot set field '" + name + "' of " + cls(current) + ": " + Parser.describe(e));
    }

    private SceneFormatException error(int line, String message) {
        return new SceneFormatException(file, line, message);
    }
}
