package ray.plan;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import ray.RayKind;
import ray.Scene;
import ray.material.Material;
import ray.surface.Surface;

/**
 * Upper bounds on how many rays one render can cast, by kind: camera, shadow, mirror, refraction, user
 * (rays user classes trace through {@code Scene.trace}). {@link Double#POSITIVE_INFINITY} where a user
 * class may trace any number of rays.
 *
 * <p>The bound follows the tree of rays one camera ray can grow, material by material: a ray of depth d
 * hits nothing or one surface, and a hit on material M casts M's shadow rays (S_M, the evaluated lights'
 * shadow rays per lit point, where M has a direct term), and, below MaxDepth D, M's mirror and refraction
 * rays (b_M of them, as M declares: a Glazed chain one or one per level, a Dielectric two), each of depth
 * d + 1. So the most rays of a kind under a ray of depth d is
 * <pre>
 *   C(d) = max(0, max over M of [own_M(d) + b_M C(d + 1)]),  C(D + 1) = 0
 * </pre>
 * and the bound is N C(0) for N camera rays: the worst path through the materials the scene has, not the
 * widest branching times the most shadow rays of any material at every level (a pure mirror casts no
 * shadow ray, a Diffuse surface ends its path). The total is bounded the same way (one tree, every kind),
 * which can be below the sum of the kinds' own bounds (their worst paths differ).
 *
 * <p>With faint paths cut ({@code --cut-faint}) a ray carries its path's weight w (the product of the
 * mirror weights along it), and a material whose secondary rays are weighted by k (a Glazed chain over a
 * base that casts nothing: the sum of its |k_m|) casts them only where w k is at least {@link RenderPlan#FAINT};
 * below any other material (glass, user code) the weight is no longer followed (nothing is assumed cut).
 */
public final class RayCountBound {

    private static final int CAMERA = RayKind.CAMERA.ordinal(), SHADOW = RayKind.SHADOW.ordinal(),
            MIRROR = RayKind.MIRROR.ordinal(), REFRACTION = RayKind.REFRACTION.ordinal(), USER = RayKind.USER.ordinal();
    /** Slots of a subtree's counts: shadow, mirror, refraction, all of them. */
    private static final int S = 0, M = 1, R = 2, ALL = 3, SLOTS = 4;
    /** Past this many (depth, weight) states, deeper weights are no longer followed (nothing assumed cut): bounded work. */
    private static final int MAX_STATES = 100_000;

    private final double[] rays = new double[RayKind.values().length];
    private double total;
    /**
     * An upper bound on {@link #total()} without the per-pixel narrowing (camera rays x the worst kind of hit):
     * what a render's cost gate reads first, so that the narrowing (a pass over every surface) runs only for
     * renders near the gate's limits and for the plan's report.
     */
    private double atMost;
    /** Until {@link #narrow()}: what the per-pixel narrowing needs (null after it, or when nothing is narrowed). */
    private Scene scene;
    private Map<Material, Node> nodeOf;
    private Tree tree;
    private boolean cut;
    /** What the bound was computed from: camera rays, most secondary rays per hit, shadow rays per lit point, MaxDepth. */
    double cameraRays, perPoint;
    int branch, depth, ns;
    /** With faint paths cut: MaxDepth, of which only {@link #depth} bounces can be reached (-1: nothing cut). */
    int uncutDepth = -1;

    private RayCountBound() {
    }

    /** One way a hit can shade, as far as the bound is concerned (materials alike in these merged). */
    private record Node(double shadow, int mirror, int refraction, double weight) {
        int children() {
            return mirror + refraction;
        }

        // written out: a record's generated equals/hashCode bootstrap through invokedynamic, which loads
        // the method-handle machinery on every render's start (StartupClassesTest)
        @Override
        public boolean equals(Object o) {
            return o instanceof Node n && Double.compare(n.shadow, shadow) == 0 && n.mirror == mirror
                    && n.refraction == refraction && Double.compare(n.weight, weight) == 0;
        }

