package ray.plan;

import java.lang.reflect.Method;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.light.Light;
import ray.light.LightSample;
import ray.material.Material;
import ray.surface.Surface;

/**
 * Whether the plan may believe what an object declares: only when the class that declares it is the
 * class that implements the behaviour, or a subclass of it. A user's subclass of a built-in that
 * overrides {@code shade} (or {@code sample}) without declaring again is treated as unknown.
 */
final class Trust {

    private Trust() {
    }

    /** True when {@code m}'s {@link Material#terms()} describes its {@code shade} methods. */
    static boolean material(Material m) {
        Class<?> c = m.getClass();
        Class<?> terms = declaring(c, "terms");
        return terms != Material.class
                && below(terms, declaring(c, "shade", Ray.class, IntersectionRecord.class, Scene.class))
                && below(terms, declaring(c, "shade", Ray.class, IntersectionRecord.class, Scene.class, TraceContext.class, Vector3d.class));
    }

    /** True when {@code l}'s {@link Light#isDark()} and {@link Light#shadowRaysPerPoint()} describe its sampling. */
    static boolean light(Light l) {
        Class<?> c = l.getClass();
        Class<?> dark = declaring(c, "isDark"), rays = declaring(c, "shadowRaysPerPoint");
        Class<?>[] behaviour = {declaring(c, "getIntensity", IntersectionRecord.class, Scene.class),
                declaring(c, "sample", IntersectionRecord.class, Scene.class, int.class, LightSample.class),
                declaring(c, "sampleCount")};
        for (Class<?> b : behaviour) {
            if (!below(dark, b) || !below(rays, b)) {
                return false;
            }
        }
        return rays != Light.class;
    }

    /**
     * False when {@code c} keeps {@link Surface#operands()} as Surface declares it (always empty), so a
     * plan need not ask each of a mesh's many surfaces.
     */
    static boolean mayHaveOperands(Class<? extends Surface> c) {
        return declaring(c, "operands") != Surface.class;
    }

    private static boolean below(Class<?> declarer, Class<?> implementer) {
        return implementer.isAssignableFrom(declarer);
    }

    private static Class<?> declaring(Class<?> c, String name, Class<?>... params) {
        try {
            Method m = c.getMethod(name, params);
            return m.getDeclaringClass();
        } catch (NoSuchMethodException e) {
            throw new AssertionError(name + " is public on every " + c.getSuperclass(), e);
        }
    }
}
