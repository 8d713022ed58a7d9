package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;

/**
 * The sphere's early-miss shortcut never drops a real hit: rays passing within 1e-7 of the silhouette,
 * from near and far, hit where the quadratic says; and an origin that is not finite is a miss, not a
 * hit at t = 0.
 */
class SphereGrazeTest {

    @Test
    void grazingRaysHitAtTheQuadraticsRoot() {
        Sphere s = CSGTest.sphere(0, 0, 0, 1, CSGTest.material());
        for (double far : new double[] {2, 10, 1e3}) {
            double y = 1 - 1e-7;
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(s.intersects(new Ray(new Vector3d(-far, y, 0), new Vector3d(1, 0, 0)), rec, null),
                    "grazing 1e-7 inside the silhouette from " + far);
            assertEquals(far - Math.sqrt((1 - y) * (1 + y)), rec.t, 1e-9 * far, "t from " + far);
            assertFalse(s.intersects(new Ray(new Vector3d(-far, 1 + 1e-7, 0), new Vector3d(1, 0, 0)), rec, null),
                    "1e-7 outside from " + far);
        }
    }

    @Test
    void anInfiniteOriginIsAMiss() {
        Sphere s = CSGTest.sphere(0, 0, 0, 1, CSGTest.material());
        Ray r = new Ray(new Vector3d(Double.NEGATIVE_INFINITY, 0, 0), new Vector3d(1, 0, 0));
        r.tMin = 0;
        assertFalse(s.intersects(r, new IntersectionRecord(), null));
        assertTrue(Double.isNaN(Sphere.hit(0, 0, 0, 1, Double.NEGATIVE_INFINITY, 0, 0, 1, 0, 0, 0, Double.POSITIVE_INFINITY)));
    }
}
