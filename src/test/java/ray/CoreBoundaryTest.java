package ray;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.light.LightSample;
import ray.parse.Parser;

/**
 * The core package's limits, each at its boundary: the camera's open ranges (yFOV in (0, 180), aspect
 * positive, up not parallel to the view relative to its own length), the default aspect when the scene
 * has a size and not when it has none, a per-thread context deeper than it was made for, the counting of
 * user rays, and the side a ray tangent to the surface leaves on.
 */
class CoreBoundaryTest {

    private static Camera camera(double yFOV, double aspect, Vector3d up) {
        Camera c = new Camera();     // eye (0, 0, 5) looking at the origin
        c.yFOV = yFOV;
        c.aspect = aspect;
        c.up = up;
        return c;
    }

    @Test
    void cameraRangesAreOpenAtTheirEnds() {
        Vector3d y = new Vector3d(0, 1, 0);
        for (double bad : new double[] {0, 180, -1e-9, 180 + 1e-9, Double.NaN}) {
            assertThrows(IllegalArgumentException.class, () -> camera(bad, Double.NaN, y).init(), "yFOV " + bad);
        }
        assertDoesNotThrow(() -> camera(1e-9, Double.NaN, y).init());
        assertDoesNotThrow(() -> camera(180 - 1e-9, Double.NaN, y).init());
        for (double bad : new double[] {0, -1, Double.POSITIVE_INFINITY}) {
            assertThrows(IllegalArgumentException.class, () -> camera(45, bad, y).init(), "aspect " + bad);
        }
        assertDoesNotThrow(() -> camera(45, 1e-300, y).init());
    }

    /**
     * "Parallel" is relative to up's length: a tiny up at a right angle to the view is fine, a huge one
     * tilted by 1e-14 of its length is parallel (its cross product with w is 1e-8, far above 1e-12 in
     * absolute terms).
     */
    @Test
    void upIsParallelRelativeToItsOwnLength() {
        assertDoesNotThrow(() -> camera(45, Double.NaN, new Vector3d(0, 1e-20, 0)).init(), "tiny perpendicular up");
        Camera tiny = camera(45, Double.NaN, new Vector3d(0, 1e-20, 0));
        tiny.init();
        assertEquals(1, tiny.v.y, 1e-15, "v follows the tiny up");
        assertThrows(IllegalArgumentException.class, () -> camera(45, Double.NaN, new Vector3d(1e-8, 0, 1e6)).init(),
                "huge up within 1e-14 of the view direction");
        assertDoesNotThrow(() -> camera(45, Double.NaN, new Vector3d(1e-4, 0, 1e6)).init(), "1e-10 of it is not parallel");
    }

    @Test
    void defaultAspectIsWidthOverHeightOnlyWhenTheSceneHasASize() {
        Scene s = new Scene();
        s.camera = new Camera();
        s.width = 40;
        s.height = 16;
        s.prepare();
        assertEquals(2.5, s.camera.aspect, 0);
        for (int[] size : new int[][] {{0, 16}, {40, 0}, {0, 0}}) {
            Scene none = new Scene();
            none.camera = new Camera();
            none.width = size[0];
            none.height = size[1];
            assertDoesNotThrow(none::prepare, "a scene built in code with size " + size[0] + " x " + size[1]);
            assertTrue(Double.isNaN(none.camera.aspect), "no size, no aspect: " + none.camera.aspect);
        }
    }

    /**
     * A context made for MaxDepth d holds d + 2 levels without allocating; deeper levels are made on
     * demand, distinct, and the levels already handed out stay the same objects (a caller may hold them).
     */
    @Test
    void traceContextGrowsPastItsDepthKeepingWhatItHandedOut() {
        TraceContext c = new TraceContext(1);
        List<Object> seen = new ArrayList<>();
        for (int d = 0; d < 3; d++) {
            seen.add(c.ray(d));
            seen.add(c.record(d));
            seen.add(c.color(d));
        }
        Object[] deep = {c.ray(3), c.record(4), c.color(5), c.ray(40), c.record(41), c.color(42)};
        for (Object o : deep) {
            assertTrue(o != null, "deeper levels exist");
            seen.add(o);
        }
        IdentityHashMap<Object, Boolean> distinct = new IdentityHashMap<>();
        for (Object o : seen) {
            distinct.put(o, true);
        }
        assertEquals(seen.size(), distinct.size(), "every level has its own objects");
        for (int d = 0; d < 3; d++) {
            assertSame(seen.get(3 * d), c.ray(d), "ray " + d + " kept");
            assertSame(seen.get(3 * d + 1), c.record(d), "record " + d + " kept");
            assertSame(seen.get(3 * d + 2), c.color(d), "color " + d + " kept");
        }
        assertSame(deep[0], c.ray(3));
        assertSame(deep[3], c.ray(40));
        assertSame(deep[4], c.record(41));
        assertSame(deep[5], c.color(42));
        // every level up to the deepest asked for is there, in each of the three kinds
        for (int d = 0; d <= 42; d++) {
            assertTrue(c.ray(d) != null && c.record(d) != null && c.color(d) != null, "level " + d);
        }
    }

