package ray.render;

import javax.vecmath.Vector3d;
import ray.Engine;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Bvh;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/**
 * The product's {@link Engine}: readies a scene for rays (camera frame, render plan handed to the
 * materials, BVH) and renders it for the framework's own methods. The one place a scene is prepared;
 * {@link Renderer#render()} prepares through it with the render's own plan.
 */
public final class RenderEngine implements Engine {

    /** For {@link java.util.ServiceLoader}. */
    public RenderEngine() {
    }

    @Override
    public void prepare(Scene scene) {
        prepare(scene, RenderPlan.derive(scene, new RenderSettings()));
    }

    /**
     * Readies {@code scene} for rays under {@code plan} (derived for it): the camera frame, the plan handed
     * to every material ({@link RenderPlan#apply()}), then the BVH over its surfaces.
     */
    public static void prepare(Scene scene, RenderPlan plan) {
        if (plan.scene() != scene) {
            throw new IllegalArgumentException("the plan was derived for another scene");
        }
        synchronized (scene) {
            scene.prepareCamera();
            plan.apply();
            scene.useAccelerator(Bvh.build(scene.surfaces, scene));
        }
    }

    @Override
    public Vector3d[][] renderAll(Scene scene) {
        return new Renderer(scene).render().toVectors();
    }

    @Override
    public void renderPixel(Scene scene, TraceContext ctx, int x, int y, Vector3d out) {
        new Renderer(scene).renderPixel(ctx, x, y, out);
    }
}
