package ray.material;

import static org.junit.jupiter.api.Assertions.assertEquals;

import javax.vecmath.Vector3d;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.light.PointLight;

/**
 * Hand-built shading situations: a hit at the origin on a surface facing +z, seen by a ray coming
 * down the z axis from (0, 0, 5), in a scene with no surfaces (so nothing casts a shadow).
 */
final class ShadingFixture {

    static final double EPS = 1e-12;

    private ShadingFixture() {
    }

    static Scene scene(Vector3d ambient, PointLight... lights) {
        Scene s = new Scene();
        s.camera = new Camera();
        s.ambientLight = ambient;
        for (PointLight l : lights) {
            s.lights.add(l);
        }
        return s;
    }

    static PointLight light(double x, double y, double z, double r, double g, double b) {
        PointLight l = new PointLight();
        l.position = new Vector3d(x, y, z);
        l.intensity = new Vector3d(r, g, b);
        l.init();
        return l;
    }

    /** The hit at the origin, normal +z. */
    static IntersectionRecord record() {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(0, 0, 0);
        rec.normal.set(0, 0, 1);
        rec.t = 5;
        return rec;
    }

    /** The viewing ray from (0, 0, 5) straight down: the viewer direction at the hit is +z. */
    static Ray viewRay() {
        return new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1));
    }

    static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    /** The renderer's fast form, on a fresh context. */
    static Vector3d fast(Material m, Ray ray, IntersectionRecord rec, Scene scene) {
        Vector3d out = new Vector3d(Double.NaN, Double.NaN, Double.NaN);
        m.shade(ray, rec, scene, new TraceContext(scene.maxDepth), out);
        return out;
    }

    static void assertColor(double r, double g, double b, Vector3d c, String what) {
        assertEquals(r, c.x, EPS, what + ": red in " + c);
        assertEquals(g, c.y, EPS, what + ": green in " + c);
        assertEquals(b, c.z, EPS, what + ": blue in " + c);
    }

    /** The framework form and the fast form agree, and the framework form leaves the record alone. */
    static void assertFormsAgree(Material m, Ray ray, IntersectionRecord rec, Scene scene) {
        IntersectionRecord before = new IntersectionRecord();
        before.set(rec);
        Vector3d slow = m.shade(ray, rec, scene);
        Vector3d quick = fast(m, ray, rec, scene);
        assertEquals(quick, slow, "framework form vs fast form");
        assertEquals(before.location, rec.location);
        assertEquals(before.normal, rec.normal);
    }
}
