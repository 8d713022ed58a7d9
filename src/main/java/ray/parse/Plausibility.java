package ray.parse;

import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import ray.light.Light;
import ray.material.Material;

/**
 * Values a scene may legally give but that are almost surely slips, reported as warnings (the render
 * goes on, exactly as given): a material's colour ({@code ...Color} fields: ambient, diffuse, specular)
 * or mirror coefficient below 0 (negative light) or above 1 (the surface reflects more light than it
 * receives), and a light's negative intensity. Read from the object's public fields after its
 * {@code init()}, so a user's subclass is checked by the same rule through the fields it inherits.
 */
final class Plausibility {

    private Plausibility() {
    }

    /** The problems of {@code o}: pairs of (field name, message after the class name). */
    static List<String[]> of(Object o) {
        if (!(o instanceof Material) && !(o instanceof Light)) {
            return List.of();      // a surface or camera: nothing to check, nothing made (a mesh scene has 100k of them)
        }
        List<String[]> out = new ArrayList<>(0);
        for (Class<?> c = o.getClass(); c != null && c != Object.class; c = c.getSuperclass()) {
            for (Field f : c.getDeclaredFields()) {
                if (!Modifier.isPublic(f.getModifiers()) || Modifier.isStatic(f.getModifiers())) {
                    continue;
                }
                String name = f.getName();
                boolean colour = o instanceof Material && f.getType() == Vector3d.class && name.endsWith("Color");
                boolean mirror = o instanceof Material && f.getType() == double.class && name.equals("mirrorCoefficient");
                boolean intensity = o instanceof Light && f.getType() == Vector3d.class && name.equals("intensity");
                if (!colour && !mirror && !intensity) {
                    continue;
                }
                Object v;
                try {
                    v = f.get(o);
                } catch (IllegalAccessException | RuntimeException e) {
                    continue;
                }
                double min, max;
                if (v instanceof Vector3d d) {
                    min = Math.min(d.x, Math.min(d.y, d.z));
                    max = Math.max(d.x, Math.max(d.y, d.z));
                } else if (v instanceof Double d) {
                    min = max = d;
                } else {
                    continue;
                }
                if (min >= 0 && (max <= 1 || intensity)) {
                    continue;   // plausible: no message, so nothing formatted (this runs for every scene)
                }
                String shown = v instanceof Vector3d d ? "[" + num(d.x) + " " + num(d.y) + " " + num(d.z) + "]" : num((Double) v);
                if (min < 0) {
                    out.add(new String[] {name, name + " " + shown + " is negative"
                            + (intensity ? ": the light takes light away" : ": the surface gives out negative light") + " (rendered as given)"});
                } else if (max > 1 && !intensity) {
                    out.add(new String[] {name, name + " " + shown + " is above 1: the surface reflects more light than it receives"
                            + " (rendered as given)"});
                }
            }
        }
        return out;
    }

    private static String num(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