    /**
     * The allocation-free promise: a context made for MaxDepth 10 hands out its 12 levels without
     * allocating (they are made with it, not on first use). Measured on a second context, made before
     * the measurement, after a first one has run the same calls (loading and linking).
     */
    @Test
    void traceContextMadeForItsDepthAllocatesNothingWithinIt() {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        if (!(mx instanceof com.sun.management.ThreadMXBean) || !((com.sun.management.ThreadMXBean) mx).isThreadAllocatedMemorySupported()) {
            return;   // not measurable on this JVM
        }
        com.sun.management.ThreadMXBean sun = (com.sun.management.ThreadMXBean) mx;
        long id = Thread.currentThread().getId();
        long sink = touchLevels(new TraceContext(10));
        TraceContext fresh = new TraceContext(10);
        long before = sun.getThreadAllocatedBytes(id);
        sink += touchLevels(fresh);
        long used = sun.getThreadAllocatedBytes(id) - before;
        assertTrue(used < 512, "levels 0..11 of a fresh MaxDepth-10 context allocated " + used + " bytes (" + sink + ")");
    }

    private static long touchLevels(TraceContext c) {
        long sink = 0;
        for (int d = 0; d < 12; d++) {
            sink += System.identityHashCode(c.ray(d)) + System.identityHashCode(c.record(d)) + System.identityHashCode(c.color(d));
        }
        return sink;
    }

    /** Each kind of level, asked for exactly one past what the context holds, grows it. */
    @Test
    void eachKindGrowsAtItsLength() {
        assertTrue(new TraceContext(1).ray(3) != null);
        assertTrue(new TraceContext(1).record(3) != null);
        assertTrue(new TraceContext(1).color(3) != null);
    }

    @Test
    void currentContextIsOnePerThreadAndKept() throws Exception {
        Scene s = new Scene();
        TraceContext mine = TraceContext.current(s);
        assertSame(mine, TraceContext.current(s), "the same context on the second call");
        TraceContext[] other = new TraceContext[2];
        Thread t = new Thread(() -> {   // a new thread: its first call makes the context, the second finds it
            other[0] = TraceContext.current(s);
            other[1] = TraceContext.current(s);
        });
        t.start();
        t.join();
        assertNotSame(mine, other[0], "another thread, another context");
        assertSame(other[0], other[1], "kept for that thread");
    }

    /** prepare() validates the camera and recomputes its frame: a camera changed after parsing takes effect. */
    @Test
    void prepareValidatesAndRecomputesTheCamera() throws Exception {
        Scene s = Parser.parse("Width 4\nHeight 4\nCamera Camera\nVector3d eye [0 0 5]\n", "cam.txt", new ArrayList<>());
        s.prepare();
        assertEquals(1, s.camera.w.z, 1e-15);
        s.camera.eye = new Vector3d(5, 0, 0);
        s.prepare();
        assertEquals(1, s.camera.w.x, 1e-15, "w follows the moved eye");
        s.camera.yFOV = 0;
        assertThrows(IllegalArgumentException.class, s::prepare, "yFOV 0 set after parsing");
    }

    /** Scene.intersect is a user ray, occluded(Ray) and occluded(record, sample) shadow rays: each counted once. */
    @Test
    void userAndShadowQueriesAreCountedOnTheCallingThread() throws Exception {
        Scene s = Parser.parse("Width 4\nHeight 4\nCamera Camera\nMaterial Diffuse d\nSurface Sphere\nref material d\n",
                "count.txt", new ArrayList<>());
        RayStats stats = TraceContext.current(s).stats;
        long user = stats.get(RayKind.USER), shadow = stats.get(RayKind.SHADOW), total = stats.total();
        Ray r = new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1));
        IntersectionRecord rec = new IntersectionRecord();
        assertTrue(s.intersect(r, rec));
        assertEquals(4, rec.t, 1e-12);
        assertEquals(user + 1, stats.get(RayKind.USER));
        assertTrue(s.occluded(r));
        assertEquals(shadow + 1, stats.get(RayKind.SHADOW));
        LightSample sample = new LightSample();
        sample.position.set(0, 0, -5);
        assertTrue(s.occluded(rec, sample), "from the front of the sphere to behind it");
        assertEquals(shadow + 2, stats.get(RayKind.SHADOW));
        assertEquals(total + 3, stats.total());
    }

    @Test
    void statsAddEveryKindAndInvalidSamples() {
        RayStats a = new RayStats(), b = new RayStats();
        a.count(RayKind.CAMERA);
        b.count(RayKind.CAMERA);
        b.count(RayKind.CAMERA);
        b.count(RayKind.MIRROR);
        a.invalidSamples = 1;
        b.invalidSamples = 5;
        a.add(b);
        assertEquals(3, a.get(RayKind.CAMERA));
        assertEquals(1, a.get(RayKind.MIRROR));
        assertEquals(6, a.invalidSamples);
        assertEquals(4, a.total());
        assertEquals(2, b.get(RayKind.CAMERA), "the added one is unchanged");
    }

    @Test
    void groupedCountsHaveCommasEveryThreeDigits() {
        long[] n = {0, 7, 999, 1000, 12345, 999999, 1000000, 1234567890L, -1234, Long.MAX_VALUE};
        for (long x : n) {
            assertEquals(String.format(java.util.Locale.ENGLISH, "%,d", x), RayStats.grouped(x), "n = " + x);
        }
    }

    /** A ray tangent to the surface (d . n = 0) leaves from the normal's side, the side the ray came from. */
    @Test
    void aTangentRayLeavesOnTheNormalsSide() {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(1, 2, 3);
        rec.normal.set(0, 0, 1);
        rec.error = 1e-6;
        Ray out = new Ray();
        rec.spawnRay(1, 0, 0, out);
        assertEquals(3 + 1e-6, out.origin.z, 1e-18, "tangent: on the normal's side");
        rec.spawnRay(1, 0, -1e-3, out);
        assertEquals(3 - 1e-6, out.origin.z, 1e-18, "into the surface: on the other side");
    }
}