        @Override
        public int hashCode() {
            return ((Double.hashCode(shadow) * 31 + mirror) * 31 + refraction) * 31 + Double.hashCode(weight);
        }
    }

    static RayCountBound of(RenderPlan plan) {
        Scene scene = plan.scene();
        RayCountBound b = new RayCountBound();
        int ns = plan.settings().samples();
        double n = (double) Math.max(0, scene.width) * Math.max(0, scene.height) * ns * ns;
        b.rays[CAMERA] = n;
        double perPoint = 0;
        for (ray.light.Light l : plan.lights()) {
            perPoint += plan.unknownLights.contains(l) ? Double.POSITIVE_INFINITY : l.plannedShadowRays();
        }
        boolean direct = false, unknown = false, mirrors = false, refracts = false;
        int branch = 0;
        Map<Material, Node> nodeOf = new HashMap<>();
        Set<Node> nodes = new LinkedHashSet<>();
        for (Map.Entry<Material, Shading> e : plan.used.entrySet()) {
            Shading s = e.getValue();
            direct |= s.direct;
            unknown |= s.unknown;
            mirrors |= s.mirror > 0;
            refracts |= s.refraction > 0;
            branch = Math.max(branch, s.mirror + s.refraction);
            Node node = new Node(s.direct ? perPoint : 0, s.mirror, s.refraction, s.weight);
            nodes.add(node);
            nodeOf.put(e.getKey(), node);
        }
        int depth = Math.max(0, plan.settings().maxDepth());
        b.cameraRays = n;
        b.ns = ns;
        b.perPoint = perPoint;
        b.branch = branch;
        b.depth = depth;
        b.rays[USER] = unknown || direct && !plan.unknownLights.isEmpty() ? Double.POSITIVE_INFINITY : 0;
        if (unknown) {   // a user's material: any number of rays of its own, each shading anything
            b.rays[SHADOW] = direct && perPoint > 0 ? Double.POSITIVE_INFINITY : 0;
            b.rays[MIRROR] = mirrors ? Double.POSITIVE_INFINITY : 0;
            b.rays[REFRACTION] = refracts ? Double.POSITIVE_INFINITY : 0;
            b.total = b.atMost = Double.POSITIVE_INFINITY;
            return b;
        }
        // the cheap upper bound first: every camera ray charged the worst kind of hit (its own tree, so the
        // narrowing's tree reports the depths only the narrowing reaches)
        Tree worst = new Tree(new ArrayList<>(nodes), depth, plan.cutsFaintPaths());
        double[] c = new double[SLOTS];
        for (Node node : nodes) {
            Tree.max(c, worst.cost(node, 0, 1));
        }
        for (int k = 0; k < SLOTS; k++) {
            c[k] = n == 0 ? 0 : c[k] * n;
        }
        b.atMost = b.fill(c, new double[b.rays.length]);
        b.scene = scene;
        b.nodeOf = nodeOf;
        b.tree = new Tree(new ArrayList<>(nodes), depth, plan.cutsFaintPaths());
        b.cut = plan.cutsFaintPaths();
        return b;
    }

    /**
     * The bound narrowed by what each pixel can see: per camera ray, the worst subtree of a material its
     * pixel can see (a surface's box projected into the image), summed over the pixels. Done once, on the
     * first question that needs it.
     */
    private synchronized void narrow() {
        if (tree == null) {
            return;
        }
        double[] c = Screen.perCameraRay(scene, nodeOf, tree, ns);
        if (cameraRays == 0) {
            c = new double[SLOTS];   // no pixel, no ray (and no 0 x infinity)
        }
        total = fill(c, rays);
        if (cut) {
            uncutDepth = depth;
            depth = tree.deepest;
        }
        scene = null;
        nodeOf = null;
        tree = null;
    }

