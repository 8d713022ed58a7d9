package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;

/**
 * Constructive solid geometry: the union, intersection or difference (left minus right) of two closed
 * surfaces, itself a closed surface (so CSGs nest). The operands are used here and not rendered on their
 * own. Each part of the boundary keeps its operand's material ({@code rec.surface} is the operand's own
 * surface), the inside of {@code right} exposed by a difference included, unless the CSG has its own
 * {@code ref material}.
 *
 * <pre>
 * Surface CSG lens
 * String operation intersection   # union (default), intersection, or difference
 * ref left a                      # closed surfaces named earlier: Sphere, Box, Cylinder, Cone, Torus,
 * ref right b                     # CSG, or a closed two-sided Mesh
 * ref material glass              # optional
 * </pre>
 *
 * The ray is classified as in Roth, "Ray casting for modeling solids" (Computer Graphics and Image
 * Processing 18, 1982): the hits of both operands along the ray are merged in order of t, and a hit is
 * a hit of the result where the set operation's in/out state changes. The hits are fetched lazily, the
 * nearest first, by asking the operand again on the same ray with its start moved just past the last
 * hit ({@code tMin = Math.nextUp(t)}): an operand's roots on a fixed ray do not depend on {@code tMin},
 * so no root is skipped; a root reported again a few ulps below the new start (a kernel whose range
 * test rounds) is stepped over, and only a root numerically on top of the last one could be. Whether the ray is inside an operand just before its next hit is
 * read from that hit's {@code frontFace} (a ray leaving through a back face was inside), never counted,
 * so rays starting inside an operand are classified right and a rounding-doubled root (a ray through a
 * mesh edge) cannot flip the state twice. Roots at exactly the same t on both operands (a surface shared
 * by both) are crossed together.
 */
public class CSG extends Surface {

    private static final int UNION = 0, INTERSECTION = 1, DIFFERENCE = 2;
    private static final List<String> OPERATIONS = List.of("union", "intersection", "difference");

    /** {@code union}, {@code intersection} or {@code difference} (left minus right). */
    public String operation = "union";
    public Surface left;
    public Surface right;

    private int op = UNION;
    /** False when the CSG had no {@code ref material}: hits then name the operand's surface. */
    private boolean ownMaterial;
    private boolean initialized;
    private final ThreadLocal<Scratch> scratch = new ThreadLocal<>();

    /** One thread's query ray and the operands' records (two per operand: the crossing and the next hit). */
    private static final class Scratch {
        final Ray ray = new Ray();
        final IntersectionRecord[] recs = {new IntersectionRecord(), new IntersectionRecord(),
            new IntersectionRecord(), new IntersectionRecord()};
    }

    @Override
    public void init() {
        op = OPERATIONS.indexOf(operation);
        if (op < 0) {
            throw new IllegalArgumentException("unknown operation '" + operation + "' (expected union, intersection or difference)");
        }
        checkOperand("left", left);
        checkOperand("right", right);
        measure();
        if (!initialized) {
            initialized = true;
            ownMaterial = material != null;
        }
        if (!ownMaterial) {
            material = left.material;   // stands for the operands' materials wherever a surface's one is asked for
        }
    }

    /**
     * Most operand visits one ray may cost a CSG: the sum over its nodes of each node's leaves (an operand
     * used twice counted twice). A left-deep chain of n unions costs about n^2 / 2 (at most about 90
     * surfaces), a balanced tree n log2 n (about 500); CSGs that share operands level after level double
     * at each level and are refused at once instead of running for hours.
     */
    public static final long MAX_VISITS = 4096;

    /** Leaves of this tree (a shared operand once per use), levels, and operand visits a ray may cost (saturating). */
    private long leaves = 1, visits;
    private int levels;
    /** Whether some CSG of this tree has one surface as both operands (shared level after level, the cost doubles). */
    private boolean shared;

