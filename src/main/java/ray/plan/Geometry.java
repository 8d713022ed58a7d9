package ray.plan;

import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import ray.surface.Mesh;
import ray.surface.Surface;

/**
 * The plan's "geometry" line: what the rays will be tested against, by class, e.g. {@code 4 Sphere,
 * 1 CSG (of 2 Sphere, 1 Box), 1 Mesh (1,280 triangles); 1 Plane tested against every ray}. Surfaces with
 * finite bounds go into the BVH; the others are tested against every ray, which the line says.
 */
final class Geometry {

    private Geometry() {
    }

    static String describe(List<Surface> surfaces) {
        Map<String, int[]> bounded = new TreeMap<>(), unbounded = new TreeMap<>();
        Map<String, int[]> operands = new TreeMap<>();
        long triangles = 0;
        for (Surface s : surfaces) {
            (s.bounds().isFinite() ? bounded : unbounded).computeIfAbsent(s.getClass().getSimpleName(), k -> new int[1])[0]++;
            if (s instanceof Mesh m) {
                triangles += m.triangleCount();
            }
            for (Surface o : s.operands()) {
                triangles += leaves(o, operands);
            }
        }
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, int[]> e : bounded.entrySet()) {
            b.append(b.length() == 0 ? "" : ", ").append(e.getValue()[0]).append(' ').append(e.getKey());
            if (e.getKey().equals("CSG") && !operands.isEmpty()) {
                b.append(" (of ").append(list(operands)).append(')');
            }
            if (e.getKey().equals("Mesh")) {
                b.append(" (").append(PlanReport.count(triangles)).append(" triangles)");
            }
        }
        if (b.length() == 0) {
            b.append(unbounded.isEmpty() ? "no surfaces: every ray sees the background" : "nothing in the BVH");
        } else {
            b.append(" in the BVH");
        }
        if (!unbounded.isEmpty()) {
            b.append("; ").append(list(unbounded)).append(" tested against every ray (unbounded)");
        }
        return b.toString();
    }

    /** Counts the leaf operands of a CSG tree by class; returns the triangles of meshes among them. */
    private static long leaves(Surface s, Map<String, int[]> out) {
        if (!s.operands().isEmpty()) {
            long t = 0;
            for (Surface o : s.operands()) {
                t += leaves(o, out);
            }
            return t;
        }
        out.computeIfAbsent(s.getClass().getSimpleName(), k -> new int[1])[0]++;
        return s instanceof Mesh m ? m.triangleCount() : 0;
    }

    private static String list(Map<String, int[]> counts) {
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, int[]> e : counts.entrySet()) {
            b.append(b.length() == 0 ? "" : ", ").append(e.getValue()[0]).append(' ').append(e.getKey());
        }
        return b.toString();
    }
}
