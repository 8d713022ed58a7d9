package ray.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;

/**
 * One dielectric shading, taken apart: the hit is at the origin on the plane z = 0 (normal +z, facing
 * the ray), inside a large sphere whose material shows where a ray went: red for a ray going up (the
 * reflection), blue for one going down (the refraction). So the colour is (k R, 0, k (1 - R)): R and the
 * Beer factor k per channel can be read off and compared with Fresnel's formulas, entering and leaving.
 */
class DielectricShadeTest {

    /** Red for a ray going up, blue for a ray going down. */
    static final class Compass extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return ray.direction.z > 0 ? new Vector3d(1, 0, 0) : new Vector3d(0, 0, 1);
        }
    }

    private static Scene compassScene() {
        Scene s = new Scene();
        s.camera = new Camera();
        Sphere sky = new Sphere();
        sky.radius = 100;
        sky.material = new Compass();
        sky.init();
        s.surfaces.add(sky);
        return s;
    }

    private static DielectricMaterial glass(String fresnel, double ax, double ay, double az) {
        DielectricMaterial g = new DielectricMaterial();
        g.refractiveIndex = 1.5;
        g.fresnel = fresnel;
        g.attenuation = new Vector3d(ax, ay, az);
        g.init();
        return g;
    }

    /** A ray arriving at the origin at {@code degrees} from the normal, with direction length {@code len}. */
    private static Ray arriving(double degrees, double len) {
        double a = Math.toRadians(degrees);
        Vector3d d = new Vector3d(Math.sin(a) * len, 0, -Math.cos(a) * len);
        Vector3d o = new Vector3d(-d.x * 2 / len, 0, -d.z * 2 / len);   // 2 units back along the ray
        return new Ray(o, d);
    }

    private static IntersectionRecord hit(boolean frontFace, double t) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.normal.set(0, 0, 1);
        rec.frontFace = frontFace;
        rec.t = t;
        rec.error = 1e-12;
        return rec;
    }

    private static Vector3d shade(Material m, Ray ray, IntersectionRecord rec, Scene s) {
        Vector3d out = new Vector3d(Double.NaN, Double.NaN, Double.NaN);
        m.shade(ray, rec, s, new TraceContext(s.maxDepth), out);
        return out;
    }

    @Test
    void reflectanceEnteringAndLeavingIsSchlicksOrFresnelsAtTheOutsideAngle() {
        Scene s = compassScene();
        double cosI = Math.cos(Math.toRadians(40));
        for (String f : new String[] {"schlick", "exact"}) {
            DielectricMaterial g = glass(f, 0, 0, 0);
            // entering: outside angle 40 degrees, inside cosT by Snell with eta = 1 / 1.5
            double cosT = Fresnel.cosTransmitted(1 / 1.5, cosI);
            double r = f.equals("exact") ? Fresnel.exact(1, 1.5, cosI, cosT) : Fresnel.schlick(1.5, cosI);
            Vector3d c = shade(g, arriving(40, 1), hit(true, 2), s);
            assertEquals(r, c.x, 1e-12, f + " entering: R in " + c);
            assertEquals(1 - r, c.z, 1e-12, f + " entering: 1 - R in " + c);
            // leaving: inside angle 20 degrees (below the critical angle), Schlick at the outside angle
            double cosIn = Math.cos(Math.toRadians(20)), cosOut = Fresnel.cosTransmitted(1.5, cosIn);
            double rl = f.equals("exact") ? Fresnel.exact(1.5, 1, cosIn, cosOut) : Fresnel.schlick(1.5, cosOut);
            c = shade(g, arriving(20, 1), hit(false, 2), s);
            assertEquals(rl, c.x, 1e-12, f + " leaving: R in " + c);
            assertEquals(1 - rl, c.z, 1e-12, f + " leaving: 1 - R in " + c);
        }
        assertEquals(Fresnel.schlick(1.5, Math.cos(Math.toRadians(40))), shade(glass("schlick", 0, 0, 0), arriving(40, 1), hit(true, 2), s).x,
                1e-12);
    }

    /** The ray's direction need not have unit length: the same shading for a direction of length 3. */
    @Test
    void directionLengthDoesNotMatter() {
        Scene s = compassScene();
        DielectricMaterial g = glass("schlick", 0.3, 0.2, 0.1);
        for (boolean front : new boolean[] {true, false}) {
            Vector3d unit = shade(g, arriving(25, 1), hit(front, 2), s);
            Vector3d three = shade(g, arriving(25, 3), hit(front, 2.0 / 3), s);   // same distance: t |d| = 2
            assertEquals(unit.x, three.x, 1e-12, "front " + front + ": " + unit + " vs " + three);
            assertEquals(unit.z, three.z, 1e-12, "front " + front + ": " + unit + " vs " + three);
        }
        assertEquals(new Vector3d(0, 0, 0), shade(g, new Ray(new Vector3d(0, 0, 1), new Vector3d(0, 0, 0)), hit(true, 1), s),
                "a ray without a direction: black");
    }

    /** Leaving the glass, each channel is attenuated by exp(-a d) with its own a, d = t |direction|; entering, not at all. */
    @Test
    void beerAttenuatesEachChannelOnTheWayOut() {
        Scene s = compassScene();
        double d = 2 * 2;   // t = 2 along a direction of length 2
        double[][] as = {{0.5, 0, 0}, {0, 0.5, 0}, {0, 0, 0.5}, {0.1, 0.2, 0.3}};
        for (double[] a : as) {
            DielectricMaterial g = glass("schlick", a[0], a[1], a[2]);
            DielectricMaterial clear = glass("schlick", 0, 0, 0);
            Vector3d out = shade(g, arriving(10, 2), hit(false, 2), s), ref = shade(clear, arriving(10, 2), hit(false, 2), s);
            assertEquals(ref.x * Math.exp(-a[0] * d), out.x, 1e-12, "red, a = " + java.util.Arrays.toString(a));
            assertEquals(0, out.y, 0);
            assertEquals(ref.z * Math.exp(-a[2] * d), out.z, 1e-12, "blue, a = " + java.util.Arrays.toString(a));
            Vector3d in = shade(g, arriving(10, 2), hit(true, 2), s), inClear = shade(clear, arriving(10, 2), hit(true, 2), s);
            assertEquals(inClear, in, "entering: no attenuation");
        }
        // green: a compass that answers white both ways shows the green channel's factor
        Scene white = compassScene();
        white.surfaces.get(0).material = new Material() {
            @Override
            public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
                return new Vector3d(1, 1, 1);
            }
        };
        Vector3d g = shade(glass("schlick", 0, 0.5, 0), arriving(10, 2), hit(false, 2), white);
        assertEquals(Math.exp(-0.5 * d), g.y, 1e-12, "green attenuated alone: " + g);
        assertEquals(1, g.x, 1e-12);
    }

    @Test
    void colorsMustBeFiniteNumbers() {
        for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY}) {
            assertThrows(IllegalArgumentException.class, () -> glass("schlick", bad, 0, 0), "attenuation " + bad);
            Diffuse d = new Diffuse();
            d.ambientColor = new Vector3d(0, bad, 0);
            assertThrows(IllegalArgumentException.class, d::init, "ambientColor " + bad);
            Diffuse e = new Diffuse();
            e.diffuseColor = new Vector3d(0, 0, bad);
            assertThrows(IllegalArgumentException.class, e::init, "diffuseColor " + bad);
            BlinnPhong b = new BlinnPhong();
            b.specularColor = new Vector3d(bad, 0, 0);
            assertThrows(IllegalArgumentException.class, b::init, "specularColor " + bad);
            BlinnPhong base = new BlinnPhong();
            base.diffuseColor = new Vector3d(bad, 0, 0);
            assertThrows(IllegalArgumentException.class, base::init, "a BlinnPhong checks what it inherits: diffuseColor " + bad);
        }
    }

    /**
     * Outside a planned render (no plan cached) a Diffuse surface still adds k_a I_a per channel, and a
     * BlinnPhong highlight does not depend on the length of the viewing ray's direction.
     */
    @Test
    void unplannedAmbientPerChannelAndHighlightForAnyDirectionLength() {
        Scene s = new Scene();
        s.camera = new Camera();
        s.ambientLight = new Vector3d(0.5, 0.25, 0.125);
        Diffuse d = new Diffuse();
        d.ambientColor = new Vector3d(0.2, 0.4, 0.8);
        d.init();
        IntersectionRecord rec = hit(true, 5);
        rec.location.set(0, 0, 0);
        Vector3d c = shade(d, new Ray(new Vector3d(0, 0, 5), new Vector3d(0, 0, -1)), rec, s);
        assertEquals(new Vector3d(0.1, 0.1, 0.1), c, "k_a I_a with no light");
        BlinnPhong b = new BlinnPhong();
        b.diffuseColor = new Vector3d(0, 0, 0);
        b.exponent = 3;
        b.init();
        ray.light.PointLight l = new ray.light.PointLight();
        l.position = new Vector3d(3, 0, 4);
        l.intensity = new Vector3d(25, 25, 25);
        l.init();
        s.lights.add(l);
        s.ambientLight = new Vector3d();
        Ray one = new Ray(new Vector3d(-1, 0, 2), new Vector3d(0.5, 0, -1));   // arriving at the origin
        Ray four = new Ray(new Vector3d(-1, 0, 2), new Vector3d(2, 0, -4));
        Vector3d h1 = shade(b, one, hit(true, 2), s), h4 = shade(b, four, hit(true, 0.5), s);
        // h = normalize(l + v) with l = (0.6, 0, 0.8), v = (-1, 0, 2) / sqrt 5; I / r^2 = 1
        double vx = -1 / Math.sqrt(5), vz = 2 / Math.sqrt(5), hx = 0.6 + vx, hz = 0.8 + vz;
        double nh = hz / Math.sqrt(hx * hx + hz * hz);
        assertEquals(Math.pow(nh, 3), h1.x, 1e-12, "the highlight " + h1);
        assertEquals(h1.x, h4.x, 1e-12, "a direction four times longer: " + h4);
    }
}