    /**
     * Measures the tree from its operands' own measures (each CSG is initialised after its operands, so
     * this costs O(1) whatever the tree), and refuses one whose cost per ray is beyond
     * {@link #MAX_VISITS}: shared operands (`ref left c9`, `ref right c9`) double it at
     * each level, and would otherwise hang the render and the plan.
     */
    private void measure() {
        long ll = left instanceof CSG c ? c.leaves : 1, rl = right instanceof CSG c ? c.leaves : 1;
        long lv = left instanceof CSG c ? c.visits : 0, rv = right instanceof CSG c ? c.visits : 0;
        leaves = sat(ll + rl);
        visits = sat(sat(lv + rv) + leaves);
        levels = 1 + Math.max(left instanceof CSG c ? c.levels : 0, right instanceof CSG c ? c.levels : 0);
        shared = left == right || left instanceof CSG c && c.shared || right instanceof CSG c && c.shared;
        if (visits > MAX_VISITS) {
            throw new IllegalArgumentException("this CSG tree would cost " + (visits == Long.MAX_VALUE ? "over 9e18"
                    : String.format(java.util.Locale.ROOT, "%,d", visits)) + " operand tests per ray (" + levels + " levels, "
                    + (leaves == Long.MAX_VALUE ? "over 9e18" : String.format(java.util.Locale.ROOT, "%,d", leaves))
                    + " leaves counting an operand each time it is used"
                    + (shared ? ": one surface is both operands of a CSG, so each level doubles the cost"
                            : 2L * levels >= leaves ? ": a ray tests every operand below each level of a chain"
                            : ": a tree of that many surfaces") + "), more than "
                    + String.format(java.util.Locale.ROOT, "%,d", MAX_VISITS)
                    + " (expected a smaller tree: a chain of at most about 90 unions, a balanced tree of about 500 "
                    + "surfaces; for more, one closed Mesh)");
        }
    }

    private static long sat(long v) {
        return v < 0 ? Long.MAX_VALUE : v;
    }

    private static void checkOperand(String side, Surface s) {
        if (s == null) {
            throw new IllegalArgumentException("no " + side + " operand (expected 'ref " + side + " <name>' naming a closed surface)");
        }
        if (!s.isClosed()) {
            throw new IllegalArgumentException(side + " operand " + s.getClass().getSimpleName() + " is not a closed surface"
                    + (s instanceof Mesh m ? ": " + m.notClosedReason() : "")
                    + " (expected Sphere, Box, Cylinder, Cone, Torus, CSG or a closed two-sided Mesh)");
        }
    }

    @Override
    public boolean isClosed() {
        return true;
    }

    @Override
    public List<Surface> operands() {
        return left == null || right == null ? List.of() : List.of(left, right);
    }

    @Override
    public Aabb bounds() {
        Aabb a = left.bounds(), b = right.bounds();
        if (op == DIFFERENCE) {
            return a;
        }
        if (op == UNION) {
            a.include(b.minX, b.minY, b.minZ);
            a.include(b.maxX, b.maxY, b.maxZ);
            return a;
        }
        Aabb c = new Aabb(Math.max(a.minX, b.minX), Math.max(a.minY, b.minY), Math.max(a.minZ, b.minZ),
                Math.min(a.maxX, b.maxX), Math.min(a.maxY, b.maxY), Math.min(a.maxZ, b.maxZ));
        // disjoint boxes: nothing can be hit; a point keeps the CSG in the BVH (an empty box would not)
        if (c.minX > c.maxX || c.minY > c.maxY || c.minZ > c.maxZ) {
            return new Aabb(c.minX, c.minY, c.minZ, c.minX, c.minY, c.minZ);
        }
        return c;
    }

