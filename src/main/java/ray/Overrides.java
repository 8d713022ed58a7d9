package ray;

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

    /**
     * Per class, cached for the class's lifetime: whether {@code name(params)} is declared strictly below
     * {@code other(otherParams)} (a subclass overrides the one and not the other).
     */
    public static ClassValue<Boolean> declaredBelow(String name, Class<?>[] params, String other, Class<?>... otherParams) {
        return new Question(false, null, name, params, other, otherParams);
    }

    /**
     * Per class, cached: whether a declaration of {@code other(otherParams)} can be believed for a class
     * that {@code framework} says takes the framework's path: true unless {@code name(params)} is declared
     * strictly below it. {@code framework} null: every class takes it.
     */
    public static ClassValue<Boolean> trusted(ClassValue<Boolean> framework, String name, Class<?>[] params,
                                              String other, Class<?>... otherParams) {
        return new Question(true, framework, name, params, other, otherParams);
    }

    /**
     * Per class, cached: whether the class overrides, below {@code base}, any of the methods
     * {@code names[i](params[i])} ({@code base} itself: false).
     */
    public static ClassValue<Boolean> overridesAny(Class<?> base, String[] names, Class<?>[][] params) {
        return new ClassValue<Boolean>() {
            @Override
            protected Boolean computeValue(Class<?> c) {
                for (int i = 0; c != base && i < names.length; i++) {
                    if (declarer(c, names[i], params[i]) != base) {
                        return true;
                    }
                }
                return false;
            }
        };
    }

    /**
     * The one form of question (a class, not a lambda: a lambda's first call at start-up loads the
     * method-handle machinery, about 90 classes, for every render).
     */
    private static final class Question extends ClassValue<Boolean> {
        private final boolean trusting;
        private final ClassValue<Boolean> framework;
        private final String name, other;
        private final Class<?>[] params, otherParams;

        Question(boolean trusting, ClassValue<Boolean> framework, String name, Class<?>[] params, String other,
                 Class<?>[] otherParams) {
            this.trusting = trusting;
            this.framework = framework;
            this.name = name;
            this.params = params;
            this.other = other;
            this.otherParams = otherParams;
        }

        @Override
        protected Boolean computeValue(Class<?> c) {
            boolean below = strictlyBelow(declarer(c, name, params), declarer(c, other, otherParams));
            if (!trusting) {
                return below;
            }
            return framework != null && !framework.get(c) || !below;
        }
    }
}
