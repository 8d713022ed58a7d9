package ray.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Scene;
import ray.TraceContext;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Sampler;

/**
 * What one {@link AreaLight} sample is, exactly: sample k = i + n j (grid sampler, outside a render: the
 * cell's centre) is the point position + s edge1 + t edge2 with s = (i + 1/2)/n - 1/2, t = (j + 1/2)/n - 1/2,
 * of intensity I / (n^2 r^2); no light when the sample sits on the point or I / (n^2 r^2) is no number.
 * The edges here are oblique (every component non-zero), so each coordinate's formula shows.
 */
class AreaLightContractTest {

    private static Scene empty() {
        return LightSampleContractTest.empty();
    }

    private static IntersectionRecord at(double x, double y, double z) {
        return LightSampleContractTest.at(x, y, z);
    }

    private static AreaLight oblique(int n) {
        AreaLight l = new AreaLight();
        l.position = new Vector3d(0.5, 4, -1);
        l.edge1 = new Vector3d(2, 0.25, 0.5);
        l.edge2 = new Vector3d(-0.75, 0.5, 1.5);
        l.intensity = new Vector3d(9, 18, 27);
        l.samples = n;
        l.init();
        return l;
    }

    @Test
    void eachSampleIsItsCellCentreWithItsShareOfTheIntensity() {
        int n = 3;
        AreaLight l = oblique(n);
        IntersectionRecord rec = at(0.25, -1, 0.75);
        LightSample out = new LightSample();
        out.shadowTested = true;
        for (int k = 0; k < n * n; k++) {
            double s = (k % n + 0.5) / n - 0.5, t = (k / n + 0.5) / n - 0.5;
            Vector3d p = new Vector3d(0.5 + 2 * s - 0.75 * t, 4 + 0.25 * s + 0.5 * t, -1 + 0.5 * s + 1.5 * t);
            String what = "sample " + k + " at " + out.position + ", expected " + p;
            assertTrue(l.sample(rec, empty(), k, out), what);
            assertEquals(p.x, out.position.x, 1e-14, what);
            assertEquals(p.y, out.position.y, 1e-14, what);
            assertEquals(p.z, out.position.z, 1e-14, what);
            Vector3d d = new Vector3d(p.x - 0.25, p.y + 1, p.z - 0.75);
            double r = d.length();
            assertEquals(r, out.distance, 1e-13, what);
            d.scale(1 / r);
            assertTrue(d.epsilonEquals(out.direction, 1e-15), what + ": direction " + out.direction);
            double k2 = 1.0 / (n * n * r * r);
            assertTrue(new Vector3d(9 * k2, 18 * k2, 27 * k2).epsilonEquals(out.intensity, 1e-14), what + ": " + out.intensity);
            assertFalse(out.shadowTested, "each sample needs its own shadow ray");
        }
        assertEquals(n * n, l.sampleCount());
        assertEquals(n * n, l.shadowRaysPerPoint());
    }

    @Test
    void noLightOnTheSampleOrBeyondReach() {
        AreaLight tiny = new AreaLight();
        tiny.position = new Vector3d(1, 2, 3);
        tiny.edge1 = new Vector3d();
        tiny.edge2 = new Vector3d();
        tiny.intensity = new Vector3d(1e300, 1e300, 1e300);
        tiny.samples = 1;
        tiny.init();
        LightSample out = new LightSample();
        assertFalse(tiny.sample(at(1, 2, 3), empty(), 0, out), "the sample sits on the point");
        assertFalse(tiny.sample(at(1, 2, 3 + 1e-6), empty(), 0, out), "I / r^2 overflows");
        assertFalse(tiny.sample(at(1, 2, 1e200), empty(), 0, out), "r^2 overflows");
        assertTrue(tiny.sample(at(1, 2, 3 + 1e10), empty(), 0, out), "far, finite");
        assertEquals(1e300 / 1e20, out.intensity.x, 1e280);
    }

    @Test
    void darkOnlyWhenEveryChannelIsZero() {
        AreaLight l = oblique(2);
        assertFalse(l.isDark());
        for (Vector3d one : new Vector3d[] {new Vector3d(1, 0, 0), new Vector3d(0, 1, 0), new Vector3d(0, 0, 1)}) {
            l.intensity = one;
            assertFalse(l.isDark(), "one channel lit: " + one);
        }
        l.intensity = new Vector3d();
        assertTrue(l.isDark());
    }

