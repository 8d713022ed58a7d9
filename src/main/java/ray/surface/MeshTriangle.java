package ray.surface;

import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.accel.Aabb;
import ray.accel.PrimitiveSet;

/**
 * One triangle of a {@link Mesh}, as the BVH's builder sees it: its box, and the packed set
 * ({@link MeshSet}) it goes into. Made only while the BVH is built; hits name the mesh.
 */
final class MeshTriangle extends Surface {

    final Mesh mesh;
    final int index;

    MeshTriangle(Mesh mesh, int index) {
        this.mesh = mesh;
        this.index = index;
        this.material = mesh.material;
    }

    @Override
    public Aabb bounds() {
        return bounds(new Aabb());
    }

    /** The triangle's box, into {@code b} (empty or not: it only grows) and returned. */
    Aabb bounds(Aabb b) {
        for (int k = 0; k < 3; k++) {
            b.include(mesh.coordinate(index, k, 0), mesh.coordinate(index, k, 1), mesh.coordinate(index, k, 2));
        }
        return b;
    }

    @Override
    public PrimitiveSet.Type primitiveType() {
        return mesh.twoSided() ? MeshSet.TWO_SIDED : MeshSet.ONE_SIDED;
    }

    /** The same test as the packed set's, for one triangle (the BVH itself never calls it). */
    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        double[] v = new double[9];
        MeshSet.pack(mesh, index, v, 0);
        double[] k = new double[Triangle.KERNEL_SIZE + 1];
        Triangle.setupRay(ray, k, 0);
        double t = MeshSet.hit(v, 0, k, ray.tMin, ray.tMax, mesh.twoSided());
        if (t != t) {
            return false;
        }
        Triangle.fill(v, 0, k, Triangle.B0, t, record);
        mesh.finishHit(index, k[Triangle.B0], k[Triangle.B0 + 1], k[Triangle.B0 + 2], k[Triangle.B0 + 3] != 0, record);
        return true;
    }

    @Override
    public String toString() {
        return "triangle " + (index + 1) + " of " + mesh;
    }
}
