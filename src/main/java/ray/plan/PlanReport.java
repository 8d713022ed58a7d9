package ray.plan;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.vecmath.Vector3d;
import ray.material.Term;
import ray.RayKind;
import ray.Scene;
import ray.light.Light;
import ray.material.Material;
import ray.settings.RenderSettings;

/**
 * The render plan told to a person ({@link #text()}) or a program ({@link #json}): each effect the scene
 * uses and what it costs, each it does not and why, what the plan saved, and the bound on rays with
 * and without the plan's skips.
 */
public final class PlanReport {

    /** One effect: its name, whether it is on, why, and the kind of ray it casts (null: none). */
    public static final class Effect {
        public final String name, why;
        public final boolean on;
        public final RayKind kind;

        Effect(String name, boolean on, String why, RayKind kind) {
            this.name = name;
            this.on = on;
            this.why = why;
            this.kind = kind;
        }
    }

    private final String sceneName;
    private final RenderPlan plan, without;
    private final List<Effect> effects = new ArrayList<>();
    private final List<String> lightLines = new ArrayList<>(), saved = new ArrayList<>(), skipped = new ArrayList<>();

    public PlanReport(String sceneName, RenderPlan plan, RenderPlan without) {
        this.sceneName = sceneName;
        this.plan = plan;
        this.without = without;
        Scene s = plan.scene();
        RenderSettings set = plan.settings();
        Map<Material, Shading> used = plan.used;
        int ns = set.samples(), maxDepth = set.maxDepth();
        effects.add(new Effect("camera rays", true, s.width + " x " + s.height + " pixels x " + (set.adaptive() ? "at most " : "") + ns + "x" + ns
                + " samples (" + set.sampler() + " sampler)", RayKind.CAMERA));
        effects.add(new Effect("geometry", !s.surfaces.isEmpty(), Geometry.describe(s.surfaces), null));
        List<Material> ambient = zero(s.ambientLight) ? List.of() : select(used, true, "ambient"), direct = select(used, true, "direct"),
                highlight = select(used, true, "highlight"), mirror = select(used, true, "mirror"),
                refraction = select(used, true, "refraction"), unknown = select(used, true, "unknown");
        effects.add(new Effect("ambient", !ambient.isEmpty(), !ambient.isEmpty() ? "k_a I_a at " + names(ambient)
                + " (computed once per material)" : zero(s.ambientLight) ? "I_a = 0" : "no material has k_a", null));
        boolean lit = plan.lights().length > 0 && !direct.isEmpty();
        effects.add(new Effect("direct light", lit, lit ? "at " + names(direct) + ", from " + plan.lights().length + " light"
                + (plan.lights().length == 1 ? "" : "s") : s.lights.isEmpty() ? "no lights" : plan.lights().length == 0
                ? "every light is dark" : "no material has a direct term", RayKind.SHADOW));
        effects.add(new Effect("highlights", lit && !highlight.isEmpty(), !highlight.isEmpty() ? "k_s at " + names(highlight)
                : "no material has k_s", null));
        boolean reflects = !mirror.isEmpty() && maxDepth > 0;
        effects.add(new Effect("mirror reflection", reflects, reflects ? "at " + names(mirror) + ", MaxDepth " + maxDepth
                : mirror.isEmpty() ? "no material reflects" : "MaxDepth 0", RayKind.MIRROR));
        boolean refracts = !refraction.isEmpty() && maxDepth > 0;
        effects.add(new Effect("refraction", refracts, refracts ? "at " + names(refraction) + ", MaxDepth " + maxDepth
                : refraction.isEmpty() ? "no material refracts" : "MaxDepth 0", RayKind.REFRACTION));
        List<String> sampled = new ArrayList<>();
        for (Light l : plan.lights()) {
            if (!plan.unknownLights.contains(l) && l.plannedShadowRays() > 1) {
                sampled.add(label(l) + " " + l.plannedShadowRays());
            }
        }
        effects.add(new Effect("area-light samples", lit && !sampled.isEmpty(), sampled.isEmpty() ? "no sampled light"
                : "per lit point: " + String.join(", ", sampled), null));
        if (plan.cutsFaintPaths()) {
            RayCountBound b = plan.bound();
            int reachable = b.reachableDepth();   // (narrows the bound first: the depth the narrowing reaches)
            effects.add(new Effect("faint paths cut", true, "inexact, --cut-faint: no mirror ray where the product of k_m along the path"
                    + " is below 1/510 (half an 8-bit step for radiance up to 1)" + (b.uncutDepth > reachable
                    ? "; at most " + reachable + " of MaxDepth " + b.uncutDepth + " bounces reachable" : "; no bounce provably cut"), null));
        }
        boolean user = !unknown.isEmpty() || lit && !plan.unknownLights.isEmpty();
        List<String> who = new ArrayList<>();
        for (Material m : unknown) {
            who.add(label(m));
        }
        for (Light l : plan.unknownLights) {
            who.add(label(l));
        }
        effects.add(new Effect("user rays", user, user ? "user classes the plan cannot see into: " + String.join(", ", who)
                + " (assumed to need everything)" : "no user class", RayKind.USER));
        for (int i = 0; i < s.lights.size(); i++) {
            Light l = s.lights.get(i);
            lightLines.add(label(l) + ": " + (plan.dark.contains(l) ? "zero intensity, skipped"
                    : plan.unknownLights.contains(l) ? "a user's light: evaluated through its own code, rays unknown"
                    : l.plannedShadowRays() + " shadow ray" + (l.plannedShadowRays() == 1 ? "" : "s") + " per lit point"));
        }
        savings(s);
    }

