package ray.spark;

import java.util.concurrent.locks.LockSupport;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.material.Diffuse;

/**
 * Test helper: Diffuse, pixel for pixel, that waits {@code RAYTRACER_TEST_SLOW_MICROS} microseconds per
 * shading call where that variable is set (the cluster test's executors only): a render that lasts
 * seconds of wall time without burning the shared machine's CPU, so an executor can be killed mid-render.
 */
public class SlowDiffuse extends Diffuse {

    private static final long NANOS = micros() * 1000L;

    private static long micros() {
        String v = System.getenv("RAYTRACER_TEST_SLOW_MICROS");
        return v == null ? 0 : Long.parseLong(v);
    }

    @Override
    public void shade(Ray ray, IntersectionRecord rec, Scene scene, TraceContext ctx, Vector3d out) {
        if (NANOS > 0) {
            LockSupport.parkNanos(NANOS);
        }
        super.shade(ray, rec, scene, ctx, out);
    }
}
