package ray;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import javax.vecmath.Vector3d;
import ray.accel.Accelerator;
import ray.light.Light;
import ray.light.LightSample;
import ray.material.Material;
import ray.surface.Surface;

/**
 * Everything a render needs: camera, surfaces, lights, materials and the global settings of the scene
 * file ({@code BGColor}, {@code AmbientLight}, {@code Width}, {@code Height}, {@code AASamples},
 * {@code MaxDepth}, {@code Sampler}, {@code TargetError}). Data, and the ray-query layer over it: a
 * render's own settings ({@code ray.settings.RenderSettings}) are resolved from these globals once and
 * never written back.
 *
 * <p>The framework's methods are kept: {@link #renderAll()}, {@link #renderPixel(int, int)} and
 * {@link #trace(Ray)}. Before the first ray the scene is prepared (camera frame, render plan, BVH) by the
 * renderer or, for the framework's methods, by {@link #prepare()}; call it again after changing the scene.
 */
public class Scene {

    public Camera camera;
    public Vector3d backgroundColor = new Vector3d();
    public Vector3d ambientLight = new Vector3d();
    public int width;
    public int height;
    /** n_s: each pixel is the mean of n_s x n_s samples. */
    public int samplesPerPixel = 1;
    /** The scene's {@code Sampler} global: one of {@code ray.settings.RenderOption.SAMPLER}'s choices (grid, the default). */
    public String sampler = "grid";
    /** The scene's {@code TargetError} global: the adaptive sampler's target, in 8-bit steps. */
    public double targetError = 0.5;
    /** Mirror bounces followed (0: the bases of glazed materials only). */
    public int maxDepth = 10;
    public List<Surface> surfaces = new ArrayList<>();
    public List<Light> lights = new ArrayList<>();
    public List<Material> materials = new ArrayList<>();

    private volatile Accelerator accel;
    /** The names objects were given in the scene file ({@code Material Diffuse red}), for messages and the plan. */
    private final Map<Object, String> names = new IdentityHashMap<>();

    /**
     * Readies the scene for rays with its own settings (camera frame, render plan, acceleration structure)
     * through the {@link Engine}. Called lazily by the first ray of the framework's methods; a render
     * prepares with its own settings instead.
     */
    public synchronized void prepare() {
        Engine.get().prepare(this);
    }

    /**
     * Fixes the camera frame: the aspect from the image size where the scene gave none, then
     * {@link Camera#init()}. The first step of every preparation.
     */
    public void prepareCamera() {
        if (camera == null) {
            throw new IllegalStateException("the scene has no camera");
        }
        if (Double.isNaN(camera.aspect) && width > 0 && height > 0) {
            camera.aspect = (double) width / height;
        }
        camera.init();
    }

    /** Records the name {@code o} has in the scene file. */
    public void name(Object o, String name) {
        names.put(o, name);
    }

    /** The name {@code o} has in the scene file, or null. */
    public String nameOf(Object o) {
        return names.get(o);
    }

    /** The acceleration structure, built on first use. */
    public Accelerator accelerator() {
        Accelerator a = accel;
        if (a == null) {
            prepare();
            a = accel;
        }
        return a;
    }

    /**
     * Installs the acceleration structure rays are tested against until the next preparation (the
     * preparation installs the BVH here; the benchmark wraps it to record the rays a render casts).
     */
    public void useAccelerator(Accelerator a) {
        accel = a;
    }

    /** Renders the whole image with the scene's own settings: {@code [x][y]}, x across, y down from the top row. */
    public Vector3d[][] renderAll() {
        return Engine.get().renderAll(this);
    }

    /** The colour of pixel (x, y): the mean of its n_s x n_s samples. */
    public Vector3d renderPixel(int x, int y) {
        accelerator();   // prepares a scene not rendered yet: the camera frame is set up there
        Vector3d out = new Vector3d();
        Engine.get().renderPixel(this, TraceContext.current(this), x, y, out);
        return out;
    }

    // ---- the ray-query layer: every ray is cast, and counted by its RayKind, in one of these ----

    /**
     * The colour seen along {@code ray}: the hit surface's material, or {@code BGColor} where nothing is
     * hit. This is the framework's method for a user's own classes; its rays count as {@link RayKind#USER}.
     */
    public Vector3d trace(Ray ray) {
        TraceContext ctx = TraceContext.current(this);
        Vector3d out = new Vector3d();
        int depth = Math.max(ray.depth, ctx.level);
        if (depth > ctx.maxDepth) {
            return out;   // a user material recursing past MaxDepth: not followed (not cast), black
        }
        Ray r = new Ray();
        r.origin.set(ray.origin);
        r.direction.set(ray.direction);
        r.tMin = ray.tMin;
        r.tMax = ray.tMax;
        r.depth = depth;
        ctx.stats.count(RayKind.USER);
        shadeClosest(r, ctx, out);
        return out;
    }

    /** A camera ray (one per sample, depth 0): its colour into {@code out}. Counted as {@link RayKind#CAMERA}. */
    public void traceCamera(Ray ray, TraceContext ctx, Vector3d out) {
        ctx.stats.count(RayKind.CAMERA);
        shadeClosest(ray, ctx, out);
    }

    /**
     * The packet's camera rays (each one sample's, from the eye, depth 0), cast together: each ray's
     * closest hit into its record, the same as {@link #traceCamera}'s ray for ray. Each counted as
     * {@link RayKind#CAMERA}. Then {@link #shadeCamera} gives each ray's colour.
     */
    public void castCameras(RayPacket p, TraceContext ctx) {
        ctx.stats.count(RayKind.CAMERA, p.size);
        accelerator().closestHits(p, ctx);
    }