    /**
     * What each exact skip saves here, measured on the bound: the plan derived once more without that one
     * skip. A skip that changes the bound is a saving, with the difference; one that does work here but
     * meets no worst path is listed as skipped, the bound the same either way.
     */
    private void savings(Scene s) {
        for (Skip k : Skip.values()) {
            if (!plan.skipping(k)) {
                continue;
            }
            java.util.EnumSet<Skip> others = java.util.EnumSet.copyOf(plan.skips());
            others.remove(k);
            RenderPlan less = RenderPlan.derive(s, plan.settings(), others);
            String what = what(k, less);
            if (what == null) {
                continue;
            }
            RayCountBound with = plan.bound(), without = less.bound();
            double fewer = without.total() - with.total();
            if (fewer > 0 || !Double.isFinite(without.total())) {
                List<String> kinds = new ArrayList<>();
                for (RayKind kind : RayKind.values()) {
                    double d = without.get(kind) - with.get(kind);
                    if (d > 0) {
                        kinds.add(kind.key() + " " + count(d));
                    }
                }
                saved.add(what + "; bound " + count(fewer) + " rays lower (" + String.join(", ", kinds) + ")");
            } else {
                skipped.add(what + " (the bound is the same without it: its worst path does not meet it)");
            }
        }
    }

