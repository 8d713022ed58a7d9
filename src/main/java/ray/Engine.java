package ray;

import java.util.Iterator;
import java.util.ServiceLoader;
import javax.vecmath.Vector3d;

/**
 * What readies a {@link Scene} for rays and renders it: the render plan, the acceleration structure and
 * the renderer, all of which sit above the model. The framework's own methods ({@link Scene#renderAll()},
 * {@link Scene#renderPixel}, a first {@link Scene#trace} before any render) reach it through this
 * interface, so the model imports none of them; the product's engine ({@code ray.render.RenderEngine}) is
 * found once through {@link ServiceLoader} ({@code META-INF/services/ray.Engine}).
 */
public interface Engine {

    /** Readies {@code scene} for rays with its own settings: camera frame, plan, acceleration structure. */
    void prepare(Scene scene);

    /** The whole image with the scene's own settings: {@code [x][y]}, x across, y down from the top row. */
    Vector3d[][] renderAll(Scene scene);

    /** The colour of pixel (x, y) with the scene's own settings, into {@code out}, on {@code ctx}. */
    void renderPixel(Scene scene, TraceContext ctx, int x, int y, Vector3d out);

    /** The engine on the class path (the first one {@link ServiceLoader} finds). */
    static Engine get() {
        return Engines.ENGINE;
    }
}

/** Holds the engine, loaded on first use. */
final class Engines {

    static final Engine ENGINE = load();

    private Engines() {
    }

    private static Engine load() {
        Iterator<Engine> it = ServiceLoader.load(Engine.class, Engine.class.getClassLoader()).iterator();
        if (!it.hasNext()) {
            throw new IllegalStateException("no ray.Engine on the class path (META-INF/services/ray.Engine names ray.render.RenderEngine)");
        }
        return it.next();
    }
}
