package ray.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static ray.material.ShadingFixture.assertColor;
import static ray.material.ShadingFixture.assertFormsAgree;
import static ray.material.ShadingFixture.fast;
import static ray.material.ShadingFixture.light;
import static ray.material.ShadingFixture.record;
import static ray.material.ShadingFixture.scene;
import static ray.material.ShadingFixture.v;
import static ray.material.ShadingFixture.viewRay;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.Ray;
import ray.Scene;
import ray.surface.Triangle;

/**
 * L = L_base + k_m L_mirror, L_base = 0 without a base. With no surfaces the mirror ray sees
 * BGColor = (0.2, 0.4, 0.6); the base is DiffuseTest's material, L_base = (0.69, 0.74, 0.78).
 */
class GlazedMaterialTest {

    private static Diffuse base() {
        Diffuse d = new Diffuse();
        d.ambientColor = v(0.1, 0.2, 0.3);
        d.diffuseColor = v(0.8, 0.4, 0.2);
        return d;
    }

    private static GlazedMaterial glazed(Material base, double km) {
        GlazedMaterial g = new GlazedMaterial();
        g.base = base;
        g.mirrorCoefficient = km;
        g.init();
        return g;
    }

    private static Scene sky() {
        Scene s = scene(v(0.5, 0.5, 1), light(0, 3, 4, 25, 50, 75));
        s.backgroundColor = v(0.2, 0.4, 0.6);
        return s;
    }

    @Test
    void basePlusMirrorOfBackground() {
        Scene s = sky();
        assertColor(0.69 + 0.1, 0.74 + 0.2, 0.78 + 0.3, fast(glazed(base(), 0.5), viewRay(), record(), s), "with base");
        assertFormsAgree(glazed(base(), 0.5), viewRay(), record(), s);
    }

    @Test
    void withoutBaseOnlyMirror() {
        Scene s = sky();
        assertColor(0.1, 0.2, 0.3, fast(glazed(null, 0.5), viewRay(), record(), s), "no base");
        assertFormsAgree(glazed(null, 0.5), viewRay(), record(), s);
    }

    /** A ray already at depth MaxDepth: its mirror ray is not followed and adds black. */
    @Test
    void mirrorNotFollowedAtMaxDepth() {
        Scene s = sky();
        s.maxDepth = 3;
        Ray r = viewRay();
        r.depth = 3;
        assertColor(0.69, 0.74, 0.78, fast(glazed(base(), 0.5), r, record(), s), "depth 3 of 3");
        r.depth = 2;
        assertColor(0.79, 0.94, 1.08, fast(glazed(base(), 0.5), r, record(), s), "depth 2 of 3");
        assertFormsAgree(glazed(base(), 0.5), r, record(), s);
    }

    @Test
    void maxDepthZeroShowsBaseOnly() {
        Scene s = sky();
        s.maxDepth = 0;
        assertColor(0.69, 0.74, 0.78, fast(glazed(base(), 0.5), viewRay(), record(), s), "MaxDepth 0");
        assertColor(0, 0, 0, fast(glazed(null, 0.5), viewRay(), record(), s), "MaxDepth 0, no base");
    }

    /**
     * The ray arrives along (1, 0, -1) and must leave along (1, 0, 1): a triangle placed across that
     * direction (ambient-only, k_a I_a = (0.3, 0.3, 0.3)) is seen in the mirror; any other direction
     * would see the background.
     */
    @Test
    void mirrorRayLeavesAtEqualAngle() {
        Scene s = scene(v(0.3, 0.3, 0.3));
        s.backgroundColor = v(0.2, 0.4, 0.6);
        Diffuse wall = new Diffuse();
        wall.ambientColor = v(1, 1, 1);
        wall.diffuseColor = v(0, 0, 0);
        // perpendicular to d = (1,0,1)/sqrt2 around (3,0,3); a = +y, b = a x d = (1,0,-1)/sqrt2, normal a x b = -d
        double k = 1, r3 = Math.sqrt(3) * k / Math.sqrt(2);
        Triangle t = new Triangle();
        t.v0 = v(3, 2 * k, 3);
        t.v1 = v(3 + r3, -k, 3 - r3);
        t.v2 = v(3 - r3, -k, 3 + r3);
        t.material = wall;
        s.surfaces.add(t);
        Ray in = new Ray(v(-5, 0, 5), v(1, 0, -1));
        assertColor(0.15, 0.15, 0.15, fast(glazed(null, 0.5), in, record(), s), "reflection of the wall");
        Ray straight = viewRay();   // reflects straight up: misses the wall
        assertColor(0.1, 0.2, 0.3, fast(glazed(null, 0.5), straight, record(), s), "reflection of the sky");
    }

    /**
     * Two facing mirrors (base k_a = red, I_a = 1, k_m = 0.5) and a camera between them: each
     * followed bounce adds half the last, so MaxDepth d gives 1 + 1/2 + ... + 1/2^d (exact in binary).
     */
    @Test
    void facingMirrorsStopAtMaxDepth() {
        for (int depth : new int[] {0, 1, 3, 10}) {
            Scene s = facingMirrors(depth);
            Vector3d c = s.trace(new Ray(v(0, 0, 0), v(0, 0, 1)));
            double expected = 2 - Math.pow(0.5, depth);
            assertEquals(expected, c.x, 1e-12, "MaxDepth " + depth);
            assertEquals(0, c.y);
        }
    }

    static Scene facingMirrors(int maxDepth) {
        Scene s = scene(v(1, 1, 1));
        s.maxDepth = maxDepth;
        s.camera = new Camera();
        Diffuse red = new Diffuse();
        red.ambientColor = v(1, 0, 0);
        red.diffuseColor = v(0, 0, 0);
        GlazedMaterial m = glazed(red, 0.5);
        // z = 1 facing -z and z = -1 facing +z, each a triangle far wider than the bounce path
        s.surfaces.add(triangle(v(-100, -100, 1), v(0, 100, 1), v(100, -100, 1), m));
        s.surfaces.add(triangle(v(-100, -100, -1), v(100, -100, -1), v(0, 100, -1), m));
        return s;
    }

    private static Triangle triangle(Vector3d a, Vector3d b, Vector3d c, Material m) {
        Triangle t = new Triangle();
        t.v0 = a;
        t.v1 = b;
        t.v2 = c;
        t.material = m;
        return t;
    }

    @Test
    void zeroCoefficientIsTheBaseAlone() {
        assertColor(0.69, 0.74, 0.78, fast(glazed(base(), 0), viewRay(), record(), sky()), "k_m = 0");
    }
}
