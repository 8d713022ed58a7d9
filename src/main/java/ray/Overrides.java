package ray;

import java.util.function.Predicate;

/**
 * Which class in a hierarchy declares a method, for a built-in's fast path: the fast form (a material's
 * allocation-free {@code shade}, a light's {@code sample}) stands in for the framework's form only when
 * it was written for that form, i.e. when no subclass overrides the framework's method below it. Decided
 * once per class ({@link ClassValue}), at construction, never per ray.
 */
public final class Overrides {

    private Overrides() {
    }

    /** The class that declares the method {@code c} runs for {@code name(params)} (the nearest superclass with it; {@code Object} if none). */
    public static Class<?> declarer(Class<?> c, String name, Class<?>... params) {
        // a scan, not getDeclaredMethod: its NoSuchMethodException builds a message with streams and
        // lambdas for every class that does not declare the method, which every render paid at start-up
        for (Class<?> k = c; k != null; k = k.getSuperclass()) {
            for (java.lang.reflect.Method m : k.getDeclaredMethods()) {
                if (m.getName().equals(name) && java.util.Arrays.equals(m.getParameterTypes(), params)) {
                    return k;
                }
            }
        }
        return Object.class;
    }

    /** True when {@code below} is a strict subclass of {@code above}. */
    public static boolean strictlyBelow(Class<?> below, Class<?> above) {
        return below != above && above.isAssignableFrom(below);
    }

    /** A per-class answer cached for the class's lifetime. */
    public static ClassValue<Boolean> perClass(Predicate<Class<?>> question) {
        return new ClassValue<Boolean>() {
            @Override
            protected Boolean computeValue(Class<?> type) {
                return question.test(type);
            }
        };
    }
}
