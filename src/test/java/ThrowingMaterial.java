import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;

/** Test helper in the default package: a user's material whose shade() fails with a two-line message. */
public class ThrowingMaterial extends Material {

    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        throw new UnsupportedOperationException("student code\nnot finished");
    }
}
