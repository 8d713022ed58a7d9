package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.light.PointLight;
import ray.material.BlinnPhong;
import ray.material.Diffuse;
import ray.material.GlazedMaterial;

/** A user's class the plan knows nothing about is assumed to need everything. */
class TrustTest {

    /** A student's Diffuse that shades its own way: its inherited declaration no longer describes it. */
    public static class OwnDiffuse extends Diffuse {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return new Vector3d(1, 0, 0);
        }
    }

    /** A student's point light that lights everything however its intensity is set. */
    public static class AlwaysOn extends PointLight {
        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return new Vector3d(1, 1, 1);
        }
    }

    @Test
    void builtInsAreTrustedAndOverridersAreNot() {
        assertTrue(Trust.material(new Diffuse()));
        assertTrue(Trust.material(new BlinnPhong()));
        assertTrue(Trust.material(new GlazedMaterial()));
        assertFalse(Trust.material(new OwnDiffuse()));
        assertTrue(Trust.light(new PointLight()));
        assertFalse(Trust.light(new AlwaysOn()));
        assertEquals(EnumSet.allOf(Term.class), RenderPlan.termsOf(new OwnDiffuse()));
    }

    /** Every concrete built-in material and light declares itself where it shades (else the plan calls it unknown). */
    @Test
    void everyBuiltInMaterialAndLightIsTrusted() throws Exception {
        int seen = 0;
        for (Class<?> base : new Class<?>[] {ray.material.Material.class, ray.light.Light.class}) {
            java.nio.file.Path dir = java.nio.file.Path.of(base.getProtectionDomain().getCodeSource().getLocation().toURI())
                    .resolve(base.getPackageName().replace('.', '/'));
            try (java.util.stream.Stream<java.nio.file.Path> files = java.nio.file.Files.list(dir)) {
                for (java.nio.file.Path f : (Iterable<java.nio.file.Path>) files::iterator) {
                    String name = f.getFileName().toString();
                    if (!name.endsWith(".class") || name.contains("$")) {
                        continue;
                    }
                    Class<?> c = Class.forName(base.getPackageName() + "." + name.replace(".class", ""));
                    if (!base.isAssignableFrom(c) || java.lang.reflect.Modifier.isAbstract(c.getModifiers())) {
                        continue;
                    }
                    Object o = c.getConstructor().newInstance();
                    assertTrue(o instanceof ray.material.Material m ? Trust.material(m) : Trust.light((ray.light.Light) o),
                            c.getSimpleName() + " must declare terms() (isDark/shadowRaysPerPoint) where it shades (samples)");
                    seen++;
                }
            }
        }
        assertTrue(seen >= 6, seen + " classes");
    }

    @Test
    void aDarkUserLightIsNotSkippedAndAUserMaterialMakesTheBoundUnknown() throws Exception {
        String text = "Width 4\nHeight 4\n\nCamera Camera\n\nMaterial Metal m\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\nVector3d v2 [0 100 0]\nref material m\n\n"
                + "Light PointLight\nVector3d position [0 0 3]\nVector3d intensity [0 0 0]\n\n";
        Scene s = PlanFixture.parse(text);
        AlwaysOn on = new AlwaysOn();
        on.intensity = new Vector3d();
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
