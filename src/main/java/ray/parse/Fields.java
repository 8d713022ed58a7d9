package ray.parse;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The settable fields of scene classes: non-private, non-static, non-final fields found by exact name
 * up the superclass chain. Looked up once per (class, name) and cached.
 */
final class Fields {

    private final Map<Class<?>, Map<String, Field>> cache = new HashMap<>();

    Field find(Class<?> c, String name) throws ClassResolver.Problem {
        Map<String, Field> byName = cache.get(c);
        if (byName == null) {      // (no lambda: linking one costs start-up time, see Parser)
            byName = new HashMap<>();
            cache.put(c, byName);
        }
        Field f = byName.get(name);
        if (f != null) {
            return f;
        }
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            Field d;
            try {
                d = k.getDeclaredField(name);
            } catch (NoSuchFieldException e) {
                continue;
            } catch (LinkageError | SecurityException e) {
                break;
            }
            int m = d.getModifiers();
            if (Modifier.isPrivate(m)) {
                throw new ClassResolver.Problem("field '" + name + "' of " + c.getSimpleName()
                        + " is private and cannot be set (settable: " + settable(c) + ")");
            }
            if (Modifier.isStatic(m)) {
                throw new ClassResolver.Problem("field '" + name + "' of " + c.getSimpleName()
                        + " is static and cannot be set from a scene (settable: " + settable(c) + ")");
            }
            if (Modifier.isFinal(m)) {
                throw new ClassResolver.Problem("field '" + name + "' of " + c.getSimpleName()
                        + " is final and cannot be set (settable: " + settable(c) + ")");
            }
            try {
                d.setAccessible(true);
            } catch (RuntimeException e) {
                throw new ClassResolver.Problem("field '" + name + "' of " + c.getSimpleName() + " cannot be accessed");
            }
            byName.put(name, d);
            return d;
        }
        throw new ClassResolver.Problem(c.getSimpleName() + " has no field '" + name + "' (settable: " + settable(c) + ")");
    }

    /** The names a scene may set on {@code c}, for error messages. */
    static String settable(Class<?> c) {
        List<String> names = new ArrayList<>();
        for (Class<?> k = c; k != null && k != Object.class; k = k.getSuperclass()) {
            try {
                for (Field f : k.getDeclaredFields()) {
                    int m = f.getModifiers();
                    if (!Modifier.isPrivate(m) && !Modifier.isStatic(m) && !Modifier.isFinal(m) && !f.isSynthetic()
                            && !names.contains(f.getName())) {
                        names.add(f.getName());
                    }
                }
            } catch (LinkageError | SecurityException e) {
                break;
            }
        }
        return names.isEmpty() ? "none" : String.join(", ", names);
    }
}
