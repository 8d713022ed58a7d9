package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.material.Term;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.light.PointLight;
import ray.material.BlinnPhong;
import ray.material.Diffuse;
import ray.material.GlazedMaterial;

/**
 * The plan reads only what materials and lights declare through their API: a subclass inherits the
 * declaration it does not change (a textured Diffuse is planned like Diffuse), a class that declares
 * nothing is assumed to need everything, a composite's parts are planned too, and no built-in needs
 * boilerplate to be believed.
 */
class DeclarationTest {

    /** A 4 x 4 image of a wall of material {@code material} (declared {@code declared}) lit by a point light of intensity {@code i}. */
    private static String wall(String declared, String material, String i) {
        return "Width 4\nHeight 4\n\nCamera Camera\n\n" + declared
                + "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\nVector3d v2 [0 100 0]\nref material " + material + "\n\n"
                + "Light PointLight\nVector3d position [0 0 3]\nVector3d intensity [" + i + "]\n\n";
    }

    /** A textured Diffuse: only its reflectance changes, so Diffuse's declaration still describes it. */
    public static class Checker extends Diffuse {
        @Override
        protected Vector3d diffuseColorAt(IntersectionRecord rec, Vector3d scratch) {
            if (((int) Math.floor(rec.location.x) + (int) Math.floor(rec.location.y) & 1) != 0) {
                return diffuseColor;
            }
            scratch.set(0.1, 0.1, 0.1);
            return scratch;
        }
    }

    /** A student's material written against the framework: it declares nothing. */
    public static class Plain extends ray.material.Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return new Vector3d(1, 0, 0);
        }
    }

    /** A student's light written against the framework: it declares nothing. */
    public static class Lamp extends ray.light.Light {
        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return new Vector3d(1, 1, 1);
        }
    }

    @Test
    void aSubclassInheritsTheDeclarationAndAClassDeclaringNothingNeedsEverything() {
        assertEquals(new Diffuse().terms(), new Checker().terms());
        assertEquals(EnumSet.allOf(Term.class), new Plain().terms());
        assertEquals(ray.light.Light.UNKNOWN_RAYS, new Lamp().shadowRaysPerPoint());
        assertEquals(1, new ray.light.SpotLight().shadowRaysPerPoint(), "SpotLight inherits PointLight's declaration");
    }

    @Test
    void aTexturedDiffuseIsPlannedLikeDiffuseAndAUserClassIsUnbounded() throws Exception {
        Scene s = PlanFixture.parse(wall("Material Diffuse m\n\n", "m", "1 1 1"));
        s.materials.clear();
        Checker c = new Checker();
        s.surfaces.get(0).material = c;
        RenderPlan p = RenderPlan.derive(s, EnumSet.allOf(Skip.class));
        assertEquals(16, p.bound().get(RayKind.SHADOW), "one shadow ray per pixel, as for Diffuse");
        assertEquals(0, p.bound().get(RayKind.USER));
        PlanFixture f = PlanFixture.render(s, EnumSet.allOf(Skip.class));
        assertWithinBoundOf(f, p);
        s.surfaces.get(0).material = new Plain();
        RenderPlan unknown = RenderPlan.derive(s, EnumSet.allOf(Skip.class));
        assertEquals(Double.POSITIVE_INFINITY, unknown.bound().get(RayKind.USER));
    }

    private static void assertWithinBoundOf(PlanFixture f, RenderPlan p) {
        for (RayKind k : RayKind.values()) {
            assertTrue(f.rays(k) <= p.bound().get(k), k + ": " + f.rays(k) + " > " + p.bound().get(k));
        }
    }

    /** A composite other than Glazed: its parts are planned (handed the plan) through {@code parts()}. */
    public static class Layered extends ray.material.Material {
        public ray.material.Material under = new Diffuse();

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return under.shade(ray, record, scene);
        }

        @Override
        public java.util.Set<Term> terms() {
            return under.terms();
        }

        @Override
        public java.util.List<ray.material.Material> parts() {
            return java.util.List.of(under);
        }
    }

    @Test
    void aCompositesPartsArePlanned() throws Exception {
        String text = wall("Material Diffuse d\n\n", "d", "1 1 1");
        Scene s = PlanFixture.parse(text);
        Layered l = new Layered();
        s.surfaces.get(0).material = l;
        RenderPlan p = RenderPlan.derive(s, EnumSet.allOf(Skip.class));
        assertEquals(16, p.bound().get(RayKind.SHADOW));
        PlanFixture f = PlanFixture.render(s, EnumSet.allOf(Skip.class));
        PlanFixture plain = PlanFixture.render(PlanFixture.parse(text), EnumSet.allOf(Skip.class));
        PlanFixture.assertSameImage(plain.image, f.image, "the part was handed the plan and shades as itself");
    }

    @Test
    void aDarkUserLightIsNotSkippedAndAUserMaterialMakesTheBoundUnknown() throws Exception {
        Scene s = PlanFixture.parse(wall("Material Metal m\n\n", "m", "0 0 0"));
        Lamp on = new Lamp();
        s.lights.add(on);
        RenderPlan p = RenderPlan.derive(s, EnumSet.allOf(Skip.class));
        assertEquals(1, p.lights().length, "the built-in dark light is skipped, the user's is not");
        assertEquals(on, p.lights()[0]);
        assertEquals(Double.POSITIVE_INFINITY, p.bound().get(RayKind.USER));
        assertEquals(Double.POSITIVE_INFINITY, p.bound().total());
        assertTrue(CostGate.refusal("t", p) == null, "an unknown bound is never refused");
        PlanReport r = PlanReport.of("t", s);
        assertTrue(r.text().stream().anyMatch(l -> l.startsWith("  user rays           on   user classes the plan cannot see into: m,")),
                String.join("\n", r.text()));
        PlanFixture f = PlanFixture.render(s, EnumSet.allOf(Skip.class));
        assertTrue(f.rays(RayKind.USER) > 0, "Metal traces through Scene.trace");
    }
}
