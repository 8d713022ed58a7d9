package ray.light;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Scene;

/**
 * {@link Light#sample} says "no light" exactly when none arrives: a light on the shading point, a point so
 * far away that I / r^2 is no number, a user light whose getIntensity gives black or nothing. A sample that
 * wrongly says "light" would make a material add an infinite or NaN term, or cast a useless shadow ray.
 */
class LightSampleContractTest {

    static IntersectionRecord at(double x, double y, double z) {
        IntersectionRecord rec = new IntersectionRecord();
        rec.location.set(x, y, z);
        rec.normal.set(0, 0, 1);
        return rec;
    }

    static Scene empty() {
        Scene s = new Scene();
        s.camera = new Camera();
        return s;
    }

    private static PointLight point(double x, double y, double z) {
        PointLight l = new PointLight();
        l.position = new Vector3d(x, y, z);
        l.intensity = new Vector3d(25, 50, 75);
        l.init();
        return l;
    }

    @Test
    void pointLightSampleIsFalseOnTheLightAndBeyondReach() {
        LightSample out = new LightSample();
        assertFalse(point(1, 2, 3).sample(at(1, 2, 3), empty(), 0, out), "light on the point: no direction");
        assertFalse(point(0, 0, 0).sample(at(1e200, 0, 0), empty(), 0, out), "r^2 overflows: no finite amount");
        assertFalse(point(0, 0, 0).sample(at(1e-160, 0, 0), empty(), 0, out), "I / r^2 overflows");
        assertTrue(point(0, 0, 0).sample(at(1e-100, 0, 0), empty(), 0, out), "small but finite I / r^2");
        assertEquals(-1, out.direction.x, 0);
    }

    @Test
    void pointLightSampleDescribesTheLight() {
        LightSample out = new LightSample();
        out.shadowTested = true;
        assertTrue(point(0, 3, 4).sample(at(0, 0, 0), empty(), 0, out));
        assertEquals(new Vector3d(0, 0.6, 0.8), out.direction);
        assertEquals(new Vector3d(0, 3, 4), out.position);
        assertEquals(5, out.distance, 0);
        assertEquals(new Vector3d(1, 2, 3), out.intensity);
        assertFalse(out.shadowTested, "a point light's sample still needs its shadow ray");
    }

    @Test
    void spotLightSampleIsFalseOnTheLightAndWhereTheFalloffIsZero() {
        LightSample out = new LightSample();
        assertFalse(SpotLightTest.spot(new Vector3d(1, 2, 3), new Vector3d(0, 0, -1), 40, 1)
                .sample(at(1, 2, 3), empty(), 0, out), "light on the point");
        // a 180-degree cone lets everything in; cos^1 is zero at 90 degrees and max(0, cos) behind the light
        SpotLight wide = SpotLightTest.spot(new Vector3d(0, 0, 0), new Vector3d(0, 0, -1), 180, 1);
        assertFalse(wide.sample(at(0, 0, 5), empty(), 0, out), "behind the light, exponent 1");
        assertFalse(wide.sample(at(5, 0, 0), empty(), 0, out), "at 90 degrees, exponent 1");
        assertTrue(wide.sample(at(0, 0, -5), empty(), 0, out), "on the axis");
        SpotLight flat = SpotLightTest.spot(new Vector3d(0, 0, 0), new Vector3d(0, 0, -1), 180, 0);
        assertTrue(flat.sample(at(0, 0, 5), empty(), 0, out), "exponent 0 and 180 degrees: a point light");
        assertEquals(25.0 / 25, out.intensity.x, 1e-15);
    }

