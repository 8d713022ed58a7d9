import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.surface.Surface;

/**
 * Test helper in the default package: a user Surface with every kind of field the parser must
 * accept (String, long, float, boxed) or refuse (private, static, final).
 */
public class FieldZooSurface extends Surface {

    private double secret;
    public static double shared;
    public final double fixed = 1;
    public String label;
    public long big;
    public float small;
    public Integer boxed;

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        return false;
    }

    /** Reads the private field (so it is not unused). */
    public double secret() {
        return secret;
    }
}
