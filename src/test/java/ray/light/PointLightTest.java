package ray.light;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Scene;
import ray.material.Diffuse;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/** getIntensity: I / r^2 at the point, zero in shadow, from a light at (0, 3, 4) (r = 5). */
class PointLightTest {

    private static final double EPS = 1e-12;

    private static PointLight light(double x, double y, double z) {
        PointLight l = new PointLight();
        l.position = new Vector3d(x, y, z);
        l.intensity = new Vector3d(25, 50, 75);
        l.init();
        return l;
    }

    private static Scene scene(Surface... occluders) {
        Scene s = new Scene();
        s.camera = new Camera();
        for (Surface o : occluders) {
            o.material = new Diffuse();
            s.surfaces.add(o);
        }
        return s;
    }

    private static IntersectionRecord at(double x, double y, double z) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(x, y, z);
        rec.normal.set(0, 0, 1);
        return rec;
    }

    private static Sphere sphere(double x, double y, double z, double r) {
        Sphere s = new Sphere();
        s.center = new Vector3d(x, y, z);
        s.radius = r;
        return s;
    }

    private static void assertIntensity(double r, double g, double b, Vector3d i, String what) {
        assertEquals(r, i.x, EPS, what + " " + i);
        assertEquals(g, i.y, EPS, what + " " + i);
        assertEquals(b, i.z, EPS, what + " " + i);
    }

    @Test
    void unshadowedIntensityIsIOverRSquared() {
        assertIntensity(1, 2, 3, light(0, 3, 4).getIntensity(at(0, 0, 0), scene()), "r = 5");
        assertIntensity(0.25, 0.5, 0.75, light(0, 6, 8).getIntensity(at(0, 0, 0), scene()), "r = 10");
        assertIntensity(1, 2, 3, light(1, 5, 7).getIntensity(at(1, 2, 3), scene()), "r = 5 from (1, 2, 3)");
    }

    @Test
    void occluderBetweenCastsShadow() {
        Scene s = scene(sphere(0, 1.5, 2, 0.5));   // the midpoint of the segment
        assertIntensity(0, 0, 0, light(0, 3, 4).getIntensity(at(0, 0, 0), s), "sphere between");
    }

    @Test
    void occluderBeyondLightCastsNoShadow() {
        Scene s = scene(sphere(0, 6, 8, 1));   // on the same line, twice as far
        assertIntensity(1, 2, 3, light(0, 3, 4).getIntensity(at(0, 0, 0), s), "sphere beyond the light");
    }

    @Test
    void occluderBesideSegmentCastsNoShadow() {
        Scene s = scene(sphere(3, 1.5, 2, 0.5));
        assertIntensity(1, 2, 3, light(0, 3, 4).getIntensity(at(0, 0, 0), s), "sphere beside");
    }

    /** A one-sided triangle blocks the light only when the shadow ray meets its front. */
    @Test
    void triangleShadowsOnlyFromItsFront() {
        // the plane z = 2 crosses the segment from (0,0,0) to (0,3,4) at (0, 1.5, 2)
        Triangle facingPoint = new Triangle();     // n = -z: faces the shading point below it
        facingPoint.v0 = new Vector3d(-5, -5, 2);
        facingPoint.v1 = new Vector3d(0, 10, 2);
        facingPoint.v2 = new Vector3d(5, -5, 2);
        Triangle facingLight = new Triangle();     // same triangle wound the other way: n = +z
        facingLight.v0 = new Vector3d(-5, -5, 2);
        facingLight.v1 = new Vector3d(5, -5, 2);
        facingLight.v2 = new Vector3d(0, 10, 2);
        assertIntensity(0, 0, 0, light(0, 3, 4).getIntensity(at(0, 0, 0), scene(facingPoint)), "front toward point");
        assertIntensity(1, 2, 3, light(0, 3, 4).getIntensity(at(0, 0, 0), scene(facingLight)), "back toward point");
    }

    /** The light exactly on the point: no direction, no finite amount: nothing, and no NaN. */
    @Test
    void lightOnThePointContributesNothing() {
        Vector3d i = light(1, 2, 3).getIntensity(at(1, 2, 3), scene());
        assertIntensity(0, 0, 0, i, "r = 0");
    }

    /** A light sitting on a surface is not shadowed by that surface. */
    @Test
    void surfaceTheLightSitsOnDoesNotShadowIt() {
        Scene s = scene(sphere(0, 6, 8, 5));   // passes through the light at (0, 3, 4) (its near pole)
        assertIntensity(1, 2, 3, light(0, 3, 4).getIntensity(at(0, 0, 0), s), "light on a sphere");
    }

    /** The shading point's own surface does not shadow it (a sphere lit from outside). */
    @Test
    void pointOnSphereIsNotShadowedBySelf() {
        Sphere own = sphere(0, 0, -1, 1);
        Scene s = scene(own);
        IntersectionRecord rec = at(0, 0, 0);   // top of the sphere, normal +z
        rec.surface = own;
        assertIntensity(1, 2, 3, light(0, 3, 4).getIntensity(rec, s), "self");
    }

    @Test
    void resultIsAFreshVector() {
        PointLight l = light(0, 3, 4);
        Scene s = scene();
        Vector3d a = l.getIntensity(at(0, 0, 0), s);
        a.set(-1, -1, -1);
        Vector3d b = l.getIntensity(at(0, 0, 0), s);
        assertNotSame(a, b);
        assertTrue(b.x == 1 && l.intensity.x == 25, "caller's changes do not leak into the light");
    }
}