    /** Sets the secondary kinds of {@code out} from the subtree totals {@code c}; returns the total. */
    private double fill(double[] c, double[] out) {
        // a known bound that overflows a double (glass at MaxDepth 1000: 2^1000 paths) stays finite, the
        // largest double, so that it is refused as astronomical and never read as "unknown" (infinite)
        out[CAMERA] = rays[CAMERA];
        out[USER] = rays[USER];
        out[SHADOW] = Double.isFinite(perPoint) ? finite(c[S]) : c[S] > 0 ? Double.POSITIVE_INFINITY : 0;
        out[MIRROR] = finite(c[M]);
        out[REFRACTION] = finite(c[R]);
        double sum = 0;
        for (double r : out) {
            sum += r;
        }
        return Double.isFinite(perPoint) ? finite(Math.min(sum, cameraRays + c[ALL])) : out[USER] + sum;
    }

    /**
     * An upper bound on {@link #total()} that needs no pass over the surfaces (camera rays x the worst kind
     * of hit): a caller that only compares the bound with a limit reads this first.
     */
    public double atMost() {
        return atMost;
    }

    /**
     * The worst subtree under a ray, by depth (and path weight, with faint paths cut), memoised: a few
     * distinct kinds of hit, so the work is depth x kinds (x the weights a path can reach).
     */
    private static final class Tree {
        private final List<Node> nodes;
        private final int maxDepth;
        private final boolean cut;
        private final Map<State, double[]> memo = new HashMap<>();
        /** The deepest secondary ray any path casts (0: none). */
        int deepest;

        Tree(List<Node> nodes, int maxDepth, boolean cut) {
            this.nodes = nodes;
            this.maxDepth = maxDepth;
            this.cut = cut;
        }

        /**
         * The most rays of each kind a ray of depth {@code d} can lead to (its own hit's shadow rays and
         * secondary rays, and theirs), with path weight {@code w} (infinity: not followed).
         */
        /** What a hit on {@code m} by a ray of depth {@code d} and weight {@code w} leads to. */
        double[] cost(Node m, int d, double w) {
            double[] c = new double[SLOTS];
            c[S] = m.shadow;
            c[ALL] = m.shadow;
            if (d < maxDepth && m.children() > 0) {
                if (!cut || w == Double.POSITIVE_INFINITY) {
                    deepest = Math.max(deepest, d + 1);
                    add(c, m, unweighted(d + 1));
                    return c;
                }
                double cw = Double.isFinite(m.weight) ? w * m.weight : Double.POSITIVE_INFINITY;
                if (!(cw < RenderPlan.FAINT)) {
                    deepest = Math.max(deepest, d + 1);
                    add(c, m, cost(d + 1, cw));
                }
            }
            return c;
        }

        double[] cost(int d, double w) {
            if (!cut || w == Double.POSITIVE_INFINITY) {
                return unweighted(d);
            }
            State key = new State(d, w);
            double[] known = memo.get(key);
            if (known != null) {
                return known;
            }
            if (memo.size() > MAX_STATES || d > 4096) {   // bounded work (and stack): stop following the weight
                return unweighted(d);
            }
            double[] out = new double[SLOTS];
            for (Node m : nodes) {
                max(out, cost(m, d, w));
            }
            memo.put(key, out);
            return out;
        }

        private record State(int depth, double weight) {
            @Override
            public boolean equals(Object o) {   // (written out: see Node)
                return o instanceof State s && s.depth == depth && Double.compare(s.weight, weight) == 0;
            }

            @Override
            public int hashCode() {
                return depth * 31 + Double.hashCode(weight);
            }
        }

        /** Without weights: one array per depth, filled from MaxDepth up (no recursion). */
        private double[][] byDepth;

        private double[] unweighted(int d) {
            if (byDepth == null) {
                byDepth = new double[maxDepth + 2][];
                byDepth[maxDepth + 1] = new double[SLOTS];
                for (int k = maxDepth; k >= 0; k--) {
                    double[] out = new double[SLOTS];
                    for (Node m : nodes) {
                        double[] c = new double[SLOTS];
                        c[S] = m.shadow;
                        c[ALL] = m.shadow;
                        if (k < maxDepth && m.children() > 0) {
                            add(c, m, byDepth[k + 1]);
                        }
                        max(out, c);
                    }
                    byDepth[k] = out;
                }
            }
            for (Node m : nodes) {   // nothing cut below here: a chain can go on to MaxDepth
                if (m.children() > 0 && d < maxDepth) {
                    deepest = maxDepth;
                }
            }
            return byDepth[d];
        }

