import java.util.List;
import ray.surface.Sphere;
import ray.surface.Surface;

/**
 * Issue 17 (test scenes): a student's surface whose operands are shared level after level, 60 levels
 * deep: 2^60 paths through 61 surfaces. A walk of the operands that visits each path never ends.
 */
public class SharedOperands extends Sphere {
    private final List<Surface> parts;

    public SharedOperands() {
        Surface below = new Sphere();
        for (int level = 0; level < 60; level++) {
            Surface shared = below;
            below = new Sphere() {
                @Override
                public List<Surface> operands() {
                    return List.of(shared, shared);
                }
            };
        }
        parts = below.operands();
    }

    @Override
    public List<Surface> operands() {
        return parts;
    }
}
