package ray;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * What a spawned ray is for: a shadow ray from {@link IntersectionRecord#spawnRayTo} starts just off the
 * surface on the target's side and runs to just short of the target (t = 1 is the target, tMax a hair
 * below 1); a ray from {@link IntersectionRecord#spawnRay} keeps its direction and starts on the side it
 * leaves to. Seeded random hit points, normals and targets; the seed and case are in each message.
 */
class SpawnedRayReachesTargetTest {

    private static final long SEED = 0x5eed11L;

    private static Vector3d unit(Random r) {
        Vector3d v = new Vector3d(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
        v.normalize();
        return v;
    }

    private static IntersectionRecord hit(Random r, double scale, double error) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1));
        rec.normal.set(unit(r));
        rec.error = error;
        return rec;
    }

    /** How far the origin sits off the surface along the normal (signed: + on the normal's side). */
    private static double offsetAlongNormal(IntersectionRecord rec, Ray ray) {
        Vector3d d = new Vector3d(ray.origin);
        d.sub(rec.location);
        return d.dot(rec.normal);
    }

    @Test
    void shadowRayRunsFromJustOffTheSurfaceToJustShortOfItsTarget() {
        Random r = new Random(SEED);
        for (int i = 0; i < 2000; i++) {
            double scale = Math.pow(10, r.nextInt(7) - 3);
            double error = i % 3 == 0 ? 0 : scale * 1e-11;   // 0: the record's fallback bound
            IntersectionRecord rec = hit(r, scale, error);
            Vector3d target = new Vector3d(unit(r));
            target.scale(scale * (0.01 + 5 * r.nextDouble()));
            target.add(rec.location);
            String what = "seed " + SEED + " case " + i + " from " + rec.location + " n " + rec.normal + " to " + target;

            Ray ray = rec.spawnRayTo(target);
            // t = 1 is the target itself
            Vector3d end = ray.evaluate(1);
            double tol = 1e-12 * Math.max(scale, target.length());
            assertEquals(target.x, end.x, tol, what);
            assertEquals(target.y, end.y, tol, what);
            assertEquals(target.z, end.z, tol, what);
            // the span is (0, just under 1): the ray stops short of the target by a tiny fraction only
            assertEquals(0, ray.tMin, what);
            assertTrue(ray.tMax < 1 && ray.tMax > 1 - 1e-6, "tMax " + ray.tMax + " " + what);
            double m = Math.max(Math.abs(target.x), Math.max(Math.abs(target.y), Math.abs(target.z)));
            double expectedEnd = Math.max(IntersectionRecord.SHADOW_END,
                    IntersectionRecord.TARGET_ERROR * m / ray.direction.length());
            assertEquals(1 - expectedEnd, ray.tMax, 1e-15, "stops short by the documented margin " + what);

            // off the surface, toward the target's side, by about the error bound (never on the surface)
            Vector3d toTarget = new Vector3d(target);
            toTarget.sub(rec.location);
            double side = Math.signum(toTarget.dot(rec.normal));
            double off = offsetAlongNormal(rec, ray);
            double bound = error > 0 ? error : 1e-9 * Math.max(Math.abs(rec.location.x),
                    Math.max(Math.abs(rec.location.y), Math.abs(rec.location.z)));
            double l1 = Math.abs(rec.normal.x) + Math.abs(rec.normal.y) + Math.abs(rec.normal.z);
            if (side != 0) {
                assertEquals(side * bound * l1, off, 1e-3 * bound * l1, "offset along the normal " + what);
            }
        }
    }

    @Test
    void spawnedRayKeepsItsDirectionAndLeavesOnItsSide() {
        Random r = new Random(SEED + 1);
        for (int i = 0; i < 2000; i++) {
            double scale = Math.pow(10, r.nextInt(7) - 3);
            IntersectionRecord rec = hit(r, scale, scale * 1e-11);
            Vector3d dir = unit(r);
            String what = "seed " + (SEED + 1) + " case " + i + " n " + rec.normal + " dir " + dir;
            Ray ray = rec.spawnRay(dir);
            assertEquals(dir, ray.direction, what);
            assertEquals(0, ray.tMin, what);
            assertEquals(Double.POSITIVE_INFINITY, ray.tMax, what);
            double cos = dir.dot(rec.normal);
            double off = offsetAlongNormal(rec, ray);
            double l1 = Math.abs(rec.normal.x) + Math.abs(rec.normal.y) + Math.abs(rec.normal.z);
            if (cos != 0) {
                assertEquals(Math.signum(cos) * rec.error * l1, off, 1e-3 * rec.error * l1, what);
            }
        }
    }

    /** The allocation-free form fills a ray the caller reuses; its depth is the caller's and is kept. */
    @Test
    void allocationFreeFormsOverwriteEverythingButTheDepth() {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(1, 2, 3);
        rec.normal.set(0, 0, 1);
        rec.error = 1e-10;
        Ray reused = new Ray(new Vector3d(9, 9, 9), new Vector3d(1, 0, 0));
        reused.tMin = 5;
        reused.tMax = 6;
        reused.depth = 4;
        rec.spawnRayTo(1, 2, 7, reused);
        assertEquals(4, reused.depth);
        assertEquals(0, reused.tMin);
        assertEquals(1, reused.origin.x, 0);
        assertEquals(2, reused.origin.y, 0);
        assertEquals(3 + 1e-10, reused.origin.z, 1e-16);
        assertEquals(4 - 1e-10, reused.direction.z, 1e-15);
        rec.spawnRay(0, 0, -1, reused);
        assertEquals(4, reused.depth);
        assertEquals(3 - 1e-10, reused.origin.z, 1e-16, "a ray into the surface starts below it");
        assertEquals(Double.POSITIVE_INFINITY, reused.tMax);
    }

    @Test
    void setCopiesEveryField() {
        IntersectionRecord a = new IntersectionRecord();
        a.location.set(1, 2, 3);
        a.normal.set(0, 1, 0);
        a.t = 7;
        a.frontFace = false;
        a.error = 1e-9;
        a.surface = new ray.surface.Sphere();
        IntersectionRecord b = new IntersectionRecord();
        b.set(a);
        assertEquals(a.location, b.location);
        assertEquals(a.normal, b.normal);
        assertEquals(7, b.t);
        assertEquals(false, b.frontFace);
        assertEquals(1e-9, b.error);
        assertTrue(a.surface == b.surface);
        assertTrue(a.location != b.location, "copies, not shares, the vectors");
    }
}