        /** {@code c} += what {@code m}'s secondary rays cast: themselves and the worst subtree under each. */
        private static void add(double[] c, Node m, double[] child) {
            int b = m.children();
            c[S] += b * child[S];
            c[M] += m.mirror + b * child[M];
            c[R] += m.refraction + b * child[R];
            c[ALL] += b * (1 + child[ALL]);
        }

        static void max(double[] out, double[] c) {
            for (int i = 0; i < SLOTS; i++) {
                out[i] = Math.max(out[i], c[i]);
            }
        }
    }

    /**
     * What a camera ray can hit: a surface with finite bounds only from the pixels its box projects to
     * ({@link ray.Camera#pixelsSeeing}); so a camera ray is charged the worst subtree of the materials its
     * pixel can see (nothing for the background), not of every material in the scene.
     */
    private static final class Screen {
        /** Past this many rectangles of one material, its rectangles are merged into their bounding one. */
        private static final int MAX_RECTS = 256;
        /** Past this much filling (cells x rectangles), every material is one rectangle: bounded work. */
        private static final long MAX_WORK = 1_000_000L;
        /** About how many cells the image is cut into for the sum (cells of one pixel in images up to this size). */
        private static final int CELLS = 65_536;

        private Screen() {
        }

        /** The rays of each kind (slots) under all camera rays together, divided by nothing: totals. */
        static double[] perCameraRay(Scene scene, Map<Material, Node> nodeOf, Tree tree, int ns) {
            int w = Math.max(0, scene.width), h = Math.max(0, scene.height);
            List<Node> order = new ArrayList<>();
            // per kind of hit: the boxes of the surfaces it can be on (null: unbounded), and their union
            Map<Node, List<double[]>> boxes = new HashMap<>();
            Map<Node, double[]> unions = new HashMap<>();
            Set<Material> ms = new LinkedHashSet<>();
            for (Surface s : scene.surfaces) {
                ms.clear();
                materials(s, ms);
                double[] box = null;
                boolean boxed = false;
                for (Material m : ms) {
                    Node node = nodeOf.get(m);
                    if (node == null) {
                        continue;
                    }
                    if (!boxed) {
                        box = box(s);
                        boxed = true;
                    }
                    List<double[]> l = boxes.get(node);
                    if (l == null) {
                        order.add(node);
                        boxes.put(node, l = new ArrayList<>());
                        unions.put(node, new double[] {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY});
                    }
                    l.add(box);
                    include(unions, node, box);
                }
            }
            // projected once per surface, or once for the union where a kind of hit is on many surfaces
            Map<Node, List<int[]>> rects = new HashMap<>();
            for (Node node : order) {
                List<double[]> l = boxes.get(node);
                List<int[]> out = new ArrayList<>();
                if (l.size() > MAX_RECTS) {
                    out.add(project(scene, unions.get(node), w, h));
                } else {
                    for (double[] b : l) {
                        out.add(project(scene, b, w, h));
                    }
                }
                rects.put(node, out);
            }
            double[][] cost = new double[order.size()][];
            for (int i = 0; i < order.size(); i++) {
                cost[i] = tree.cost(order.get(i), 0, 1);
                if (cost[i][ALL] == 0) {
                    rects.get(order.get(i)).clear();   // a hit that casts nothing adds nothing anywhere
                }
            }
            // the image in cells of cell x cell pixels (about CELLS of them): a cell is charged its worst rectangle
            // for each of its pixels (an upper bound, rectangles rounded out to whole cells), so the work does
            // not grow with the image
            int cell = (int) Math.max(1, Math.ceil(Math.sqrt((double) w * h / CELLS)));
            int gw = (w + cell - 1) / cell, gh = (h + cell - 1) / cell;
            long work = 0;
            for (List<int[]> l : rects.values()) {
                for (int[] r : l) {
                    work += (long) ((r[2] + cell - 1) / cell - r[0] / cell) * ((r[3] + cell - 1) / cell - r[1] / cell);
                }
            }
            if (work > MAX_WORK) {
                for (List<int[]> l : rects.values()) {
                    int[] u = union(l);
                    l.clear();
                    l.add(u);
                }
            }
            // row of cells by row: each cell's worst over the rectangles covering it, times its pixels, summed
            List<List<int[]>> starting = new ArrayList<>();
            for (int y = 0; y <= gh; y++) {
                starting.add(new ArrayList<>());
            }
            for (int i = 0; i < order.size(); i++) {
                for (int[] r : rects.get(order.get(i))) {
                    if (r[2] > r[0] && r[3] > r[1]) {
                        starting.get(r[1] / cell).add(new int[] {r[0] / cell, r[1] / cell, (r[2] + cell - 1) / cell, (r[3] + cell - 1) / cell, i});
                    }
                }
            }
            double[] total = new double[SLOTS];
            double[] row = new double[gw * SLOTS];
            List<int[]> active = new ArrayList<>();
            for (int y = 0; y < gh; y++) {
                active.addAll(starting.get(y));
                int kept = 0;
                for (int[] r : active) {   // drop the rectangles ended above this row (no removeIf lambda: see Node)
                    if (r[3] > y) {
                        active.set(kept++, r);
                    }
                }
                active.subList(kept, active.size()).clear();
                if (active.isEmpty()) {
                    continue;
                }
                int from = gw, to = 0;
                for (int[] r : active) {
                    from = Math.min(from, r[0]);
                    to = Math.max(to, r[2]);
                }
                java.util.Arrays.fill(row, from * SLOTS, to * SLOTS, 0);
                for (int[] r : active) {
                    double[] c = cost[r[4]];
                    for (int x = r[0]; x < r[2]; x++) {
                        for (int k = 0; k < SLOTS; k++) {
                            row[x * SLOTS + k] = Math.max(row[x * SLOTS + k], c[k]);
                        }
                    }
                }
                int rows = Math.min(cell, h - y * cell);
                for (int x = from; x < to; x++) {
                    double pixels = (double) rows * Math.min(cell, w - x * cell);
                    for (int k = 0; k < SLOTS; k++) {
                        total[k] += row[x * SLOTS + k] * pixels;
                    }
                }
            }
            for (int k = 0; k < SLOTS; k++) {
                total[k] *= (double) ns * ns;
            }
            return total;
        }

