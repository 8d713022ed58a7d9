package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.accel.Aabb;

/**
 * The BVH build asks a built-in type for a primitive's box written into one reused Aabb; it must be
 * exactly the box {@code bounds()} allocates, whatever the scratch box held before (seeded).
 */
class PackedBoundsTest {

    private static void assertSameBox(Aabb expected, Aabb actual, String what) {
        assertEquals(expected.toString(), actual.toString(), what);
        assertEquals(expected.isFinite(), actual.isFinite(), what);
    }

    @Test
    void reusedBoxesEqualTheAllocatedOnes() {
        Random r = new Random(20261201L);
        Aabb scratch = new Aabb(-1, -1, -1, 1, 1, 1);   // stale contents must not leak into the next box
        double[] special = {Double.NaN, Double.POSITIVE_INFINITY, -0.0, 0.0, 1e300, -1e-300};
        for (int i = 0; i < 2000; i++) {
            Triangle t = new Triangle();
            t.v0 = vector(r, special);
            t.v1 = vector(r, special);
            t.v2 = vector(r, special);
            assertSameBox(t.bounds(), TriangleSet.TYPE.bounds(t, scratch), "triangle " + i + " (seed 20261201)");
            Sphere s = new Sphere();
            s.center = vector(r, special);
            s.radius = r.nextInt(10) == 0 ? -r.nextDouble() : r.nextDouble() * 10;   // a negative radius: an empty box
            assertSameBox(s.bounds(), SphereSet.TYPE.bounds(s, scratch), "sphere " + i + " (seed 20261201)");
        }
    }

    @Test
    void resetIsTheEmptyBox() {
        Aabb a = new Aabb(1, 2, 3, 4, 5, 6).reset();
        assertSameBox(new Aabb(), a, "reset");
        a.include(1, 2, 3);
        assertSameBox(new Aabb(1, 2, 3, 1, 2, 3), a, "one point");
    }

    private static Vector3d vector(Random r, double[] special) {
        double[] c = new double[3];
        for (int k = 0; k < 3; k++) {
            c[k] = r.nextInt(20) == 0 ? special[r.nextInt(special.length)] : (r.nextDouble() - 0.5) * 100;
        }
        return new Vector3d(c[0], c[1], c[2]);
    }
}
