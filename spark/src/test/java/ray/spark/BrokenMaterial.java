package ray.spark;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;

/** Test helper: a user's material whose shade() fails the same way every time (a bug no retry mends). */
public class BrokenMaterial extends Material {

    @Override
    public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
        throw new IllegalStateException("student code not finished");
    }
}
