package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.light.AreaLight;
import ray.light.Light;
import ray.light.PointLight;
import ray.light.SpotLight;
import ray.material.BlinnPhong;
import ray.material.CheckerDiffuse;
import ray.material.DielectricMaterial;
import ray.material.Diffuse;
import ray.material.GlazedMaterial;
import ray.material.Material;
import ray.material.Term;
import ray.render.Image;
import ray.surface.Mesh;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * A student's subclass of a built-in that overrides only the framework's method (Material.shade,
 * Light.getIntensity, Surface.intersects) drops in: the renderer runs the override, not the built-in's
 * fast path, and the plan does not lend it the parent's declaration.
 */
class FrameworkOverrideTest {

    /** A 4 x 4 image of a wall (material m) lit by a point light of intensity {@code i}, ambient light 0.5. */
    private static String wall(String kd, String i) {
        return "Width 4\nHeight 4\n\nAmbientLight [0.5 0.5 0.5]\n\nCamera Camera\n\n"
                + "Material Diffuse m\nVector3d diffuseColor [" + kd + "]\nVector3d ambientColor [" + kd + "]\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\nVector3d v2 [0 100 0]\nref material m\n\n"
                + "Light PointLight\nVector3d position [0 0 3]\nVector3d intensity [" + i + "]\n\n";
    }