    /** The colour of ray {@code k} of a packet cast by {@link #castCameras}, into {@code out}: {@link #traceCamera}'s. */
    public void shadeCamera(RayPacket p, int k, TraceContext ctx, Vector3d out) {
        // shadeClosest's shading, written out again: a call more there costs the short renders under C1
        if (!p.hit[k]) {
            out.set(backgroundColor);
            return;
        }
        IntersectionRecord rec = p.records[k];
        rec.surface.material.shadeHit(p.rays[k], rec, this, ctx, out);
    }

    /**
     * The ideal mirror reflection of {@code ray} at {@code rec} (r = d - 2 (d.n) n), cast one bounce deeper
     * and counted as {@link RayKind#MIRROR}: the colour it sees, or null when the incoming ray is already
     * at {@code MaxDepth} (nothing cast). The returned vector is {@code ctx}'s scratch for that depth: read
     * it before casting the next ray of the same depth.
     */
    public Vector3d traceMirror(Ray ray, IntersectionRecord rec, TraceContext ctx) {
        Vector3d d = ray.direction, n = rec.normal;
        double dn = 2 * (d.x * n.x + d.y * n.y + d.z * n.z);
        return traceSecondary(RayKind.MIRROR, ray, rec, d.x - dn * n.x, d.y - dn * n.y, d.z - dn * n.z, ctx);
    }

    /**
     * A transmitted ray leaving {@code rec}'s point along (dx, dy, dz) (the refracted direction the
     * material computed; the origin is offset to that side of the surface), cast one bounce deeper and
     * counted as {@link RayKind#REFRACTION}. Returns what {@link #traceMirror} returns.
     */
    public Vector3d traceRefraction(Ray ray, IntersectionRecord rec, double dx, double dy, double dz, TraceContext ctx) {
        return traceSecondary(RayKind.REFRACTION, ray, rec, dx, dy, dz, ctx);
    }

    private Vector3d traceSecondary(RayKind kind, Ray ray, IntersectionRecord rec, double dx, double dy, double dz,
                                    TraceContext ctx) {
        // inside framework-style material code, ctx.level is the depth of the rays it traces: one more
        // than the ray it is shading (which may be a fresh Ray of depth 0 it made itself)
        int depth = Math.max(ray.depth, ctx.level - 1);
        if (depth >= ctx.maxDepth) {
            return null;
        }
        Ray next = ctx.ray(depth + 1);
        rec.spawnRay(dx, dy, dz, next);
        next.depth = depth + 1;
        Vector3d c = ctx.color(depth + 1);
        ctx.stats.count(kind);
        shadeClosest(next, ctx, c);
        return c;
    }

    /** Shades the closest hit along {@code ray} into {@code out} (BGColor on a miss). Counts nothing. */
    private void shadeClosest(Ray ray, TraceContext ctx, Vector3d out) {
        IntersectionRecord rec = ctx.record(ray.depth);
        if (!accelerator().closestHit(ray, rec, ctx)) {
            out.set(backgroundColor);
            return;
        }
        Material m = rec.surface.material;
        m.shadeHit(ray, rec, this, ctx, out);
    }

    /**
     * The closest hit along {@code ray} within its span, written into {@code record}; false on a miss.
     * Counted as {@link RayKind#USER} (built-in code never calls it).
     */
    public boolean intersect(Ray ray, IntersectionRecord record) {
        TraceContext ctx = TraceContext.current(this);
        ctx.stats.count(RayKind.USER);
        return accelerator().closestHit(ray, record, ctx);
    }

    /** True when anything lies on {@code ray} within its span (a shadow query, counted as {@link RayKind#SHADOW}). */
    public boolean occluded(Ray ray) {
        TraceContext ctx = TraceContext.current(this);
        ctx.stats.count(RayKind.SHADOW);
        return accelerator().anyHit(ray, ctx);
    }

    /** True when something lies between {@code record}'s point and the light sample (its position, or infinitely far). */
    public boolean occluded(IntersectionRecord record, LightSample sample) {
        return occluded(record, sample, TraceContext.current(this));
    }

    /**
     * Allocation-free shadow query for a light sample, on {@code ctx}'s shadow ray ({@link RayKind#SHADOW}):
     * to the sample's position, or to infinity along its direction for a light infinitely far away.
     */
    public boolean occluded(IntersectionRecord record, LightSample sample, TraceContext ctx) {
        return occluded(record, sample, ctx, -1);
    }

    /**
     * The shadow query for one of the samples of light number {@code light} (its index among the lights
     * a material shades; another number, -1 say: none): the accelerator first tests whatever stopped
     * this thread's last shadowed ray toward that light ({@link Accelerator#anyHit(Ray, TraceContext, int)},
     * the occluder cache). The answer is the same as without it.
     */
    public boolean occluded(IntersectionRecord record, LightSample sample, TraceContext ctx, int light) {
        Ray s = ctx.shadowRay;
        if (sample.distance == Double.POSITIVE_INFINITY) {
            Vector3d d = sample.direction;
            record.spawnRay(d.x, d.y, d.z, s);
        } else {
            Vector3d p = sample.position;
            record.spawnRayTo(p.x, p.y, p.z, s);
        }
        ctx.stats.count(RayKind.SHADOW);
        return accelerator().anyHit(s, ctx, light);
    }
}
