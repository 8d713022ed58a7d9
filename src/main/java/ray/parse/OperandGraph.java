package ray.parse;

import java.util.ArrayDeque;
import java.util.IdentityHashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import java.util.Set;
import ray.surface.Surface;

/**
 * The surfaces a surface is built from ({@link Surface#operands()}) form a graph the plan walks. A
 * built-in CSG's operands are surfaces declared before it, so they cannot lead back to it; a class of
 * one's own may return itself, or parts that do. Such a cycle would make every walk of the scene's
 * surfaces endless, so the parser refuses it where the surface is declared.
 */
final class OperandGraph {

    private OperandGraph() {
    }

    /**
     * A one-line description of a cycle through {@code top}'s operands (a surface that is, through its
     * operands, an operand of itself), or null when there is none. Iterative depth first, each surface
     * once: surfaces already found free of cycles ({@code acyclic}, shared across a scene) are not walked
     * again, so the check costs O(surfaces) over a whole scene however the operands are shared.
     */
    static String cycle(Surface top, Set<Surface> acyclic) {
        Map<Surface, Boolean> onPath = new IdentityHashMap<>();   // true while its operands are being walked
        ArrayDeque<Surface> path = new ArrayDeque<>();
        ArrayDeque<Iterator<Surface>> next = new ArrayDeque<>();
        onPath.put(top, true);
        path.push(top);
        next.push(top.operands().iterator());
        while (!next.isEmpty()) {
            Iterator<Surface> it = next.peek();
            if (!it.hasNext()) {
                next.pop();
                Surface done = path.pop();
                onPath.put(done, false);
                acyclic.add(done);
                continue;
            }
            Surface o = it.next();
            if (o == null || acyclic.contains(o)) {
                continue;
            }
            Boolean walking = onPath.get(o);
            if (walking == null) {
                List<Surface> ops = o.operands();
                onPath.put(o, true);
                path.push(o);
                next.push(ops.iterator());
            } else if (walking) {
                String via = path.peek() == o ? "" : " through " + path.peek().getClass().getSimpleName();
                return top.getClass().getSimpleName() + "'s operands lead back to "
                        + (o == top ? "itself" : "its operand " + o.getClass().getSimpleName()) + via
                        + " (a cycle: expected operands() to return the surfaces it is built from, none of them built from it)";
            }
        }
        return null;
    }
}