    /** What skip {@code k} leaves out in this scene (the plan {@code less} derived without it), or null: nothing. */
    private String what(Skip k, RenderPlan less) {
        List<Material> ms = new ArrayList<>();
        switch (k) {
            case DARK_LIGHTS -> {
                if (plan.dark.isEmpty()) {
                    return null;
                }
                List<String> names = new ArrayList<>();
                for (Light l : plan.dark) {
                    names.add(label(l));
                }
                return String.join(", ", names) + (names.size() == 1 ? " has" : " have") + " zero intensity: skipped";
            }
            case NO_DIRECT_TERM -> {
                for (Map.Entry<Material, Shading> e : plan.used.entrySet()) {
                    Shading w = less.used.get(e.getKey());
                    if (!e.getValue().direct && w != null && w.direct) {
                        ms.add(e.getKey());
                    }
                }
                return ms.isEmpty() ? null : "no light evaluation and no shadow rays at " + names(ms) + ": k_d = k_s = 0, no direct term";
            }
            case ZERO_MIRROR -> {
                for (Map.Entry<Material, Shading> e : plan.used.entrySet()) {
                    Shading w = less.used.get(e.getKey());
                    if (w != null && w.mirror > e.getValue().mirror) {
                        ms.add(e.getKey());
                    }
                }
                return ms.isEmpty() ? null : "no mirror rays at " + names(ms) + ": k_m = 0";
            }
            case FOLD_GLAZED -> {
                List<String> lines = new ArrayList<>();
                for (Map.Entry<Material, Shading> e : plan.used.entrySet()) {
                    Shading w = less.used.get(e.getKey());
                    if (e.getValue().folded > 1 && w != null && w.mirror > e.getValue().mirror) {
                        lines.add(label(e.getKey()) + " (" + e.getValue().folded + " levels): " + e.getValue().mirror + " mirror ray"
                                + (e.getValue().mirror == 1 ? "" : "s") + " per hit instead of " + w.mirror);
                    }
                }
                return lines.isEmpty() ? null : "nested Glazed chain" + (lines.size() == 1 ? "" : "s") + " folded at " + String.join(", ", lines);
            }
            default -> throw new IllegalArgumentException(k.name());
        }
    }

    /** The materials whose shading has the named property. */
    private static List<Material> select(Map<Material, Shading> used, boolean on, String what) {
        List<Material> out = new ArrayList<>();
        for (Map.Entry<Material, Shading> e : used.entrySet()) {
            Shading s = e.getValue();
            boolean has = switch (what) {
                case "ambient" -> s.terms.contains(Term.AMBIENT);
                case "direct" -> s.direct;
                case "highlight" -> s.terms.contains(Term.HIGHLIGHT);
                case "mirror" -> s.mirror > 0;
                case "refraction" -> s.refraction > 0;
                case "unknown" -> s.unknown;
                default -> throw new IllegalArgumentException(what);
            };
            if (has == on) {
                out.add(e.getKey());
            }
        }
        return out;
    }

    private String names(List<Material> ms) {
        List<String> n = new ArrayList<>();
        for (int i = 0; i < ms.size() && i < 6; i++) {
            n.add(label(ms.get(i)));
        }
        return String.join(", ", n) + (ms.size() > 6 ? " and " + (ms.size() - 6) + " more" : "");
    }

    private String label(Object o) {
        String name = plan.scene().nameOf(o);
        String cls = o.getClass().getSimpleName();
        if (o instanceof Light) {
            return "light " + (plan.scene().lights.indexOf(o) + 1) + " (" + cls + (name == null ? "" : " " + name) + ")";
        }
        return name != null ? name : cls;
    }

    private static String plural(int n, String what) {
        return n + " " + what + (n == 1 ? "" : "s");
    }

    private static boolean zero(Vector3d v) {
        return v.x == 0 && v.y == 0 && v.z == 0;
    }

    /** The plan of {@code scene} rendered with {@code settings}, every exact skip made, beside the same plan without them. */
    public static PlanReport of(String name, Scene scene, RenderSettings settings) {
        return new PlanReport(name, RenderPlan.derive(scene, settings), RenderPlan.derive(scene, settings, RenderPlan.NO_SKIPS));
    }

    /** {@link #of(String, Scene, RenderSettings)} with the scene's own settings. */
    public static PlanReport of(String name, Scene scene) {
        return of(name, scene, new RenderSettings());
    }

    /** The plan with the exact skips. */
    public RenderPlan plan() {
        return plan;
    }

    public List<Effect> effects() {
        return effects;
    }

    /** The exact skips that lower the bound here, each with how much. */
    public List<String> saved() {
        return saved;
    }

    /** The exact skips that do work here without lowering the bound (no worst path meets them). */
    public List<String> skipped() {
        return skipped;
    }