    /**
     * Inside the cone a spot light is the point light times cos^e of the angle to its axis, for an axis
     * given at any length and in general position: I / r^2 (cos t)^e per channel, exactly.
     */
    @Test
    void spotLightSampleIsThePointLightTimesCosineToTheExponent() {
        SpotLight s = SpotLightTest.spot(new Vector3d(0, 0, 0), new Vector3d(3, 6, 6), 60, 2);   // axis (1, 2, 2) / 3
        LightSample out = new LightSample();
        assertTrue(s.sample(at(1, 2, 3), empty(), 0, out));
        double cos = 11 / (3 * Math.sqrt(14)), f = cos * cos / 14;   // axis . (1, 2, 3) / |(1, 2, 3)|, r^2 = 14
        assertEquals(25 * f, out.intensity.x, 1e-14);
        assertEquals(50 * f, out.intensity.y, 1e-14);
        assertEquals(75 * f, out.intensity.z, 1e-14);
        // just outside and just inside a 20-degree cone around the same axis, at 1 degree either side
        SpotLight narrow = SpotLightTest.spot(new Vector3d(0, 0, 0), new Vector3d(3, 6, 6), 20, 0);
        Vector3d a = new Vector3d(1, 2, 2), side = new Vector3d(2, -1, 0);   // side is perpendicular to the axis
        a.normalize();
        side.normalize();
        for (double deg : new double[] {19, 21}) {
            double r = Math.toRadians(deg);
            IntersectionRecord p = at(a.x * Math.cos(r) + side.x * Math.sin(r), a.y * Math.cos(r) + side.y * Math.sin(r),
                    a.z * Math.cos(r) + side.z * Math.sin(r));
            assertEquals(deg < 20, narrow.sample(p, empty(), 0, out), deg + " degrees off a 20-degree spot's axis");
        }
    }

    @Test
    void spotLightValidatesWhatItInheritsAndItsOwnFields() {
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(Double.NaN, 0, 0), new Vector3d(0, 0, -1), 30, 1),
                "a spot light is a point light: its position must be finite");
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, 0), 30, 1), "zero direction");
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(), new Vector3d(1e308, 1e308, 0), 30, 1), "direction overflows");
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 0, 1), "cut-off 0");
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 180.0001, 1), "cut-off past 180");
        assertDoesNotThrow(() -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 180, 1), "cut-off 180");
        assertDoesNotThrow(() -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 1e-9, 0), "tiny cut-off");
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 30, -1e-9), "negative exponent");
        assertThrows(IllegalArgumentException.class,
                () -> SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 30, Double.POSITIVE_INFINITY));
    }

    @Test
    void darkIsZeroIntensityOnly() {
        SpotLight s = SpotLightTest.spot(new Vector3d(), new Vector3d(0, 0, -1), 30, 1);
        assertFalse(s.isDark());
        s.intensity = new Vector3d(0, 0, 0);
        assertTrue(s.isDark(), "a black spot light adds nothing");
        PointLight p = point(0, 0, 0);
        assertFalse(p.isDark());
        for (Vector3d one : new Vector3d[] {new Vector3d(1, 0, 0), new Vector3d(0, 1, 0), new Vector3d(0, 0, 1)}) {
            p.intensity = one;
            assertFalse(p.isDark(), "one channel lit: " + one);
        }
        p.intensity = new Vector3d();
        assertTrue(p.isDark());
        assertEquals(1, s.shadowRaysPerPoint());
        assertEquals(1, p.shadowRaysPerPoint());
    }

    /** A light written against the framework's getIntensity only. */
    private static final class UserLight extends Light {
        Vector3d value;

        UserLight(Vector3d value) {
            this.value = value;
        }

        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return value;
        }
    }

    @Test
    void userLightSamplesAreFalseExactlyWhenNothingArrives() {
        LightSample out = new LightSample();
        IntersectionRecord rec = at(1, 2, 3);
        rec.normal.set(0, 1, 0);
        assertFalse(new UserLight(null).sample(rec, empty(), 0, out), "null");
        assertFalse(new UserLight(new Vector3d()).sample(rec, empty(), 0, out), "black");
        assertFalse(new UserLight(new Vector3d(-1, -1, -1)).sample(rec, empty(), 0, out), "negative");
        assertFalse(new UserLight(new Vector3d(Double.NaN, 0, 0)).sample(rec, empty(), 0, out), "NaN");
        for (Vector3d lit : new Vector3d[] {new Vector3d(2, 0, 0), new Vector3d(0, 2, 0), new Vector3d(0, 0, 2)}) {
            assertTrue(new UserLight(lit).sample(rec, empty(), 0, out), "lit " + lit);
            assertEquals(lit, out.intensity);
        }
        // the light arrives along the normal, already shadowed, from the point itself
        assertEquals(new Vector3d(0, 1, 0), out.direction);
        assertEquals(new Vector3d(1, 2, 3), out.position);
        assertEquals(Double.POSITIVE_INFINITY, out.distance);
        assertTrue(out.shadowTested);
        UserLight user = new UserLight(new Vector3d(1, 1, 1));
        assertFalse(user.isDark(), "a user's light may light anything");
        assertEquals(Light.UNKNOWN_RAYS, user.shadowRaysPerPoint(), "and trace anything");
        assertEquals(1, user.sampleCount());
    }
}