    /** A student's Diffuse at half strength, through the framework's shade only (and the parent's, by super). */
    public static class HalfDiffuse extends Diffuse {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            Vector3d c = super.shade(ray, record, scene);
            c.scale(0.5);
            return c;
        }
    }

    /** A student's point light that overrides only getIntensity: a constant, unshadowed amount. */
    public static class SteadyLight extends PointLight {
        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return new Vector3d(0.25, 0.5, 0.75);
        }
    }

    /** The same light written against the framework's Light directly: what SteadyLight must render as. */
    public static class SteadyLamp extends Light {
        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return new Vector3d(0.25, 0.5, 0.75);
        }
    }

    /** A sphere whose own test never hits: if it renders, the BVH's packed kernel ran instead of it. */
    public static class HiddenSphere extends Sphere {
        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            return false;
        }
    }

    public static class HiddenTriangle extends Triangle {
        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            return false;
        }
    }

    /** A mesh whose own test never hits: if it renders, the BVH took its triangles instead of it. */
    public static class HiddenMesh extends Mesh {
        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            return false;
        }
    }

    @Test
    void aDiffuseOverridingOnlyShadeIsShadedByItsOverride() throws Exception {
        Scene half = PlanFixture.parse(wall("1 1 1", "3 3 3"));
        half.surfaces.get(0).material = new HalfDiffuse();
        ((Diffuse) half.surfaces.get(0).material).diffuseColor.set(1, 1, 1);
        ((Diffuse) half.surfaces.get(0).material).ambientColor.set(1, 1, 1);
        Image expected = PlanFixture.withPlan(wall("0.5 0.5 0.5", "3 3 3")).image;
        Image full = PlanFixture.withPlan(wall("1 1 1", "3 3 3")).image;
        PlanFixture f = PlanFixture.render(half, EnumSet.allOf(Skip.class));
        assertTrue(full.rgb[0] > 0 && full.rgb[0] != expected.rgb[0], "the scene tells half from full strength");
        PlanFixture.assertSameImage(expected, f.image, "HalfDiffuse renders at half of Diffuse (x 0.5 is exact)");
    }

    @Test
    void aPointLightOverridingOnlyGetIntensityLightsByItsOverride() throws Exception {
        // intensity 0 in the scene: PointLight's declaration (dark) must not skip the student's light
        Scene s = PlanFixture.parse(wall("1 1 1", "0 0 0"));
        s.lights.set(0, new SteadyLight());
        Scene lamp = PlanFixture.parse(wall("1 1 1", "0 0 0"));
        lamp.lights.set(0, new SteadyLamp());
        PlanFixture f = PlanFixture.render(s, EnumSet.allOf(Skip.class));
        PlanFixture.assertSameImage(PlanFixture.render(lamp, EnumSet.allOf(Skip.class)).image, f.image,
                "SteadyLight renders as the same light written against Light");
        assertTrue(f.image.rgb[0] > 0.5 * 1 + 1e-9, "the override's light shows above the ambient term");
        SteadyLight p = new SteadyLight();
        p.intensity.set(0, 0, 0);
        assertFalse(p.plannedDark(), "an override of getIntensity is not PointLight's dark declaration");
        assertEquals(Light.UNKNOWN_RAYS, p.plannedShadowRays());
        assertEquals(1, p.renderSampleCount());
    }

    @Test
    void surfacesOverridingOnlyIntersectsAreTestedByTheirOverride() throws Exception {
        String text = "Width 4\nHeight 4\n\nBGColor [0.25 0.25 0.25]\nAmbientLight [1 1 1]\n\nCamera Camera\n\n"
                + "Material Diffuse m\nVector3d ambientColor [1 1 1]\n\n"
                + "Surface Sphere\nVector3d center [0 0 0]\ndouble radius 100\nref material m\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\nVector3d v2 [0 100 0]\nref material m\n\n";
        Scene plain = PlanFixture.parse(text);
        assertTrue(PlanFixture.withPlan(text).image.rgb[0] != 0.25, "the built-ins cover the view");
        HiddenSphere s = new HiddenSphere();
        Sphere from = (Sphere) plain.surfaces.get(0);
        s.center.set(from.center);
        s.radius = from.radius;
        s.material = from.material;
        HiddenTriangle t = new HiddenTriangle();
        Triangle tf = (Triangle) plain.surfaces.get(1);
        t.v0.set(tf.v0);
        t.v1.set(tf.v1);
        t.v2.set(tf.v2);
        t.material = tf.material;
        t.init();
        HiddenMesh m = new HiddenMesh();
        m.twoSided = 1;
        m.material = tf.material;
        m.setTriangles(new float[] {-100, -100, 0, 100, -100, 0, 0, 100, 0}, new float[0], new int[] {0, 1, 2}, null, "test");
        assertTrue(new Sphere().packedType() != null && new Triangle().packedType() != null, "the built-ins keep their packed sets");
        assertNull(s.packedType());
        assertNull(t.packedType());
        List<Surface> parts = new ArrayList<>();
        m.addPrimitives(parts);
        assertEquals(List.of(m), parts, "the mesh itself, not its triangles");
        assertEquals(1, m.plannedPrimitiveCount());
        plain.surfaces.set(0, s);
        plain.surfaces.set(1, t);
        plain.surfaces.add(m);
        Image image = PlanFixture.render(plain, EnumSet.allOf(Skip.class)).image;
        for (double v : image.rgb) {
            assertEquals(0.25, v, "only the background: the overrides' tests (never a hit) ran");
        }
    }

    @Test
    void anOverrideOfShadeIsPlannedAsNeedingEverythingUnlessItDeclaresItself() throws Exception {
        assertEquals(EnumSet.allOf(Term.class), new HalfDiffuse().plannedTerms());
        assertEquals(new Diffuse().terms(), new CheckerDiffuse().plannedTerms(), "a hook's override keeps the declaration");
        Scene s = PlanFixture.parse(wall("1 1 1", "3 3 3"));
        s.surfaces.get(0).material = new HalfDiffuse();
        assertEquals(Double.POSITIVE_INFINITY, RenderPlan.derive(s, EnumSet.allOf(Skip.class)).bound().get(RayKind.USER));
        Scene glazed = PlanFixture.parse(wall("1 1 1", "3 3 3"));
        GlazedMaterial g = new GlazedMaterial();
        g.base = new HalfDiffuse();
        assertTrue(g.terms().containsAll(EnumSet.allOf(Term.class)), "a Glazed base's override is planned as needing everything");
        glazed.surfaces.get(0).material = g;
        assertEquals(Double.POSITIVE_INFINITY, RenderPlan.derive(glazed, EnumSet.allOf(Skip.class)).bound().get(RayKind.USER));
    }

    @Test
    void noBuiltInTakesTheFrameworkForm() {
        for (Material m : List.of(new Diffuse(), new BlinnPhong(), new GlazedMaterial(), new DielectricMaterial(), new CheckerDiffuse())) {
            assertFalse(m.usesFrameworkShade(), m.getClass().getSimpleName());
            assertEquals(m.terms(), m.plannedTerms(), m.getClass().getSimpleName());
        }
        assertTrue(new HalfDiffuse().usesFrameworkShade());
        for (Light l : List.of(new PointLight(), new SpotLight(), new AreaLight())) {
            assertFalse(l.usesFrameworkIntensity(), l.getClass().getSimpleName());
            assertEquals(l.shadowRaysPerPoint(), l.plannedShadowRays(), l.getClass().getSimpleName());
        }
        assertTrue(new SteadyLight().usesFrameworkIntensity());
    }
}
