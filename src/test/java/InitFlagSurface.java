import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.surface.Surface;

/**
 * Test helper in the default package: a real Surface whose static initialiser leaves a trace, the
 * positive control for {@link EvilNotASurface} (a scene that uses it must run the initialiser).
 */
public class InitFlagSurface extends Surface {

    public static final String RAN = "raytracer.test.InitFlagSurface.initialised";

    static {
        System.setProperty(RAN, "true");
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        return false;
    }
}
