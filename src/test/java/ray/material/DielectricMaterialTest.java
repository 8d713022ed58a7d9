package ray.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Ray;
import ray.RayKind;
import ray.Scene;
import ray.TraceContext;
import ray.parse.Parser;
import ray.parse.ObjectErrors;
import ray.parse.SceneFormatException;

/**
 * The dielectric against values that follow by hand from its model: a ray through the centre of a
 * glass sphere crosses a slab of thickness 2 at normal incidence on both sides, so every reflectance is
 * R0 and every path inside is a multiple of 2 long. Behind the sphere an ambient-only wall shows A;
 * the background (seen by rays reflected back towards +z) is black.
 */
class DielectricMaterialTest {

    static final double N = 1.5, R0 = 0.04;
    static final double[] A = {0.5, 0.6, 0.7};
    static final double[] ABSORB = {0, 0.1, 0.5};

    static Scene slab(String fresnel, int maxDepth, double n) throws SceneFormatException {
        return Parser.parse(slabText(fresnel, maxDepth, n), "slab.txt", new ArrayList<>());
    }

    static String slabText(String fresnel, int maxDepth, double n) {
        return """
                Width 1
                Height 1
                MaxDepth %d
                AmbientLight [1 1 1]

                Camera Camera
                Vector3d eye [0 0 5]

                Material Diffuse wall
                Vector3d ambientColor [0.5 0.6 0.7]
                Vector3d diffuseColor [0 0 0]

                Material Dielectric glass
                double refractiveIndex %s
                Vector3d attenuation [0 0.1 0.5]
                String fresnel %s

                Surface Sphere
                Vector3d center [0 0 0]
                double radius 1
                ref material glass

                Surface Triangle
                Vector3d v0 [-50 -50 -5]
                Vector3d v1 [50 -50 -5]
                Vector3d v2 [0 50 -5]
                ref material wall
                """.formatted(maxDepth, Double.toString(n), fresnel);
    }