    private boolean inside(boolean inLeft, boolean inRight) {
        return switch (op) {
            case UNION -> inLeft || inRight;
            case INTERSECTION -> inLeft && inRight;
            default -> inLeft && !inRight;
        };
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Scratch s = scratch.get();
        if (s == null) {
            s = new Scratch();
            scratch.set(s);
        }
        Ray q = s.ray;
        q.origin.set(ray.origin);
        q.direction.set(ray.direction);
        q.depth = ray.depth;
        IntersectionRecord[] r = s.recs;
        // r[0]: left's next hit, r[1]: right's next hit; r[2], r[3]: the crossings just passed
        double tl = next(left, q, ray.tMin, Double.NEGATIVE_INFINITY, r, 0, scene);
        double tr = next(right, q, ray.tMin, Double.NEGATIVE_INFINITY, r, 1, scene);
        boolean inL = tl < Double.POSITIVE_INFINITY && !r[0].frontFace;
        boolean inR = tr < Double.POSITIVE_INFINITY && !r[1].frontFace;
        boolean in = inside(inL, inR);
        while (true) {
            double t = Math.min(tl, tr);
            if (!(t <= ray.tMax) || t == Double.POSITIVE_INFINITY) {
                return false;
            }
            boolean crossL = tl == t, crossR = tr == t;
            boolean inR0 = inR;
            // the state just past t is the state just before each operand's next hit
            if (crossL) {
                swap(r, 0, 2);
                tl = next(left, q, Math.nextUp(t), t, r, 0, scene);
                inL = tl < Double.POSITIVE_INFINITY && !r[0].frontFace;
            }
            if (crossR) {
                swap(r, 1, 3);
                tr = next(right, q, Math.nextUp(t), t, r, 1, scene);
                inR = tr < Double.POSITIVE_INFINITY && !r[1].frontFace;
            }
            boolean after = inside(inL, inR);
            if (after != in) {
                // the boundary is left's where left's crossing alone changes the result, else right's
                boolean useLeft = crossL && (!crossR || inside(inL, inR0) != in);
                report(useLeft ? r[2] : r[3], after, ray, record);
                return true;
            }
            in = after;
        }
    }

    /**
     * The operand's nearest hit after {@code after}, asked for from {@code tMin} on the query ray, into
     * {@code r[i]}: its t, or +infinity when there is none. A kernel's range test rounds (the watertight
     * triangle compares t times its determinant), so it may report the root just passed again, a few
     * ulps below {@code tMin}: then the start moves up past it by doubling steps. Only a root within
     * those few ulps of the last one, numerically the same crossing, can be stepped over.
     */
    private static double next(Surface s, Ray q, double tMin, double after, IntersectionRecord[] r, int i, Scene scene) {
        IntersectionRecord rec = r[i];
        double from = tMin;
        for (int k = 1; k <= 64; k++) {
            q.tMin = from;
            q.tMax = Double.POSITIVE_INFINITY;
            rec.surface = null;
            boolean hit = intersectInto(s, q, rec, scene);
            if (!hit || Double.isNaN(rec.t)) {
                return Double.POSITIVE_INFINITY;
            }
            if (rec.t > after) {
                if (rec.surface == null) {
                    rec.surface = s;
                }
                return rec.t;
            }
            from = after + Math.scalb(Math.max(Math.ulp(after), Double.MIN_NORMAL), k);
        }
        return Double.POSITIVE_INFINITY;     // a surface that keeps answering behind its start: no further hit
    }

    private static void swap(IntersectionRecord[] r, int i, int j) {
        IntersectionRecord x = r[i];
        r[i] = r[j];
        r[j] = x;
    }

    /** The result's hit: the operand's record, its normal facing the ray, frontFace from entering or leaving. */
    private void report(IntersectionRecord hit, boolean entering, Ray ray, IntersectionRecord record) {
        record.t = hit.t;
        record.location.set(hit.location);
        record.normal.set(hit.normal);
        if (record.normal.dot(ray.direction) > 0) {
            record.normal.negate();
        }
        record.frontFace = entering;
        record.error = hit.error;
        record.surface = ownMaterial ? this : hit.surface;
    }

    @Override
    public String toString() {
        return "CSG[" + operation + " of " + left + " and " + right + "]";
    }
}
