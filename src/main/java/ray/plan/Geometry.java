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
        final Map<String, long[]> operands = new TreeMap<>();
    }

    private Geometry() {
    }

    static String describe(List<Surface> surfaces) {
        Map<String, Tally> bounded = new TreeMap<>(), unbounded = new TreeMap<>();
        Map<Surface, Leaves> memo = new java.util.IdentityHashMap<>();
        for (Surface s : surfaces) {
            Tally t = (s.bounds().isFinite() ? bounded : unbounded).computeIfAbsent(s.getClass().getSimpleName(), k -> new Tally());
            t.surfaces++;
            long p = 0;
            for (Surface o : s.operands()) {
                Leaves l = leaves(o, memo);
                p = sum(p, l.primitives);
                for (Map.Entry<String, Long> e : l.byClass.entrySet()) {
                    long[] n = t.operands.computeIfAbsent(e.getKey(), k -> new long[1]);
                    n[0] = sum(n[0], e.getValue());
                }
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
            Map<String, long[]> counts = new TreeMap<>();
            for (Map.Entry<String, Tally> e : unbounded.entrySet()) {
                counts.put(e.getKey(), new long[] {e.getValue().surfaces});
            }
            b.append("; ").append(list(counts)).append(" tested against every ray (unbounded)");
        }
        return b.toString();
    }

    /** The leaf operands under a surface by class (an operand counted each time it is used), and their primitives. */
    private static final class Leaves {
        final Map<String, Long> byClass = new TreeMap<>();
        long primitives;
    }

    /**
     * The leaf operands of a tree of operands; memoised per surface (identity), so operands shared
     * level after level (a user's class may build such a graph) cost one visit each instead of one per
     * path, and the counts saturate instead of overflowing.
     */
    private static Leaves leaves(Surface s, Map<Surface, Leaves> memo) {
        Leaves known = memo.get(s);
        if (known != null) {
            return known;
        }
        Leaves l = new Leaves();
        List<Surface> ops = s.operands();
        if (ops.isEmpty()) {
            l.byClass.put(s.getClass().getSimpleName(), 1L);
            l.primitives = s.plannedPrimitiveCount();
        } else {
            for (Surface o : ops) {
                Leaves c = leaves(o, memo);
                l.primitives = sum(l.primitives, c.primitives);
                c.byClass.forEach((k, v) -> l.byClass.merge(k, v, Geometry::sum));
            }
        }
        memo.put(s, l);
        return l;
    }

    private static long sum(long a, long b) {
        long r = a + b;
        return r < 0 ? Long.MAX_VALUE : r;
    }

    private static String list(Map<String, long[]> counts) {
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, long[]> e : counts.entrySet()) {
            long n = e.getValue()[0];
            b.append(b.length() == 0 ? "" : ", ").append(n < 1000 ? Long.toString(n) : PlanReport.count(n)).append(' ').append(e.getKey());
        }
        return b.toString();
    }
}
