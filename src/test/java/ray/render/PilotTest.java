package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;
import ray.plan.CostGate;
import ray.plan.RayEstimate;
import ray.plan.RenderPlan;
import ray.settings.RenderSettings;

/** The plan's estimate: a pilot render of a fraction of the pixels, scaled up; the scene left as it was. */
class PilotTest {

    private static Scene parse(String scene) throws Exception {
        return Parser.parse(Path.of("scenes", scene), new ArrayList<>());
    }

    /** Rays counted by a full render, all kinds. */
    private static long render(Scene s, RenderSettings set, double[] image) {
        Renderer r = new Renderer(s).threads(2).settings(set);
        Image img = r.render();
        if (image != null) {
            System.arraycopy(img.rgb, 0, image, 0, img.rgb.length);
        }
        long n = 0;
        for (ray.RayKind k : ray.RayKind.values()) {
            n += r.stats().get(k);
        }
        return n;
    }

    @Test
    void theEstimateComesCloseToTheRaysARenderCastsAndLeavesTheSceneAsItWas() throws Exception {
        RenderSettings set = new RenderSettings();
        for (String name : new String[] {"material-dielectric.txt", "glazed-base-vs-none.txt", "light-area.txt"}) {
            Scene a = parse(name), b = parse(name);
            int w = a.width, h = a.height;
            RayEstimate e = Pilot.estimate(a, set, 2);
            assertNotNull(e, name);
            assertEquals(w, a.width);
            assertEquals(h, a.height);
            assertTrue(e.fraction <= 1.0 / 60, name + ": a pilot of about 1/64 of the pixels (each side / 8, rounded up): " + e.fraction);
            double[] after = new double[w * h * 3], fresh = new double[w * h * 3];
            long cast = render(a, set, after);
            render(b, set, fresh);
            assertArrayEquals(fresh, after, 0.0, name + ": the render after the pilot is the render without it");
            double ratio = e.total() / cast;
            // measured over scenes/ (docs/plan.md): 0.94-1.07; a pilot at 1/64 of the pixels can miss small things
            assertTrue(ratio > 0.8 && ratio < 1.25, name + ": estimated " + e.total() + " rays, cast " + cast);
            assertTrue(e.total() <= RenderPlan.derive(b, set).bound().total(), name + ": an estimate within the bound");
        }
    }

    @Test
    void theLongRenderNoteAsksThePilotOnlyWhereTheBoundLeavesRoomAndSaysItIsAnEstimate() throws Exception {
        Scene s = parse("glazed-base-vs-none.txt");
        RenderPlan plan = RenderPlan.derive(s, new RenderSettings());
        AtomicInteger asked = new AtomicInteger();
        // its bound is a fraction of a second's rays: no pilot, no note
        assertNull(CostGate.warning("g", plan, 2, () -> {
            asked.incrementAndGet();
            return null;
        }));
        assertEquals(0, asked.get());
        // a bound of hours with a pilot that finds seconds: no note; one that finds 13 minutes: the note, as an estimate
        Scene big = parse("glazed-base-vs-none.txt");
        big.width *= 40;
        big.height *= 40;
        RenderPlan bigPlan = RenderPlan.derive(big, new RenderSettings().samples(4));
        double[] rays = new double[ray.RayKind.values().length];
        rays[ray.RayKind.CAMERA.ordinal()] = 1e6;
        assertNull(CostGate.warning("g", bigPlan, 2, () -> new RayEstimate(rays, 1.0 / 64, 0.1)));
        rays[ray.RayKind.SHADOW.ordinal()] = 6e9;
        String note = CostGate.warning("g", bigPlan, 2, () -> new RayEstimate(rays, 1.0 / 64, 0.1));
        assertNotNull(note);
        assertTrue(note.startsWith("g: note: this render will likely take long: estimate (not a bound): about 6,001,000,000 rays, about 13 min on 2 threads"), note);
        assertTrue(note.contains("the plan's bound: up to "), note);
    }

    /** A class that declares nothing may trace any number of rays: no pilot, no estimate (the plan says "no estimate"). */
    @Test
    void noEstimateForAUserMaterialThatDeclaresNothing() throws Exception {
        Scene s = parse("material-diffuse.txt");
        ray.material.Material mine = new ray.material.Material() {
            @Override
            public javax.vecmath.Vector3d shade(ray.Ray ray, ray.IntersectionRecord record, Scene scene) {
                return new javax.vecmath.Vector3d(0.5, 0.5, 0.5);
            }
        };
        s.surfaces.get(0).material = mine;
        assertEquals(Double.POSITIVE_INFINITY, RenderPlan.derive(s, new RenderSettings()).bound().total());
        assertNull(Pilot.estimate(s, new RenderSettings(), 2));
    }
}
