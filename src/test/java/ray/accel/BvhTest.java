package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.material.Diffuse;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The BVH must answer exactly what a loop over every surface's own {@code intersects} answers: the
 * same closest t, the same surface, and the same yes/no for shadow rays. Seeded random scenes; the
 * seed is in every failure message.
 */
class BvhTest {

    private static final long SEED = 0x5EED_B0A7L;

    /** A textbook sphere a student might write, with bounds: goes inside the tree. */
    public static class Ball extends Surface {
        public Vector3d center = new Vector3d();
        public double radius = 1;

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            Vector3d d = ray.direction;
            Vector3d f = new Vector3d(ray.origin);
            f.sub(center);
            double a = d.dot(d), b = 2 * f.dot(d), c = f.dot(f) - radius * radius;
            double disc = b * b - 4 * a * c;
            if (disc < 0) {
                return false;
            }
            double sq = Math.sqrt(disc);
            double t = (-b - sq) / (2 * a);
            if (t < ray.tMin || t > ray.tMax) {
                t = (-b + sq) / (2 * a);
                if (t < ray.tMin || t > ray.tMax) {
                    return false;
                }
            }
            record.t = t;
            record.location.set(ray.evaluate(t));
            record.normal.sub(record.location, center);
            record.normal.normalize();      // outward, not turned to the ray: the BVH does that
            record.surface = this;
            return true;
        }