    static Vector3d centreRay(Scene s) {
        return s.trace(new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1)));
    }

    /**
     * Light reaching the wall and back crosses two interfaces, (1 - R0)^2, and 2 units of glass,
     * exp(-2a); with MaxDepth 2 no internally reflected path is followed, so that is all of it.
     */
    @Test
    void slabTransmitsOneMinusR0SquaredTimesBeer() throws Exception {
        for (String fresnel : new String[] {"schlick", "exact"}) {
            Vector3d c = centreRay(slab(fresnel, 2, N));
            double[] got = {c.x, c.y, c.z};
            for (int k = 0; k < 3; k++) {
                double expected = (1 - R0) * (1 - R0) * Math.exp(-2 * ABSORB[k]) * A[k];
                assertEquals(expected, got[k], 1e-12, fresnel + " channel " + k);
            }
        }
    }

    /**
     * With deeper rays the light bouncing inside adds a geometric series: path k (k internal round
     * trips) is followed while its last ray's depth 2 + 2k stays within MaxDepth and contributes
     * (1 - R0)^2 R0^(2k) exp(-2a (1 + 2k)) A.
     */
    @Test
    void internalReflectionsAddTheGeometricSeriesUpToMaxDepth() throws Exception {
        for (int maxDepth : new int[] {1, 2, 3, 4, 7, 60}) {
            Vector3d c = centreRay(slab("exact", maxDepth, N));
            double[] got = {c.x, c.y, c.z};
            for (int k = 0; k < 3; k++) {
                double expected = 0;
                for (int trip = 0; 2 + 2 * trip <= maxDepth; trip++) {
                    expected += (1 - R0) * (1 - R0) * Math.pow(R0, 2 * trip) * Math.exp(-2 * ABSORB[k] * (1 + 2 * trip)) * A[k];
                }
                assertEquals(expected, got[k], 1e-12, "MaxDepth " + maxDepth + " channel " + k);
            }
        }
        // the infinite series in closed form
        Vector3d deep = centreRay(slab("exact", 60, N));
        double e = Math.exp(-2 * ABSORB[2]);
        assertEquals((1 - R0) * (1 - R0) * e / (1 - R0 * R0 * e * e) * A[2], deep.z, 1e-12);
    }

    /**
     * A real slab: a glass Box 0.8 thick seen head-on, over the same ambient wall. With MaxDepth 2 the
     * light crossing it is (1 - R0)^2 exp(-0.8 a); with more depth the internal round trips add
     * (1 - R0)^2 R0^(2k) exp(-0.8 a (1 + 2k)). Checks the Box's inside (frontFace) as glass sees it.
     */
    @Test
    void boxSlabTransmitsTheSameSeries() throws Exception {
        for (int maxDepth : new int[] {2, 5, 40}) {
            String text = slabText("exact", maxDepth, N).replace("""
                    Surface Sphere
                    Vector3d center [0 0 0]
                    double radius 1
                    ref material glass
                    """, """
                    Surface Box
                    Vector3d minPoint [-3 -3 -0.4]
                    Vector3d maxPoint [3 3 0.4]
                    ref material glass
                    """);
            Vector3d c = centreRay(Parser.parse(text, "box.txt", new ArrayList<>()));
            double[] got = {c.x, c.y, c.z};
            for (int k = 0; k < 3; k++) {
                double expected = 0;
                for (int trip = 0; 2 + 2 * trip <= maxDepth; trip++) {
                    expected += (1 - R0) * (1 - R0) * Math.pow(R0, 2 * trip) * Math.exp(-0.8 * ABSORB[k] * (1 + 2 * trip)) * A[k];
                }
                assertEquals(expected, got[k], 1e-12, "MaxDepth " + maxDepth + " channel " + k);
            }
        }
    }

    /**
     * Index-1 glass with exact Fresnel lets a ray straight through, attenuated by exp(-a L) with L the
     * length of the ray inside: which needs each closed surface to report its inside (frontFace false)
     * on the way out. Along the x axis: a sphere of radius 1 (L = 2), a box 1.5 wide, a cylinder and a
     * cone along their axes (L = height 1.2), a torus through both sides of its tube (L = 2 x 0.5).
     */
    @Test
    void chordsThroughClosedSurfacesAreAttenuatedByTheirLengthInside() throws Exception {
        String[][] shapes = {
                {"Surface Sphere\nVector3d center [0 0 0]\ndouble radius 1", "2"},
                {"Surface Box\nVector3d minPoint [-0.75 -1 -1]\nVector3d maxPoint [0.75 1 1]", "1.5"},
                {"Surface Cylinder\nVector3d base [-0.6 0 0]\nVector3d axis [1.2 0 0]\ndouble radius 0.5", "1.2"},
                {"Surface Cone\nVector3d base [-0.6 0 0]\nVector3d axis [1.2 0 0]\ndouble radius 0.5", "1.2"},
                {"Surface Torus\nVector3d center [0 0 0]\nVector3d axis [0 0 1]\ndouble majorRadius 1\n"
                        + "double minorRadius 0.25", "1"},
        };
        for (String[] shape : shapes) {
            Scene s = Parser.parse("Width 1\nHeight 1\nBGColor [1 1 1]\n\nCamera Camera\n\n"
                    + "Material Dielectric glass\ndouble refractiveIndex 1\nVector3d attenuation [0 0.1 0.5]\n"
                    + "String fresnel exact\n\n" + shape[0] + "\nref material glass\n", "chord.txt", new ArrayList<>());
            Vector3d c = s.trace(new Ray(new Vector3d(-5, 0, 0), new Vector3d(1, 0, 0)));
            double length = Double.parseDouble(shape[1]);
            assertEquals(1, c.x, 1e-12, shape[0]);
            assertEquals(Math.exp(-0.1 * length), c.y, 1e-12, shape[0]);
            assertEquals(Math.exp(-0.5 * length), c.z, 1e-12, shape[0]);
        }
    }

    /**
     * The camera at the centre of a glass ball of radius 1: every ray leaves at normal incidence after
     * travelling 1 (and 2 per internal bounce); with refractive index 1 and exact Fresnel nothing is
     * reflected and the image is the background times exp(-a).
     */
    @Test
    void cameraInsideGlassSeesThroughItAttenuated() throws Exception {
        for (double n : new double[] {1, N}) {
            Scene s = Parser.parse("""
                    Width 9
                    Height 9
                    MaxDepth 20
                    BGColor [1 1 1]

                    Camera Camera
                    Vector3d eye [0 0 0]
                    Vector3d target [0 0 -1]
                    double yFOV 120

                    Material Dielectric glass
                    double refractiveIndex %s
                    Vector3d attenuation [0 0.1 0.5]
                    String fresnel exact

                    Surface Sphere
                    Vector3d center [0 0 0]
                    double radius 1
                    ref material glass
                    """.formatted(Double.toString(n)), "inside.txt", new ArrayList<>());
            Vector3d[][] img = s.renderAll();
            double r0 = ((n - 1) / (n + 1)) * ((n - 1) / (n + 1));
            for (int k = 0; k < 3; k++) {
                // 1 + R0 exp(-2a) + R0^2 exp(-4a) + ... times (1 - R0) exp(-a), up to depth 20
                double expected = 0;
                for (int bounce = 0; bounce < 20; bounce++) {
                    expected += (1 - r0) * Math.pow(r0, bounce) * Math.exp(-ABSORB[k] * (1 + 2 * bounce));
                }
                for (Vector3d[] column : img) {
                    for (Vector3d p : column) {
                        double got = k == 0 ? p.x : k == 1 ? p.y : p.z;
                        assertEquals(expected, got, 1e-9, "n " + n + " channel " + k);
                    }
                }
            }
        }
    }

    /** Past the critical angle from inside, nothing is refracted: only the reflected ray is cast. */
    @Test
    void totalInternalReflectionCastsNoRefractedRay() throws Exception {
        Scene s = slab("schlick", 5, N);
        // from inside the sphere, hitting it at 60 degrees to the normal: sin 60 * 1.5 = 1.3 > 1
        assertEquals("0 0", raysCast(s, 60, 5), "a ray at MaxDepth casts nothing");
        assertEquals("1 0", raysCast(s, 60, 4), "one reflection (whose hit, at MaxDepth, casts nothing)");
        assertEquals("2 0", raysCast(s, 60, 3), "a chord keeps its angle: reflected again, never refracted");
        // at 30 degrees (sin 30 * 1.5 = 0.75) the same ray is refracted as well
        assertEquals("1 1", raysCast(s, 30, 4), "below the critical angle");
    }

    /**
     * "mirror refraction" rays cast for a ray at {@code depth} going +z from (sin i, 0, 0) inside the
     * unit sphere: it meets the sphere at {@code degrees} to the normal.
     */
    private static String raysCast(Scene s, double degrees, int depth) {
        TraceContext ctx = new TraceContext(s.maxDepth);
        double a = Math.toRadians(degrees);
        Ray r = new Ray(new Vector3d(Math.sin(a), 0, 0), new Vector3d(0, 0, 1));
        r.depth = depth;
        s.traceCamera(r, ctx, new Vector3d());
        return ctx.stats.get(RayKind.MIRROR) + " " + ctx.stats.get(RayKind.REFRACTION);
    }

    /** A refracted ray's direction obeys Snell's law and stays in the plane of incidence. */
    @Test
    void refractedRayBendsBySnellsLaw() throws Exception {
        // a ray at 45 degrees hits a glass ball at its top; the refracted ray goes on to the wall
        Scene s = slab("exact", 1, N);
        double a = Math.toRadians(45);
        Ray r = new Ray(new Vector3d(-Math.sin(a) * 3, 1 + Math.cos(a) * 3, 0), new Vector3d(Math.sin(a), -Math.cos(a), 0));
        TraceContext ctx = new TraceContext(s.maxDepth);
        Vector3d out = new Vector3d();
        s.traceCamera(r, ctx, out);
        Ray refracted = ctx.ray(1);   // the last ray cast at depth 1 is the refracted one
        Vector3d t = new Vector3d(refracted.direction);
        t.normalize();
        assertEquals(Math.sin(a), N * t.x, 1e-12, "n1 sin(i) = n2 sin(t), normal +y at the top");
        assertEquals(0, t.z, 1e-15, "in the plane of incidence");
        assertTrue(t.y < 0, "goes on into the glass");
        assertEquals(1, refracted.origin.y, 1e-12, "starts at the hit point");
        assertTrue(refracted.origin.y < 1, "offset to the inside");
    }

    @Test
    void badFieldsAreRejectedWithTheirLine() {
        String[][] cases = {
                {"double refractiveIndex 0", "refractiveIndex must be a finite number > 0, got 0.0"},
                {"double refractiveIndex -1.5", "refractiveIndex must be a finite number > 0"},
                {"Vector3d attenuation [0 -1 0]", "attenuation must be >= 0 in each channel"},
                {"String fresnel Schlick", "fresnel must be schlick or exact, got 'Schlick'"},
        };
        for (String[] c : cases) {
            ObjectErrors.assertRefused("Material DielectricMaterial", c[0], c[1]);
        }
    }
}
