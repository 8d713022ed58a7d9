package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.material.Diffuse;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The built-in fields the parser stores without reflection ({@link Fields#setDirect}) must end up as
 * {@code Field.set} leaves them: in the field the entry names, for a subclass's object too, and never
 * for a field a subclass declares under the same name.
 */
class FieldsDirectTest {

    /** A student's triangle: the fields are still Triangle's own. */
    public static class Sub extends Triangle {
    }

    /** A student's triangle hiding v0 behind a field of its own: reflection must set that one. */
    public static class Shadowing extends Triangle {
        public Vector3d v0 = new Vector3d();
    }

    @Test
    void aSceneSetsEachBuiltInFieldToItsValue() throws Exception {
        Scene s = ParserTest.parse(ParserTest.BASE + "Material Diffuse m\n\nSurface Triangle\nVector3d v0 [1 2 3]\nVector3d v1 [4 5 6]\n"
                + "Vector3d v2 [7 8 10]\nref material m\n\nSurface Sphere\nVector3d center [1.5 -2 0.25]\ndouble radius 0.75\n"
                + "ref material m\n");
        Triangle t = (Triangle) s.surfaces.get(0);
        Sphere p = (Sphere) s.surfaces.get(1);
        assertEquals(new Vector3d(1, 2, 3), t.v0);
        assertEquals(new Vector3d(4, 5, 6), t.v1);
        assertEquals(new Vector3d(7, 8, 10), t.v2);
        assertEquals(new Vector3d(1.5, -2, 0.25), p.center);
        assertEquals(0.75, p.radius);
        assertTrue(t.material instanceof Diffuse);
        assertSame(t.material, p.material);
    }

    @Test
    void eachDirectStoreIsReflectionsStoreIntoTheSameField() throws Exception {
        Fields fields = new Fields();
        Object[][] cases = {
            {Triangle.class, "v0"}, {Triangle.class, "v1"}, {Triangle.class, "v2"}, {Sub.class, "v0"}, {Sub.class, "v2"},
            {Shadowing.class, "v1"}, {Sphere.class, "center"}, {Sphere.class, "material"}, {Sub.class, "material"},
        };
        for (Object[] c : cases) {
            Class<?> cls = (Class<?>) c[0];
            Fields.Entry e = fields.find(cls, (String) c[1]);
            assertTrue(e.direct() != 0, cls.getSimpleName() + "." + c[1] + " is stored directly");
            Object direct = cls.getConstructor().newInstance(), reflected = cls.getConstructor().newInstance();
            Object v = e.field().getType() == Vector3d.class ? new Vector3d(0.1, -2.5, 7) : new Diffuse();
            assertTrue(Fields.setDirect(e.direct(), direct, v));
            e.field().set(reflected, v);
            for (java.lang.reflect.Field f : new java.lang.reflect.Field[] {Triangle.class.getField("v0"), Triangle.class.getField("v1"),
                    Triangle.class.getField("v2"), Sphere.class.getField("center"), Surface.class.getField("material")}) {
                if (!f.getDeclaringClass().isInstance(direct)) {
                    continue;
                }
                String what = cls.getSimpleName() + "." + c[1] + ": " + f.getName();
                if (f.equals(e.field())) {
                    assertSame(v, f.get(direct), what);
                    assertSame(v, f.get(reflected), what);
                } else {
                    assertEquals(f.get(reflected), f.get(direct), what);   // untouched: both still the defaults
                }
            }
        }
        assertEquals(Fields.SPHERE_RADIUS, fields.find(Sphere.class, "radius").direct());
        Sphere p = new Sphere();
        assertTrue(Fields.setDirect(Fields.SPHERE_RADIUS, p, 2.5));
        assertEquals(2.5, p.radius);
        assertFalse(Fields.setDirect(Fields.SPHERE_CENTER, p, 3.5));
        assertEquals(2.5, p.radius);
    }

    @Test
    void aFieldASubclassDeclaresUnderTheSameNameIsSetByReflection() throws Exception {
        Fields.Entry e = new Fields().find(Shadowing.class, "v0");
        assertEquals(0, e.direct());
        assertEquals(Shadowing.class, e.field().getDeclaringClass());
        assertFalse(Fields.setDirect(e.direct(), new Shadowing(), new Vector3d()));
        Scene s = ParserTest.parse(ParserTest.BASE + "Material Diffuse m\n\nSurface " + Shadowing.class.getName() + "\nVector3d v0 [1 2 3]\n"
                + "Vector3d v1 [4 5 6]\nVector3d v2 [7 8 10]\nref material m\n");
        Shadowing t = (Shadowing) s.surfaces.get(0);
        assertEquals(new Vector3d(1, 2, 3), t.v0);
        assertEquals(new Vector3d(0, 0, 0), ((Triangle) t).v0);
    }
}