        /** {@code s}'s box as {min x, y, z, max x, y, z}, or null where it has none to project (unbounded, or none given). */
        private static double[] box(Surface s) {
            ray.accel.Aabb b = s.bounds();   // a user's surface may have none (null): the render names that, not the plan
            return b == null || !b.isFinite() ? null : new double[] {b.minX, b.minY, b.minZ, b.maxX, b.maxY, b.maxZ};
        }

        private static void include(Map<Node, double[]> unions, Node node, double[] box) {
            double[] u = unions.get(node);
            if (box == null || u == null) {
                unions.put(node, null);   // unbounded: the whole image
                return;
            }
            for (int i = 0; i < 3; i++) {
                u[i] = Math.min(u[i], box[i]);
                u[i + 3] = Math.max(u[i + 3], box[i + 3]);
            }
        }

        /** The pixels whose camera rays can meet {@code box} (the whole image for null or without a camera). */
        private static int[] project(Scene scene, double[] box, int w, int h) {
            if (scene.camera == null || box == null) {
                return new int[] {0, 0, w, h};
            }
            return scene.camera.pixelsSeeing(box[0], box[1], box[2], box[3], box[4], box[5], w, h);
        }

        private static int[] union(List<int[]> l) {
            if (l.isEmpty()) {
                return new int[4];
            }
            int[] u = {Integer.MAX_VALUE, Integer.MAX_VALUE, Integer.MIN_VALUE, Integer.MIN_VALUE};
            for (int[] r : l) {
                if (r[2] > r[0] && r[3] > r[1]) {
                    u[0] = Math.min(u[0], r[0]);
                    u[1] = Math.min(u[1], r[1]);
                    u[2] = Math.max(u[2], r[2]);
                    u[3] = Math.max(u[3], r[3]);
                }
            }
            return u[0] > u[2] ? new int[4] : u;
        }

