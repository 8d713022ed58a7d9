import java.util.List;
import ray.surface.Sphere;
import ray.surface.Surface;

/** Issue 17 (test scenes): a student's surface whose operands() returns the surface itself, a cycle. */
public class SelfOperand extends Sphere {
    @Override
    public List<Surface> operands() {
        return List.of(this);
    }
}