        @Override
        public Aabb bounds() {
            return new Aabb(center.x - radius, center.y - radius, center.z - radius,
                    center.x + radius, center.y + radius, center.z + radius);
        }
    }

    /** An infinite plane y = height, two-sided, without bounds: tested against every ray. */
    public static class Floor extends Surface {
        public double height;

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            if (ray.direction.y == 0) {
                return false;
            }
            double t = (height - ray.origin.y) / ray.direction.y;
            if (t < ray.tMin || t > ray.tMax) {
                return false;
            }
            record.t = t;
            record.location.set(ray.evaluate(t));
            record.location.y = height;
            record.normal.set(0, 1, 0);
            record.surface = this;
            return true;
        }
    }

    /** A subclass of a built-in: must go through its own intersects, not the packed sphere path. */
    public static class TintedSphere extends Sphere {
    }

    // ---- scene and ray generators ----

    private static double logUniform(Random rnd, double lo, double hi) {
        return lo * Math.pow(hi / lo, rnd.nextDouble());
    }

    private static Vector3d uniform(Random rnd, double half) {
        return new Vector3d(half * (2 * rnd.nextDouble() - 1), half * (2 * rnd.nextDouble() - 1),
                half * (2 * rnd.nextDouble() - 1));
    }

    private static Sphere sphere(Vector3d c, double r, boolean tinted) {
        Sphere s = tinted ? new TintedSphere() : new Sphere();
        s.center = c;
        s.radius = r;
        s.material = new Diffuse();
        return s;
    }

    private static Triangle triangle(Vector3d a, Vector3d b, Vector3d c) {
        Triangle t = new Triangle();
        t.v0 = a;
        t.v1 = b;
        t.v2 = c;
        t.material = new Diffuse();
        return t;
    }

    private static List<Surface> randomScene(Random rnd, int n, boolean userSurfaces) {
        List<Surface> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            Vector3d c = uniform(rnd, 10);
            double size = logUniform(rnd, 1e-3, 8);
            int kind = rnd.nextInt(userSurfaces ? 12 : 10);
            if (kind < 4) {
                out.add(sphere(c, size, false));
            } else if (kind < 9) {
                Vector3d a = uniform(rnd, size), b = uniform(rnd, size), d = uniform(rnd, size);
                a.add(c);
                b.add(c);
                d.add(c);
                out.add(triangle(a, b, d));
            } else if (kind == 9) {
                out.add(triangle(new Vector3d(c), new Vector3d(c), uniform(rnd, size)));   // degenerate
            } else if (kind == 10) {
                Ball ball = new Ball();
                ball.center = c;
                ball.radius = size;
                ball.material = new Diffuse();
                out.add(ball);
            } else {
                out.add(sphere(c, size, true));
            }
        }
        if (userSurfaces) {
            Floor f = new Floor();
            f.height = -9.5;
            f.material = new Diffuse();
            out.add(f);
        }
        return out;
    }

    /** Rays of several kinds: random, aimed at a primitive, axis-aligned through box planes, short spans. */
    private static Ray randomRay(Random rnd, List<Surface> surfaces, Vector3d centre, double spread) {
        Vector3d o = uniform(rnd, spread);
        o.add(centre);
        Vector3d d;
        int kind = rnd.nextInt(4);
        if (kind == 0 || surfaces.isEmpty()) {
            d = new Vector3d(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
        } else {
            Aabb b = surfaces.get(rnd.nextInt(surfaces.size())).bounds();
            if (!b.isFinite()) {
                b = new Aabb(-1, -1, -1, 1, 1, 1);
            }
            Vector3d target = new Vector3d(b.minX + rnd.nextDouble() * (b.maxX - b.minX),
                    b.minY + rnd.nextDouble() * (b.maxY - b.minY), b.minZ + rnd.nextDouble() * (b.maxZ - b.minZ));
            d = new Vector3d(target);
            d.sub(o);
            if (kind == 2) {
                // axis-aligned, starting on a face plane of the box (rounded to float as the nodes are):
                // the slab test sees 0 * infinity there
                int axis = rnd.nextInt(3);
                double[] dd = {0, 0, 0};
                dd[axis] = rnd.nextBoolean() ? 1 : -1;
                d = new Vector3d(dd);
                if (axis != 0) o.x = rnd.nextBoolean() ? (float) b.minX : target.x;
                if (axis != 1) o.y = rnd.nextBoolean() ? (float) b.minY : target.y;
                if (axis != 2) o.z = rnd.nextBoolean() ? (float) b.maxZ : target.z;
            }
            d.scale(logUniform(rnd, 1e-2, 1e2));     // unnormalised
        }
        Ray r = new Ray(o, d);
        if (rnd.nextInt(4) == 0) {
            r.tMin = rnd.nextDouble() * 0.5;
            r.tMax = r.tMin + rnd.nextDouble();
        }
        return r;
    }

    // ---- the reference: a loop over Surface.intersects ----

    /** The closest hit by brute force (narrowing tMax), or null. */
    private static IntersectionRecord bruteClosest(List<Surface> surfaces, Ray ray, Scene scene) {
        Ray r = copy(ray);
        IntersectionRecord tmp = new IntersectionRecord(), best = null;
        for (Surface s : surfaces) {
            if (s.intersects(r, tmp, scene)) {
                best = new IntersectionRecord();
                best.set(tmp);
                r.tMax = tmp.t;
            }
        }
        return best;
    }

    private static boolean bruteAny(List<Surface> surfaces, Ray ray, Scene scene) {
        for (Surface s : surfaces) {
            if (s.intersects(copy(ray), new IntersectionRecord(), scene)) {
                return true;
            }
        }
        return false;
    }

    private static Ray copy(Ray ray) {
        Ray r = new Ray(ray.origin, ray.direction);
        r.tMin = ray.tMin;
        r.tMax = ray.tMax;
        return r;
    }

    private static Scene sceneOf(List<Surface> surfaces) {
        Scene s = new Scene();
        s.camera = new Camera();
        s.surfaces = surfaces;
        return s;
    }

    /** Compares the BVH with brute force on {@code rays} random rays; returns the number of hits seen. */
    private static int compare(List<Surface> surfaces, Random rnd, int rays, String label) {
        return compare(surfaces, rnd, rays, label, new Vector3d(), 15);
    }

    /** As above, with ray origins within {@code spread} of {@code centre}. */
    private static int compare(List<Surface> surfaces, Random rnd, int rays, String label, Vector3d centre, double spread) {
        Scene scene = sceneOf(surfaces);
        Bvh bvh = Bvh.build(surfaces, scene);
        TraceContext ctx = new TraceContext(4);
        int hits = 0;
        for (int i = 0; i < rays; i++) {
            Ray ray = randomRay(rnd, surfaces, centre, spread);
            String where = label + ", ray " + i + ": " + ray;
            IntersectionRecord expected = bruteClosest(surfaces, ray, scene);
            IntersectionRecord rec = new IntersectionRecord();
            Ray probe = copy(ray);
            boolean hit = bvh.closestHit(probe, rec, ctx);
            assertEquals(ray.tMax, probe.tMax, where + ": closestHit must leave the ray's span as it was");
            if (expected == null) {
                assertFalse(hit, where + ": BVH hit " + rec + ", brute force missed");
            } else {
                hits++;
                assertTrue(hit, where + ": BVH missed, brute force hit " + expected);
                double tol = 1e-12 * Math.abs(expected.t);
                assertEquals(expected.t, rec.t, tol, where + ": closest t");
                if (rec.surface != expected.surface) {
                    // only an exact tie may pick another surface: that surface must hit at the same t
                    IntersectionRecord other = new IntersectionRecord();
                    assertTrue(rec.surface.intersects(copy(ray), other, scene) && Math.abs(other.t - expected.t) <= tol,
                            where + ": BVH chose " + rec.surface + " at " + rec.t + ", brute force " + expected.surface);
                } else {
                    double scale = 1e-9 * Math.max(1, expected.location.length());
                    assertTrue(close(expected.location, rec.location, scale), where + ": location " + rec.location
                            + " vs " + expected.location);
                }
                assertEquals(1, rec.normal.length(), 1e-9, where + ": unit normal");
                assertTrue(rec.normal.dot(ray.direction) <= 0, where + ": normal faces the ray");
            }
            boolean any = bruteAny(surfaces, ray, scene);
            assertEquals(any, bvh.anyHit(copy(ray), ctx), where + ": anyHit");
            // the occluder cache: the same answers with a slot, whatever the slot remembers from earlier
            // rays; asked again, a hit comes from the remembered leaf run; shortened to end before its
            // closest hit, the remembered run must not answer for it
            int slot = i % 3;
            assertEquals(any, bvh.anyHit(copy(ray), ctx, slot), where + ": anyHit, cache slot " + slot);
            assertEquals(any, bvh.anyHit(copy(ray), ctx, slot), where + ": anyHit again, cache slot " + slot);
            if (expected != null) {
                Ray shorter = copy(ray);
                shorter.tMax = expected.t * (1 - 1e-6);
                assertEquals(bruteAny(surfaces, shorter, scene), bvh.anyHit(shorter, ctx, slot), where + ": anyHit short of the hit, slot " + slot);
            }
        }
        return hits;
    }

    private static boolean close(Vector3d a, Vector3d b, double tol) {
        return Math.abs(a.x - b.x) <= tol && Math.abs(a.y - b.y) <= tol && Math.abs(a.z - b.z) <= tol;
    }

    // ---- the tests ----

    @Test
    void randomScenesMatchBruteForce() {
        int hits = 0, rays = 0;
        for (int k = 0; k < 30; k++) {
            long seed = SEED + k;
            Random rnd = new Random(seed);
            int n = 1 + rnd.nextInt(k < 10 ? 20 : 400);
            List<Surface> surfaces = randomScene(rnd, n, false);
            hits += compare(surfaces, rnd, 400, "seed " + seed + " (" + n + " surfaces)");
            rays += 400;
        }
        assertTrue(hits > rays / 4, "the rays must actually hit things: " + hits + " hits of " + rays);
    }

    @Test
    void randomScenesWithUserSurfacesMatchBruteForce() {
        for (int k = 0; k < 10; k++) {
            long seed = SEED + 1000 + k;
            Random rnd = new Random(seed);
            List<Surface> surfaces = randomScene(rnd, 1 + rnd.nextInt(200), true);
            compare(surfaces, rnd, 400, "seed " + seed + " with user surfaces");
        }
    }

    /** Every primitive has the same centroid: the SAH cannot split, the builder must split by count. */
    @Test
    void identicalCentroidsMatchBruteForce() {
        long seed = SEED + 2000;
        Random rnd = new Random(seed);
        Vector3d c = new Vector3d(1, -2, 0.5);
        List<Surface> surfaces = new ArrayList<>();
        for (int i = 0; i < 60; i++) {
            surfaces.add(sphere(new Vector3d(c), 0.01 + 0.01 * i, false));
        }
        for (int i = 0; i < 60; i++) {
            // a triangle with centroid exactly c: vertices c + p, c + q, c - p - q
            Vector3d p = uniform(rnd, 3), q = uniform(rnd, 3);
            Vector3d a = new Vector3d(c), b = new Vector3d(c), d = new Vector3d(c);
            a.add(p);
            b.add(q);
            d.sub(p);
            d.sub(q);
            surfaces.add(triangle(a, b, d));
        }
        Bvh bvh = Bvh.build(surfaces, sceneOf(surfaces));
        assertEquals(120, bvh.primitiveCount(), "seed " + seed);
        assertTrue(bvh.nodeCount() > 1, "seed " + seed + ": more than one leaf for 120 primitives");
        // rays from all around and from inside the cluster, so each primitive is the closest hit somewhere
        int hits = compare(surfaces, rnd, 2000, "seed " + seed + " identical centroids", new Vector3d(), 15)
                + compare(surfaces, rnd, 2000, "seed " + seed + " identical centroids, from inside", c, 2);
        assertTrue(hits > 2000, "seed " + seed + ": only " + hits + " hits");
    }

    @Test
    void emptySceneNeverHits() {
        List<Surface> none = new ArrayList<>();
        Bvh bvh = Bvh.build(none, sceneOf(none));
        TraceContext ctx = new TraceContext(2);
        Ray r = new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1));
        IntersectionRecord rec = new IntersectionRecord();
        rec.t = 42;
        assertFalse(bvh.closestHit(r, rec, ctx));
        assertEquals(42, rec.t);
        assertFalse(bvh.anyHit(r, ctx));
        assertEquals(0, bvh.primitiveCount());
    }

    @Test
    void singlePrimitiveHitsAndMisses() {
        Sphere s = sphere(new Vector3d(0, 0, 0), 1, false);
        List<Surface> one = List.of(s);
        Bvh bvh = Bvh.build(one, sceneOf(one));
        TraceContext ctx = new TraceContext(2);
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(bvh.closestHit(new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1)), rec, ctx));
        assertEquals(4, rec.t, 1e-12);
        assertSame(s, rec.surface);
        assertFalse(bvh.closestHit(new Ray(new Vector3d(2, 0, 5), new Vector3d(0, 0, -1)), new IntersectionRecord(), ctx));
        assertTrue(bvh.anyHit(new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1)), ctx));
        assertFalse(bvh.anyHit(new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, 1)), ctx));
        compare(one, new Random(SEED + 3000), 500, "seed " + (SEED + 3000) + " single sphere");
    }

    /** Zero-area triangles are left out of the tree and never hit, like Triangle.intersects. */
    @Test
    void degenerateTrianglesAreLeftOut() {
        List<Surface> list = List.of(
                triangle(new Vector3d(0, 0, 0), new Vector3d(1, 1, 1), new Vector3d(2, 2, 2)),
                triangle(new Vector3d(0, 0, 0), new Vector3d(0, 0, 0), new Vector3d(0, 1, 0)));
        Bvh bvh = Bvh.build(list, sceneOf(list));
        assertEquals(0, bvh.primitiveCount());
        assertFalse(bvh.anyHit(new Ray(new Vector3d(0, 0.5, 5), new Vector3d(0, 0, -1)), new TraceContext(2)));
    }

    /** A user Surface with bounds() (inside the tree) and one without (tested always) are both hit. */
    @Test
    void userSurfacesWithAndWithoutBoundsAreHit() {
        Ball ball = new Ball();
        ball.center = new Vector3d(3, 0, 0);
        ball.material = new Diffuse();
        Floor floor = new Floor();
        floor.height = -2;
        floor.material = new Diffuse();
        List<Surface> list = new ArrayList<>(List.of(ball, floor, sphere(new Vector3d(-3, 0, 0), 1, false)));
        Scene scene = sceneOf(list);
        Bvh bvh = Bvh.build(list, scene);
        TraceContext ctx = new TraceContext(2);
        assertEquals(3, bvh.primitiveCount());

        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(bvh.closestHit(new Ray(new Vector3d(3, 0, 5), new Vector3d(0, 0, -1)), rec, ctx));
        assertSame(ball, rec.surface);
        assertEquals(4, rec.t, 1e-12);
        assertTrue(bvh.closestHit(new Ray(new Vector3d(0, 5, 0), new Vector3d(0, -1, 0)), rec, ctx));
        assertSame(floor, rec.surface);
        assertEquals(7, rec.t, 1e-12);
        // the ball in front of the floor: the ball is closer
        assertTrue(bvh.closestHit(new Ray(new Vector3d(3, 5, 0), new Vector3d(0, -1, 0)), rec, ctx));
        assertSame(ball, rec.surface);
        assertEquals(4, rec.t, 1e-12);
        // from inside the ball, looking out along -y: the normal the student wrote (outward, -y at the
        // bottom) points along the ray, so it is turned to face it
        assertTrue(bvh.closestHit(new Ray(new Vector3d(3, 0, 0), new Vector3d(0, -1, 0)), rec, ctx));
        assertSame(ball, rec.surface);
        assertEquals(1, rec.normal.y, 1e-12);
        assertFalse(rec.frontFace);
        assertTrue(bvh.anyHit(new Ray(new Vector3d(3, 5, 0), new Vector3d(0, -1, 0)), ctx));
        Ray shortRay = new Ray(new Vector3d(0, 5, 0), new Vector3d(0, -1, 0));
        shortRay.tMax = 6.5;
        assertFalse(bvh.anyHit(shortRay, ctx), "floor beyond tMax");
    }
}
