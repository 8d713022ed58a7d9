package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The BVH and the teaching API ({@code Sphere.intersects}, {@code Triangle.intersects}) run the same
 * kernel: for the same ray they give the same t, bit for bit, and the same record.
 */
class KernelAgreementTest {

    private static final long SEED = 0x7ab1e5L;

    private static Vector3d point(Random r, double scale) {
        return new Vector3d(scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1), scale * (2 * r.nextDouble() - 1));
    }

    private static List<Surface> randomScene(Random r) {
        List<Surface> all = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            Vector3d c = point(r, 4);
            Triangle t = new Triangle();
            t.v0 = c;
            t.v1 = new Vector3d(c.x + r.nextDouble(), c.y + r.nextDouble() - 0.5, c.z + r.nextDouble() - 0.5);
            t.v2 = new Vector3d(c.x + r.nextDouble() - 0.5, c.y + r.nextDouble(), c.z + r.nextDouble() - 0.5);
            all.add(t);
            Sphere s = new Sphere();
            s.center = point(r, 4);
            s.radius = 0.05 + 0.5 * r.nextDouble();
            all.add(s);
        }
        return all;
    }

    @Test
    void bvhAndTeachingApiGiveBitIdenticalHits() {
        Random r = new Random(SEED);
        List<Surface> all = randomScene(r);
        Scene scene = new Scene();
        Bvh bvh = Bvh.build(all, scene);
        TraceContext ctx = new TraceContext(4);
        IntersectionRecord viaBvh = new IntersectionRecord(), own = new IntersectionRecord(), best = new IntersectionRecord();
        int hits = 0;
        for (int n = 0; n < 4000; n++) {
            Vector3d o = point(r, 6), target = point(r, 3);
            target.sub(o);
            Ray ray = new Ray(o, target);
            ray.tMin = n % 2 == 0 ? 0 : r.nextDouble();
            String where = "seed " + SEED + ", ray " + n + ": " + ray;
            // the teaching API on every primitive, shrinking the span as the framework's loop does
            Ray span = new Ray(o, target);
            span.tMin = ray.tMin;
            boolean any = false;
            for (Surface s : all) {
                if (s.intersects(span, own, scene)) {
                    best.set(own);
                    span.tMax = own.t;
                    any = true;
                }
            }
            boolean got = bvh.closestHit(ray, viaBvh, ctx);
            assertEquals(any, got, where);
            assertEquals(any, bvh.anyHit(ray, ctx), where);
            if (!any) {
                continue;
            }
            hits++;
            assertEquals(Double.doubleToLongBits(best.t), Double.doubleToLongBits(viaBvh.t), where);
            assertEquals(best.location, viaBvh.location, where);
            assertEquals(best.normal, viaBvh.normal, where);
            assertEquals(best.frontFace, viaBvh.frontFace, where);
            assertEquals(best.error, viaBvh.error, where);
        }
        assertEquals(true, hits > 500, "enough rays hit something: " + hits);
    }
}
