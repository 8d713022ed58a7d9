package ray.render;

import javax.vecmath.Vector3d;
import ray.Engine;
import ray.RayKind;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Bvh;
import ray.light.PointLight;
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
            // a shadow ray toward each point light at most per camera ray's hit: the light buffers' measure
            scene.useAccelerator(Bvh.build(scene.surfaces, scene, pointLights(scene), plan.bound().get(RayKind.CAMERA)));
        }
    }

    /**
     * The positions of the scene's point lights (x, y, z each), for the BVH's light buffers: a shadow ray
     * toward one of them tests only the leaves seen from it in the ray's direction (ray.accel.LightBuffer;
     * the BVH checks that a ray ends at the position before it uses the buffer, so a subclass that moves
     * its samples is answered by the tree).
     */
    static double[] pointLights(Scene scene) {
        int n = 0;
        for (int i = 0; i < scene.lights.size(); i++) {   // indexed: no iterator
            if (scene.lights.get(i) instanceof PointLight) {
                n++;
            }
        }
        double[] xyz = new double[3 * n];
        for (int i = 0, k = 0; i < scene.lights.size(); i++) {
            if (scene.lights.get(i) instanceof PointLight) {
                Vector3d p = ((PointLight) scene.lights.get(i)).position;
                xyz[k++] = p.x;
                xyz[k++] = p.y;
                xyz[k++] = p.z;
            }
        }
        return xyz;
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
