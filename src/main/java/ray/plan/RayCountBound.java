package ray.plan;

import ray.RayKind;
import ray.Scene;

/**
 * Upper bounds on how many rays one render can cast, by kind: camera, shadow, mirror, refraction, user
 * (rays user classes trace through {@code Scene.trace}). {@link Double#POSITIVE_INFINITY} where a user
 * class may trace any number of rays.
 *
 * <p>With N camera rays, MaxDepth D and b the most secondary rays one hit casts, at most N b^d rays
 * reach depth d, so hits &lt;= N (1 + b + ... + b^D); each hit at depth &lt; D casts at most m mirror and
 * r refraction rays; each hit on a material with a direct term casts at most S shadow rays, S the sum
 * of the evaluated lights' shadow rays per point.
 */
public final class RayCountBound {

    private static final int CAMERA = RayKind.CAMERA.ordinal(), SHADOW = RayKind.SHADOW.ordinal(),
            MIRROR = RayKind.MIRROR.ordinal(), REFRACTION = RayKind.REFRACTION.ordinal(), USER = RayKind.USER.ordinal();

    private final double[] rays = new double[RayKind.values().length];
    /** What the bound was computed from: camera rays, most secondary rays per hit, shadow rays per lit point, MaxDepth. */
    double cameraRays, perPoint;
    int branch, depth, ns;
    /** With faint paths cut: MaxDepth, of which only {@link #depth} bounces can be reached (-1: nothing cut). */
    int uncutDepth = -1;

    private RayCountBound() {
    }

    static RayCountBound of(RenderPlan plan) {
        Scene scene = plan.scene();
        RayCountBound b = new RayCountBound();
        int ns = plan.settings().samples();
        double n = (double) Math.max(0, scene.width) * Math.max(0, scene.height) * ns * ns;
        b.rays[CAMERA] = n;
        int mirror = 0, refraction = 0, branch = 0;
        boolean direct = false, unknown = false;
        for (Shading s : plan.used.values()) {
            mirror = Math.max(mirror, s.mirror);
            refraction = Math.max(refraction, s.refraction);
            branch = Math.max(branch, s.mirror + s.refraction);
            direct |= s.direct;
            unknown |= s.unknown;
        }
        double perPoint = 0;
        for (ray.light.Light l : plan.lights()) {
            perPoint += plan.unknownLights.contains(l) ? Double.POSITIVE_INFINITY : l.plannedShadowRays();
        }
        int depth = Math.max(0, plan.settings().maxDepth());
        if (plan.cutsFaintPaths()) {
            b.uncutDepth = depth;
            depth = cutDepth(plan, depth);
        }
        b.cameraRays = n;
        b.ns = ns;
        b.perPoint = perPoint;
        b.branch = branch;
        b.depth = depth;
        // a known bound that overflows a double (glass at MaxDepth 1000: 2^1000 paths) stays finite, the
        // largest double, so that it is refused as astronomical and never read as "unknown" (infinite)
        double hits = finite(n * geometric(branch, depth)), parents = finite(n * geometric(branch, depth - 1));
        if (unknown) {   // a user's material: any number of rays of its own, each shading anything
            hits = parents = Double.POSITIVE_INFINITY;
        }
        b.rays[MIRROR] = mirror == 0 ? 0 : parents * mirror;
        b.rays[REFRACTION] = refraction == 0 ? 0 : parents * refraction;
        b.rays[SHADOW] = direct && perPoint > 0 ? hits * perPoint : 0;
        if (!unknown) {
            b.rays[MIRROR] = finite(b.rays[MIRROR]);
            b.rays[REFRACTION] = finite(b.rays[REFRACTION]);
            b.rays[SHADOW] = Double.isFinite(perPoint) ? finite(b.rays[SHADOW]) : b.rays[SHADOW];
        }
        b.rays[USER] = unknown || direct && !plan.unknownLights.isEmpty() ? Double.POSITIVE_INFINITY : 0;
        return b;
    }

    /**
     * The deepest mirror ray a render cutting faint paths can cast: a ray of depth d carries a weight
     * of at most k^d (k the largest weight one hit gives), and none is cast below {@link RenderPlan#FAINT}.
     */
    static int cutDepth(RenderPlan plan, int depth) {
        double k = 0;
        for (Shading s : plan.used.values()) {
            k = Math.max(k, s.weight);
        }
        if (!(k < 1)) {
            return depth;   // refraction, user code or a coefficient >= 1: nothing provably faint
        }
        int d = 0;
        for (double w = 1; d < depth && w * k >= RenderPlan.FAINT; d++) {
            w *= k;
        }
        return d;
    }

    /** With faint paths cut, the bounces that can still be reached; MaxDepth otherwise. */
    public int reachableDepth() {
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

    /** 1 + b + ... + b^k (0 for k &lt; 0). */
    static double geometric(int b, int k) {
        if (k < 0) {
            return 0;
        }
        if (b == 1) {
            return k + 1;
        }
        double sum = 0, term = 1;
        for (int d = 0; d <= k && sum < Double.MAX_VALUE; d++) {
            sum += term;
            term *= b;
        }
        return sum;
    }

    /** The bound for rays of kind {@code k}, infinite where unknown. */
    public double get(RayKind k) {
        return rays[k.ordinal()];
    }

    /** All kinds together (infinite where any is unknown). */
    public double total() {
        double t = 0;
        boolean unknown = false;
        for (double r : rays) {
            t += r;
            unknown |= r == Double.POSITIVE_INFINITY;
        }
        return unknown ? t : finite(t);
    }

    /** {@code v}, or the largest double where a finite bound overflowed. */
    private static double finite(double v) {
        return v == Double.POSITIVE_INFINITY ? Double.MAX_VALUE : v;
    }
}
