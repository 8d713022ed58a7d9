package ray.parse;

import java.lang.reflect.Field;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

/**
 * One parameter line, {@code <type> <field> <value>}: finds the field, checks that the type keyword
 * fits it, parses the value and writes it into the object being read.
 */
final class Parameters {

    private final Parser parser;

    Parameters(Parser parser) {
        this.parser = parser;
    }

    /** {@code w}: the line's words, the third being the rest of the line. */
    void parameter(String[] w) throws SceneFormatException {
        String type = w[0];
        Object current = parser.current();
        String cls = current.getClass().getSimpleName();
        if (w.length < 2) {
            throw parser.error("'" + type + "' needs a field name and a value (expected '" + type + " <field> "
                    + Fields.placeholder(type) + "')");
        }
        String name = w[1];
        Field f;
        try {
            f = parser.fields().find(current.getClass(), name);
        } catch (Problem p) {
            throw parser.error(p.getMessage());
        }
        Class<?> ft = f.getType();
        String fits = Fields.keyword(ft);
        if (fits == null) {
            throw parser.error("field '" + name + "' of " + cls + " is a " + ft.getSimpleName()
                    + ", which a scene cannot set (expected a field of type int, double, String, Vector3d or an object)");
        }
        if (!fits.equals(type)) {
            throw parser.error("'" + type + " " + name + "' does not fit: " + name + " of " + cls + " is a " + ft.getSimpleName()
                    + " (expected '" + fits + " " + name + " " + Fields.placeholder(fits) + "')");
        }
        if (w.length < 3) {
            throw parser.error("'" + type + " " + name + "' has no value (expected '" + type + " " + name + " "
                    + Fields.placeholder(type) + "')");
        }
        int first = parser.currentFields().putIfAbsent(name, parser.line());
        if (first >= 0) {
            throw parser.error("field '" + name + "' is set twice (first at line " + first + "; expected each field once per object)");
        }
        Object v;
        try {
            v = value(type, name, ft, w[2]);
        } catch (Problem p) {
            throw parser.error(p.getMessage());
        }
        try {
            f.set(current, v);
        } catch (IllegalAccessException | RuntimeException e) {
            throw parser.error("cannot set field '" + name + "' of " + cls + ": " + Parser.describe(e));
        }
    }

    private Object value(String type, String name, Class<?> ft, String value) throws Problem {
        switch (type) {
            case "int":
                if (ft == long.class || ft == Long.class) {
                    return Values.parseWhole(value, name, Long.MIN_VALUE, Long.MAX_VALUE);
                }
                return (int) Values.parseWhole(value, name, Integer.MIN_VALUE, Integer.MAX_VALUE);
            case "double":
                double d = Values.parseDouble(value, name);
                if (ft == float.class || ft == Float.class) {
                    if (!Float.isFinite((float) d)) {
                        throw new Problem(Values.quote(value) + " is too large for " + name + " (expected a finite float, at most about 3.4e38)");
                    }
                    return (float) d;
                }
                return d;
            case "String":
                return value;
            case "Vector3d":
                return Values.parseVector(value, name);
            default:
                return reference(name, ft, value);
        }
    }

    private Object reference(String name, Class<?> ft, String value) throws Problem {
        if (Parser.words(value).length > 1) {
            throw new Problem("'ref " + name + "' takes one object name, found " + Values.quote(value)
                    + " (expected 'ref " + name + " <name>')");
        }
        Map<String, Object> named = parser.named();
        Object target = named.get(value);
        if (target == null) {
            throw new Problem("undefined object " + Values.quote(value) + " in 'ref " + name + "' (expected the name of an object "
                    + "declared earlier in the file" + (named.isEmpty() ? "; none has a name yet)" : ", such as " + someNames(named) + ")"));
        }
        if (target == parser.current()) {
            throw new Problem(Values.quote(value) + " is the object being defined (expected an object declared earlier; "
                    + "an object cannot refer to itself)");
        }
        if (!ft.isInstance(target)) {
            throw new Problem(Values.quote(value) + " is a " + target.getClass().getSimpleName() + ", but 'ref " + name
                    + "' needs a " + ft.getSimpleName());
        }
        return target;
    }

    private static String someNames(Map<String, Object> named) {
        List<String> names = new ArrayList<>(named.keySet());
        names.sort(null);
        List<String> shown = new ArrayList<>();
        for (String n : names.subList(0, Math.min(6, names.size()))) {
            shown.add(Values.quote(n).substring(1, Values.quote(n).length() - 1));
        }
        return String.join(", ", shown) + (names.size() > 6 ? ", ..." : "");
    }
}
