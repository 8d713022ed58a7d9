package ray.plan;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import ray.surface.Surface;

/**
 * The plan's "geometry" line: what the rays will be tested against, by class, e.g. {@code 4 Sphere,
 * 1 CSG (of 2 Sphere, 1 Box), 1 Mesh (1,280 primitives); 1 Plane tested against every ray}, read from the
 * Surface API only: a class's operands ({@link Surface#operands()}) and its primitives
 * ({@link Surface#primitiveCount()}). Surfaces with finite bounds go into the BVH; the others are tested
 * against every ray, which the line says.
 */
final class Geometry {

    /** Per class: surfaces, primitives, and the leaf operands of those with operands (by class). */
    private static final class Tally {
        long surfaces, primitives;
        final Map<String, int[]> operands = new TreeMap<>();
    }

    private Geometry() {
    }

    static String describe(List<Surface> surfaces) {
        Map<String, Tally> bounded = new TreeMap<>(), unbounded = new TreeMap<>();
        for (Surface s : surfaces) {
            Tally t = (s.bounds().isFinite() ? bounded : unbounded).computeIfAbsent(s.getClass().getSimpleName(), k -> new Tally());
            t.surfaces++;
            long p = 0;
            for (Surface o : s.operands()) {
                p += leaves(o, t.operands);
            }
            t.primitives += s.operands().isEmpty() ? s.plannedPrimitiveCount() : p;
        }
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, Tally> e : bounded.entrySet()) {
            Tally t = e.getValue();
            b.append(b.length() == 0 ? "" : ", ").append(t.surfaces).append(' ').append(e.getKey());
            if (!t.operands.isEmpty()) {
                b.append(" (of ").append(list(t.operands)).append(')');
            } else if (t.primitives != t.surfaces) {
                b.append(" (").append(PlanReport.count(t.primitives)).append(" primitives)");
            }
        }
        if (b.length() == 0) {
            b.append(unbounded.isEmpty() ? "no surfaces: every ray sees the background" : "nothing in the BVH");
        } else {
            b.append(" in the BVH");
        }
        if (!unbounded.isEmpty()) {
            Map<String, int[]> counts = new TreeMap<>();
            for (Map.Entry<String, Tally> e : unbounded.entrySet()) {
                counts.put(e.getKey(), new int[] {(int) e.getValue().surfaces});
            }
            b.append("; ").append(list(counts)).append(" tested against every ray (unbounded)");
        }
        return b.toString();
    }

    /** Counts the leaf operands of a tree of operands by class; returns their primitives. */
    private static long leaves(Surface s, Map<String, int[]> out) {
        if (!s.operands().isEmpty()) {
            long t = 0;
            for (Surface o : s.operands()) {
                t += leaves(o, out);
            }
            return t;
        }
        out.computeIfAbsent(s.getClass().getSimpleName(), k -> new int[1])[0]++;
        return s.plannedPrimitiveCount();
    }

    private static String list(Map<String, int[]> counts) {
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, int[]> e : counts.entrySet()) {
            b.append(b.length() == 0 ? "" : ", ").append(e.getValue()[0]).append(' ').append(e.getKey());
        }
        return b.toString();
    }
}