        /**
         * The materials a hit on {@code s} can shade with: its own and its operands' (a CSG's), all the way
         * down, each operand once (an identity set: operands a user's class shares level after level would
         * otherwise be walked once per path, 2^60 times for 60 levels).
         */
        private static void materials(Surface s, Set<Material> out) {
            if (s.operands().isEmpty()) {    // a plain surface, nearly every one: no walk, nothing made (this runs per surface per render)
                if (s.material != null) {
                    out.add(s.material);
                }
                return;
            }
            ArrayDeque<Surface> todo = new ArrayDeque<>();
            Set<Surface> seen = Collections.newSetFromMap(new IdentityHashMap<>());
            todo.push(s);
            seen.add(s);
            while (!todo.isEmpty()) {
                Surface t = todo.pop();
                if (t.material != null) {
                    out.add(t.material);
                }
                List<Surface> ops = t.operands();
                for (int i = ops.size() - 1; i >= 0; i--) {     // the left operand's materials first, as a recursion finds them
                    if (seen.add(ops.get(i))) {
                        todo.push(ops.get(i));
                    }
                }
            }
        }
    }

    /** With faint paths cut, the bounces that can still be reached; MaxDepth otherwise. */
    public int reachableDepth() {
        narrow();
        return depth;
    }

    /** The kind with the largest bound. */
    public RayKind largest() {
        RayKind big = RayKind.CAMERA;
        for (RayKind k : RayKind.values()) {
            if (get(k) > get(big)) {
                big = k;
            }
        }
        return big;
    }

    /** What makes the bound large, in words: the factors it multiplies. */
    public String factors(Scene scene) {
        narrow();
        String s = scene.width + "x" + scene.height + " pixels x " + ns + "x" + ns + " samples";
        if (branch > 0 && depth > 0) {
            s += ", " + (branch == 1 ? "a chain of " + depth + " bounces (MaxDepth)"
                    : branch + " secondary rays per hit to MaxDepth " + depth + " (" + branch + "^" + depth + " paths)");
        }
        if (perPoint > 0 && get(RayKind.SHADOW) > 0) {
            s += ", " + (Double.isFinite(perPoint) ? PlanReport.count(perPoint) : "unknown") + (perPoint == 1 ? " shadow ray" : " shadow rays")
                    + " per lit point";
        }
        return s;
    }

    /** The bound for rays of kind {@code k}, infinite where unknown. */
    public double get(RayKind k) {
        if (k != RayKind.CAMERA) {   // camera rays are not narrowed: the JIT policy reads them on every render
            narrow();
        }
        return rays[k.ordinal()];
    }

    /**
     * All kinds together (infinite where any is unknown): the tree's bound on every ray, at most the sum
     * of the kinds' bounds.
     */
    public double total() {
        narrow();
        return total;
    }

    /** The sum of the kinds' own bounds (at least {@link #total()}). */
    public double sumOfKinds() {
        narrow();
        double t = 0;
        for (double r : rays) {
            t += r;
        }
        return Double.isFinite(t) || hasUnknown() ? t : Double.MAX_VALUE;
    }

    private boolean hasUnknown() {
        for (double r : rays) {
            if (r == Double.POSITIVE_INFINITY) {
                return true;
            }
        }
        return false;
    }

    /** {@code v}, or the largest double where a finite bound overflowed. */
    private static double finite(double v) {
        return v == Double.POSITIVE_INFINITY ? Double.MAX_VALUE : v;
    }
}