    /**
     * The framework's getIntensity is the sum of the unshadowed samples: with nothing in the way, all n^2
     * of them; with a small sphere hiding exactly the middle sample, the other eight.
     */
    @Test
    void getIntensityIsTheSumOfTheUnshadowedSamples() throws SceneFormatException {
        String light = "Light AreaLight\nVector3d position [0 4 0]\nVector3d edge1 [3 0 0]\nVector3d edge2 [0 0 3]\n"
                + "Vector3d intensity [9 18 27]\nint samples 3\n";
        Scene open = Parser.parse("Width 4\nHeight 4\nCamera Camera\n" + light, "open.txt", new ArrayList<>());
        // samples sit at x, z in {-1, 0, 1} at height 4; the shading point is the origin. A sphere of
        // radius 0.3 at (0, 2, 0) blocks the middle sample (k = 4) only: the shadow rays to the others pass
        // its centre at a distance of sqrt(4 / 17) = 0.485 or more.
        Scene blocked = Parser.parse("Width 4\nHeight 4\nCamera Camera\n" + light
                + "Material Diffuse d\nSurface Sphere\nVector3d center [0 2 0]\ndouble radius 0.3\nref material d\n",
                "blocked.txt", new ArrayList<>());
        IntersectionRecord rec = at(0, 0, 0);
        AreaLight l = (AreaLight) open.lights.get(0);
        Vector3d all = new Vector3d(), unblocked = new Vector3d();
        LightSample out = new LightSample();
        for (int k = 0; k < 9; k++) {
            assertTrue(l.sample(rec, open, k, out));
            all.add(out.intensity);
            if (k != 4) {
                unblocked.add(out.intensity);
            }
        }
        assertTrue(all.epsilonEquals(l.getIntensity(rec, open), 1e-12), "nothing in the way: " + all);
        Vector3d got = blocked.lights.get(0).getIntensity(rec, blocked);
        assertTrue(unblocked.epsilonEquals(got, 1e-12), "middle sample blocked: expected " + unblocked + ", got " + got);
        assertTrue(got.x < all.x, "the sphere takes light away");
    }

    /**
     * Inside a render each sample draws the next two dimensions of the pixel sample: sample k of a jittered
     * pixel sample sits at offsets (get(2 + 2k), get(3 + 2k)) of its cell, not at the cell's centre and
     * not where the previous sample was.
     */
    @Test
    void eachSampleDrawsTheNextTwoDimensionsOfThePixelSample() {
        int n = 2;
        AreaLight l = oblique(n);
        Scene scene = empty();
        Sampler jittered = Sampler.create("jittered", 4);
        TraceContext ctx = TraceContext.current(scene);
        try {
            ctx.sample.start(jittered, 3, 5, 1);
            LightSample out = new LightSample(ctx.sample);   // the light draws from the sample handed to it
            IntersectionRecord rec = at(0.25, -1, 0.75);
            for (int k = 0; k < n * n; k++) {
                double u = jittered.get(3, 5, 1, 2 + 2 * k), v = jittered.get(3, 5, 1, 3 + 2 * k);
                assertTrue(u != 0.5 || v != 0.5, "a jittered draw, not the centre");
                double s = (k % n + u) / n - 0.5, t = (k / n + v) / n - 0.5;
                assertTrue(l.sample(rec, scene, k, out));
                assertEquals(0.5 + 2 * s - 0.75 * t, out.position.x, 1e-14, "sample " + k);
                assertEquals(4 + 0.25 * s + 0.5 * t, out.position.y, 1e-14, "sample " + k);
                assertEquals(-1 + 0.5 * s + 1.5 * t, out.position.z, 1e-14, "sample " + k);
            }
            assertEquals(2 + 2 * n * n, ctx.sample.dimension(), "two dimensions per sample");
        } finally {
            ctx.sample.start(Sampler.create("grid", 1), 0, 0, 0);   // as outside a render
        }
    }
}
