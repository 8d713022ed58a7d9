package ray.plan;

import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import ray.material.Term;
import ray.Scene;
import ray.light.Light;
import ray.material.Material;
import ray.material.ShadingPlan;
import ray.settings.RenderSettings;
import ray.surface.Surface;

/**
 * The render plan: which effects a scene uses, derived once per render from its materials, lights,
 * surfaces and resolved {@link RenderSettings} before the first ray, with an upper bound on the rays
 * of each kind. Built-in materials read it once ({@link Material#planned}) and cast only what it lists:
 * no light evaluation where a material has no direct term, no dark light, no mirror ray where k_m = 0,
 * one mirror ray for a chain of Glazed materials. {@link PlanReport} prints it.
 */
public final class RenderPlan implements ShadingPlan {

    /** Every exact skip off: the renderer does what it did before the plan. */
    public static final Set<Skip> NO_SKIPS = Collections.unmodifiableSet(EnumSet.noneOf(Skip.class));

    /**
     * With {@code --cut-faint}, a mirror ray is not cast where the product of the mirror coefficients
     * along its path is below this: half an 8-bit step for radiance up to 1. Inexact (brighter light
     * seen at the end of such a path is lost), so opt-in.
     */
    public static final double FAINT = ShadingPlan.FAINT;

    private final Scene scene;
    /** The render's settings, resolved against the scene: what the bound counts and the report prints. */
    private final RenderSettings settings;
    private final Set<Skip> skips;
    private final boolean cutFaint;
    private final Light[] lights;
    /** Every material a hit can shade (on surfaces, declared, or a Glazed base), for {@link #apply()}. */
    private final Set<Material> materials;
    /** How each material on a surface shades, in scene order. */
    final Map<Material, Shading> used = new LinkedHashMap<>();
    /** Lights the plan skipped, and lights whose rays it cannot know (user classes). */
    final List<Light> dark = new ArrayList<>(), unknownLights = new ArrayList<>();
    final RayCountBound bound;

    private RenderPlan(Scene scene, RenderSettings settings, Set<Skip> skips) {
        this.scene = scene;
        this.settings = settings.resolve(scene);
        this.cutFaint = settings.cutsFaintPaths();
        this.skips = skips.isEmpty() ? NO_SKIPS : Collections.unmodifiableSet(EnumSet.copyOf(skips));
        List<Light> evaluated = new ArrayList<>();
        for (Light l : scene.lights) {   // a light's own declarations, inherited where its class does not change them
            if (l.plannedDark() && this.skips.contains(Skip.DARK_LIGHTS)) {
                dark.add(l);
                continue;
            }
            if (l.plannedShadowRays() < 0) {
                unknownLights.add(l);
            }
            evaluated.add(l);
        }
        lights = evaluated.toArray(new Light[0]);
        // Breadth first: the scene's surfaces in order, then a CSG's operands (which shade its hits with
        // their own materials). Runs of surfaces sharing a material (a mesh's 100k triangles) cost one
        // comparison each, not a map lookup: the plan is derived before every render.
        // Each operand once (an identity set): operands shared level after level (a user's class, a DAG)
        // would otherwise be queued once per path, doubling at each level.
        java.util.ArrayDeque<Surface> parts = new java.util.ArrayDeque<>();
        java.util.Set<Surface> queued = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        Material last = null;
        for (Surface s : scene.surfaces) {
            last = use(s, last, parts, queued);
        }
        while (!parts.isEmpty()) {
            last = use(parts.pop(), last, parts, queued);
        }
        materials = new LinkedHashSet<>(used.keySet());
        materials.addAll(scene.materials);
        java.util.ArrayDeque<Material> todo = new java.util.ArrayDeque<>();
        for (Material m : materials) {   // loops, not lambdas, here: the plan is derived at start-up
            todo.add(m);
        }
        while (!todo.isEmpty()) {   // the parts a composite material shades through (a Glazed base), declared or not
            Material m = todo.pop();
            if (m != null) {
                for (Material part : m.parts()) {
                    if (materials.add(part)) {
                        todo.push(part);
                    }
                }
            }
        }
        materials.remove(null);
        bound = RayCountBound.of(this);
    }

    /**
     * Notes how {@code s}'s material shades (unless it is {@code last}, noted just before) and queues its
     * operands; returns the material to compare the next surface with.
     */
    private Material use(Surface s, Material last, java.util.ArrayDeque<Surface> parts, java.util.Set<Surface> queued) {
        Material m = s.material;
        if (m != null && m != last) {
            if (!used.containsKey(m)) {
                used.put(m, Shading.of(m, this));
            }
            last = m;
        }
        List<Surface> ops = s.operands();
        for (int i = 0; i < ops.size(); i++) {
            if (queued.add(ops.get(i))) {
                parts.add(ops.get(i));
            }
        }
        return last;
    }

    /** Derives the plan of {@code scene} rendered with its own settings, with the given exact skips. */
    public static RenderPlan derive(Scene scene, Set<Skip> skips) {
        return new RenderPlan(scene, new RenderSettings(), skips);
    }

    /**
     * The plan of {@code scene} rendered with {@code settings} (resolved against it here; cutting faint
     * mirror paths when they say so, inexact: {@link #FAINT}), with the given exact skips.
     */
    public static RenderPlan derive(Scene scene, RenderSettings settings, Set<Skip> skips) {
        return new RenderPlan(scene, settings, skips);
    }

    /** {@link #derive(Scene, RenderSettings, Set)} with every exact skip: the plan a render uses. */
    public static RenderPlan derive(Scene scene, RenderSettings settings) {
        return new RenderPlan(scene, settings, EnumSet.allOf(Skip.class));
    }

    /** The settings the plan was derived for, resolved against its scene. */
    public RenderSettings settings() {
        return settings;
    }

    /** True when mirror paths fainter than {@link #FAINT} are cut (the one inexact skip, opt-in). */
    @Override
    public boolean cutsFaintPaths() {
        return cutFaint;
    }

    @Override
    public boolean skipsLightsWithoutDirectTerm() {
        return skips.contains(Skip.NO_DIRECT_TERM);
    }

    @Override
    public boolean skipsZeroMirrors() {
        return skips.contains(Skip.ZERO_MIRROR);
    }

    @Override
    public boolean foldsGlazedChains() {
        return skips.contains(Skip.FOLD_GLAZED);
    }

    /** Hands the plan to every material ({@link Material#planned}); the scene's preparation calls it. */
    public void apply() {
        for (Material m : materials) {
            m.planned(this);
        }
    }

    @Override
    public Scene scene() {
        return scene;
    }

    /** The lights a direct term evaluates: the scene's lights without the dark ones (when skipping them). */
    @Override
    public Light[] lights() {
        return lights;
    }

    /** True when the plan makes this exact skip. */
    public boolean skipping(Skip s) {
        return skips.contains(s);
    }

    public Set<Skip> skips() {
        return skips;
    }

    /** Upper bounds on the rays of each kind this render can cast. */
    public RayCountBound bound() {
        return bound;
    }
}