    /** The plan for a person: one line per effect, the lights, what was saved, the bounds. */
    public List<String> text() {
        List<String> out = new ArrayList<>();
        Scene s = plan.scene();
        out.add("plan for " + sceneName + " (" + s.width + "x" + s.height + ", MaxDepth " + plan.settings().maxDepth() + ")");
        for (Effect e : effects) {
            String cost = e.kind == null ? "" : "   <= " + count(plan.bound().get(e.kind)) + " " + e.kind.key() + (plan.bound().get(e.kind) == 1 ? " ray" : " rays");
            out.add(String.format(java.util.Locale.ROOT, "  %-19s %-4s %s%s", e.name, e.on ? "on" : "off", e.why, e.on ? cost : ""));
        }
        for (String l : lightLines) {
            out.add("    " + l);
        }
        for (String w : saved) {
            out.add("  saved: " + w);
        }
        for (String w : skipped) {
            out.add("  skipped: " + w);
        }
        out.add("  bound: " + bounds(plan.bound()));
        out.add("  without the plan's skips: " + bounds(without.bound()));
        return out;
    }

    /** "1,234 rays (camera ..., shadow ...)", or "... rays in all (by kind: ...)" where the kinds' worst paths differ. */
    private static String bounds(RayCountBound b) {
        StringBuilder t = new StringBuilder(count(b.total()) + (b.total() < b.sumOfKinds() ? " rays in all (by kind: " : " rays ("));
        for (RayKind k : RayKind.values()) {
            t.append(k.ordinal() == 0 ? "" : ", ").append(k.key()).append(' ').append(count(b.get(k)));
        }
        return t.append(')').toString();
    }

    /** A ray count for people: grouped digits, or 1.2e+13 when large, "unbounded" when unknown. */
    public static String count(double n) {
        if (!Double.isFinite(n)) {
            return "unbounded";
        }
        return n < 1e12 ? String.format(java.util.Locale.ROOT, "%,d", (long) n) : String.format(java.util.Locale.ROOT, "%.1e", n);
    }

    /** The plan for a program: one JSON object (keys in docs/json.md), without an estimate. */
    public String json() {
        return json(null, 0);
    }

    /** The plan for a program with the pilot's estimate on {@code threads} threads ({@code null}: none). */
    public String json(RayEstimate estimate, int threads) {
        Scene s = plan.scene();
        JsonLine j = new JsonLine().put("scene", sceneName).put("width", s.width).put("height", s.height)
                .put("samplesPerPixel", plan.settings().samples() * plan.settings().samples()).put("maxDepth", plan.settings().maxDepth());
        j.open("effects");
        for (Effect e : effects) {
            j.open(key(e.name)).put("on", e.on).put("why", e.why).close();
        }
        j.close();
        bound(j.open("bound"), plan.bound()).close();
        bound(j.open("boundWithoutPlan"), without.bound()).close();
        j.put("totalBound", plan.bound().total()).put("totalBoundWithoutPlan", without.bound().total());
        j.put("cutFaint", plan.cutsFaintPaths()).put("lights", lightLines).put("saved", saved).put("skipped", skipped);
        if (estimate != null) {
            j.open("estimate");
            for (RayKind k : RayKind.values()) {
                j.put(k.key(), Math.round(estimate.get(k)));
            }
            j.put("seconds", estimate.seconds(threads)).put("cpuSeconds", estimate.cpuSeconds()).put("threads", threads)
                    .put("pilotFraction", estimate.fraction).close();
        } else {
            j.put("estimate", (String) null);
        }
        return j.toString();
    }

    private static JsonLine bound(JsonLine j, RayCountBound b) {
        for (RayKind k : RayKind.values()) {
            j.put(k.key(), b.get(k));
        }
        return j;
    }

    /** "mirror reflection" -> "mirrorReflection". */
    static String key(String name) {
        StringBuilder k = new StringBuilder();
        boolean up = false;
        for (char c : name.toCharArray()) {
            if (c == ' ' || c == '-') {
                up = true;
            } else {
                k.append(up ? Character.toUpperCase(c) : c);
                up = false;
            }
        }
        return k.toString();
    }
}
