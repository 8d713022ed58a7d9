package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static ray.robust.RobustSupport.EPS;
import static ray.robust.RobustSupport.add;
import static ray.robust.RobustSupport.atAngle;
import static ray.robust.RobustSupport.forEachSeed;
import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.maxAbs;
import static ray.robust.RobustSupport.sphereResidual;
import static ray.robust.RobustSupport.sub;
import static ray.robust.RobustSupport.unit;
import static ray.robust.RobustSupport.unnormalised;

import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import ray.Camera;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.surface.Sphere;

/**
 * The ray/sphere test (Haines et al., Ray Tracing Gems ch. 7, plus re-projection of the hit point) at
 * scales from 1e-6 to 1e6: hit points on the surface, clean hits and misses near the silhouette of small
 * spheres far away and of huge spheres close up, no speckles in a rendered disk.
 */
class SphereRobustnessTest {

    /** A sphere of radius ~s at up to a million radii from the origin. */
    private static Sphere randomSphere(Random r, double s) {
        Vector3d c = unit(r);
        c.scale(s * logUniform(r, 1e-3, 1e6));
        return RobustSupport.sphere(c, s * logUniform(r, 0.1, 10));
    }

    /**
     * Trap: a hit point computed as o + t d from a far origin (or from the textbook quadratic's t) lies off
     * the sphere by the rounding of t times |d|, which grows with the distance travelled, not with the
     * point's own magnitude; spawned rays then start inside. The hit point must lie within
     * 4 eps (|p| + r) of the sphere (the rounding of c + r n), and within the record's own error bound.
     */
    @Test
    void hitPointLiesOnSphereWithinRelativeBound() {
        forEachSeed(0x5e7e7eL, 10000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Sphere sp = randomSphere(r, s);
            double rad = sp.radius;
            // origin from just off the surface (either side) to ten thousand radii away
            double rho = r.nextBoolean() ? 1 + (r.nextBoolean() ? 1 : -1) * logUniform(r, 1e-9, 0.5) : logUniform(r, 1, 1e4);
            Vector3d o = add(sp.center, rad * rho, unit(r));
            // aim at a random point of the sphere, so the line surely meets it
            Vector3d q = add(sp.center, rad, unit(r));
            Vector3d d = unnormalised(r, sub(q, o));
            Vector3d nq = sub(q, sp.center);
            nq.normalize();
            double cos = Math.abs(nq.dot(d)) / d.length();
            Ray ray = new Ray(o, d);
            ray.tMin = 0;
            IntersectionRecord rec = new IntersectionRecord();
            boolean hit = sp.intersects(ray, rec, null);
            if (!hit) {
                // only a near-tangent line may miss (it touches within rounding)
                assertTrue(cos < 1e-6, "missed a sphere the ray enters at cos " + cos + ": " + sp + ", " + ray);
                return;
            }
            Vector3d p = rec.location;
            double bound = 4 * EPS * (maxAbs(p) + rad);
            double res = Math.abs(sphereResidual(p, sp.center, rad));
            assertTrue(res <= bound, "hit point " + res + " off the sphere (bound " + bound + "): " + rec + ", " + sp + ", " + ray);
            assertTrue(res <= rec.error, "record's error bound " + rec.error + " is below the actual error " + res);
            assertEquals(1, rec.normal.length(), 1e-12, "normal not unit: " + rec);
            assertTrue(rec.normal.dot(d) <= 0, "normal does not face the ray: " + rec);
            if (rho > 1 + 1e-6) {
                // from outside, the first hit is on the near side: the outward normal faces the ray
                assertTrue(rec.frontFace, "hit the far side from outside: " + rec + ", " + ray);
            }
        });
    }

    /**
     * Trap: the textbook discriminant b^2 - a c cancels catastrophically for a small sphere far away
     * (both terms are ~D^2 |d|^2, their difference ~r^2 |d|^2: at D / r = 1e8 the rounding of each is
     * as large as the difference), so rays aimed
     * well inside the disk miss and rays well outside hit, as speckles. Rays aimed at 0.99 r from the
     * centre must hit, at 1.01 r must miss, for distances up to 1e10 radii.
     */
    @Test
    void smallSphereFarAwayHitsInsideAndMissesOutside() {
        forEachSeed(0xfa7L, 4000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e3));
            Sphere sp = RobustSupport.sphere(c, s);
            Vector3d dir = unit(r);
            Vector3d o = add(c, s * logUniform(r, 1e2, 1e10), dir);
            for (double f : new double[] {0, 0.5, 0.99, 1.01, 2}) {
                Vector3d aim = add(c, s * f, atAngle(r, dir, 0));   // a point at f r, perpendicular to the view line
                Vector3d d = unnormalised(r, sub(aim, o));
                Ray ray = new Ray(o, d);
                ray.tMin = 0;
                IntersectionRecord rec = new IntersectionRecord();
                boolean hit = sp.intersects(ray, rec, null);
                assertEquals(f < 1, hit, "ray aimed at " + f + " r from the centre of " + sp + ": " + (hit ? "hit" : "missed")
                        + ", " + ray);
            }
        });
    }

    /**
     * Trap: a huge sphere seen from close up (radius up to 1e9 times the eye's height above it): the
     * constant term |o - c|^2 - r^2 and the discriminant both cancel. Rays below the horizon (closest
     * approach 1% of the height inside the surface) must hit near the expected point, rays above it
     * (1% outside) must miss, rays straight down must hit at the height.
     */
    @Test
    void hugeSphereUpCloseHitsBelowAndMissesAboveHorizon() {
        forEachSeed(0x4a9eL, 4000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            double rad = s * logUniform(r, 1e3, 1e9);
            double h = s * logUniform(r, 1e-3, 1);
            Vector3d c = unit(r);
            c.scale(rad * logUniform(r, 1e-3, 1));
            Sphere sp = RobustSupport.sphere(c, rad);
            Vector3d up = unit(r);
            Vector3d o = add(c, rad + h, up);
            double dist = (rad + h);
            // straight down: hits at distance h
            Vector3d down = new Vector3d(up);
            down.scale(-logUniform(r, 1e-3, 1e3));
            Ray ray = new Ray(o, down);
            ray.tMin = 0;
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(sp.intersects(ray, rec, null), "missed straight down: " + sp + ", " + ray);
            assertEquals(h, rec.t * down.length(), 1e-6 * h + 8 * EPS * (maxAbs(c) + rad), "distance straight down");
            for (double miss : new double[] {-0.01, 0.01}) {
                // a ray whose line passes the centre at rad + miss * h: sin(angle from -up) = that / dist
                double sin = (rad + miss * h) / dist;
                Vector3d side = atAngle(r, up, 0);
                Vector3d d = new Vector3d();
                d.scaleAdd(-Math.sqrt(Math.max(0, 1 - sin * sin)), up, d);
                d.scaleAdd(sin, side, d);
                d = unnormalised(r, d);
                Ray g = new Ray(o, d);
                g.tMin = 0;
                boolean hit = sp.intersects(g, new IntersectionRecord(), null);
                assertEquals(miss < 0, hit, "grazing ray passing " + miss + " h from the surface of " + sp + " (h = " + h + "): "
                        + (hit ? "hit" : "missed") + ", " + g);
            }
        });
    }

    /**
     * Trap: speckles at a silhouette: pixels whose rays pass clearly inside a distant sphere's outline
     * rendered as background, or clearly outside as sphere. A sphere of radius r seen from D = 1e2, 1e5
     * and 1e8 radii with a field of view that makes it fill the image; each pixel is checked against the
     * exact distance of its ray from the centre (computed independently); only pixels within 1e-6 r of
     * the outline may go either way.
     */
    @ParameterizedTest(name = "distance {0} radii, scale {1}")
    @CsvSource({"1e2, 1", "1e5, 1e-4", "1e8, 1", "1e8, 1e4", "1e5, 3e5"})
    void distantSphereRendersAsCleanDisk(double distance, double scale) {
        Vector3d c = new Vector3d(0.3 * scale, -0.7 * scale, 0.2 * scale);
        double rad = scale;
        Sphere sp = RobustSupport.sphere(c, rad);
        Scene scene = RobustSupport.scene(List.of(sp));
        Camera cam = scene.camera;
        cam.eye.set(add(c, distance * rad, new Vector3d(0.48, 0.6, 0.64)));
        cam.target.set(c);
        cam.up.set(0, 1, 0);
        cam.yFOV = Math.toDegrees(2 * Math.atan(1.5 / distance));    // the disk spans 2/3 of the height
        cam.aspect = 96.0 / 72;
        cam.init();
        int wrong = 0;
        String first = null;
        for (int j = 0; j < 72; j++) {
            for (int i = 0; i < 96; i++) {
                Ray ray = cam.getRayThrough(i + 0.5, j + 0.5, 96, 72);
                double miss = lineDistance(ray, c) / rad - 1;   // > 0: the line passes outside
                if (Math.abs(miss) < 1e-6) {
                    continue;
                }
                boolean hit = scene.intersect(ray, new IntersectionRecord());
                if (hit != (miss < 0)) {
                    wrong++;
                    if (first == null) {
                        first = "pixel (" + i + ", " + j + ") passes " + miss + " r " + (miss < 0 ? "inside" : "outside") + " but "
                                + (hit ? "hit" : "missed");
                    }
                }
            }
        }
        assertEquals(0, wrong, wrong + " speckled pixels; first: " + first);
    }

    /** Distance of c from the ray's line, in 60-digit arithmetic. */
    private static double lineDistance(Ray ray, Vector3d c) {
        java.math.MathContext mc = new java.math.MathContext(60);
        java.math.BigDecimal[] f = {
            new java.math.BigDecimal(c.x).subtract(new java.math.BigDecimal(ray.origin.x)),
            new java.math.BigDecimal(c.y).subtract(new java.math.BigDecimal(ray.origin.y)),
            new java.math.BigDecimal(c.z).subtract(new java.math.BigDecimal(ray.origin.z))};
        java.math.BigDecimal[] d = {
            new java.math.BigDecimal(ray.direction.x), new java.math.BigDecimal(ray.direction.y), new java.math.BigDecimal(ray.direction.z)};
        java.math.BigDecimal ff = f[0].multiply(f[0]).add(f[1].multiply(f[1])).add(f[2].multiply(f[2]));
        java.math.BigDecimal dd = d[0].multiply(d[0]).add(d[1].multiply(d[1])).add(d[2].multiply(d[2]));
        java.math.BigDecimal fd = f[0].multiply(d[0]).add(f[1].multiply(d[1])).add(f[2].multiply(d[2]));
        // |f|^2 - (f.d)^2 / |d|^2
        java.math.BigDecimal d2 = ff.subtract(fd.multiply(fd).divide(dd, mc));
        return Math.sqrt(Math.max(0, d2.doubleValue()));
    }

    /** Trap: a zero or infinite direction producing NaN t accepted as a hit (NaN comparisons are false). */
    @Test
    void degenerateDirectionsMiss() {
        Sphere sp = RobustSupport.sphere(new Vector3d(0, 0, -5), 1);
        for (Vector3d d : new Vector3d[] {new Vector3d(0, 0, 0), new Vector3d(0, 0, -1e300), new Vector3d(Double.NaN, 0, -1),
            new Vector3d(0, 0, Double.NEGATIVE_INFINITY)}) {
            Ray ray = new Ray(new Vector3d(), d);
            IntersectionRecord rec = new IntersectionRecord();
            if (sp.intersects(ray, rec, null)) {
                if (!(Double.isFinite(rec.t) && Double.isFinite(maxAbs(rec.location)) && Double.isFinite(maxAbs(rec.normal)))) {
                    fail("non-finite hit for direction " + d + ": " + rec);
                }
            }
        }
    }
}
