package ray.robust;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.add;
import static ray.robust.RobustSupport.atAngle;
import static ray.robust.RobustSupport.forEachSeed;
import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.sub;
import static ray.robust.RobustSupport.unit;
import static ray.robust.RobustSupport.unnormalised;

import java.util.List;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.light.LightSample;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * {@link IntersectionRecord#spawnRay} and {@link IntersectionRecord#spawnRayTo}: a ray leaving a hit
 * point never hits the surface it left again (the cause of shadow acne and of mirrors reflecting
 * themselves), at every scale and position, for grazing and unnormalised directions; and a surface a
 * light sits on does not shadow it.
 */
class SpawnRayTest {

    /** cos of the angle between a spawned direction and the normal: from grazing (1e-12) to straight out. */
    private static double cosine(Random r) {
        return r.nextInt(4) == 0 ? 1 : logUniform(r, 1e-12, 1);
    }

    /** A hit on {@code sp} by a ray from a random origin (outside or inside), or null when it missed. */
    private static IntersectionRecord randomHit(Random r, Sphere sp, Ray[] rayOut) {
        double rad = sp.radius;
        double rho = r.nextInt(3) == 0 ? logUniform(r, 1e-3, 1) : logUniform(r, 1, 1e4);
        Vector3d o = add(sp.center, rad * rho, unit(r));
        Vector3d d = unnormalised(r, sub(add(sp.center, rad, unit(r)), o));
        Ray ray = new Ray(o, d);
        ray.tMin = 0;
        rayOut[0] = ray;
        IntersectionRecord rec = new IntersectionRecord();
        return sp.intersects(ray, rec, null) ? rec : null;
    }

    /**
     * Trap: self-intersection. A fixed epsilon (tMin = 1e-4, or an offset of 1e-4) is too small for a
     * sphere of radius 1e6 far from the origin or for a short direction vector, and too large for one of
     * radius 1e-6. Rays leaving the outside of a sphere (any direction into the outer half-space, down
     * to 1e-12 from tangent) never hit it; rays leaving the inside into the interior only hit the far side.
     */
    @Test
    void rayLeavingSphereNeverRehitsIt() {
        forEachSeed(0x5a3eL, 20000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e6));
            Sphere sp = RobustSupport.sphere(c, s * logUniform(r, 0.1, 10));
            Ray[] in = new Ray[1];
            IntersectionRecord rec = randomHit(r, sp, in);
            if (rec == null) {
                return;
            }
            double cos = cosine(r);
            Vector3d dir = unnormalised(r, atAngle(r, rec.normal, cos));
            Ray out = rec.spawnRay(dir);
            IntersectionRecord again = new IntersectionRecord();
            boolean hit = sp.intersects(out, again, null);
            if (rec.frontFace) {
                assertFalse(hit, "ray leaving the outside (cos " + cos + ") hit the sphere again at t " + again.t + " ("
                        + again.location + "); first hit " + rec + ", " + sp + ", spawned " + out);
            } else if (hit) {
                // inside: the far side is 2 r cos away; the record's error bound is the resolution
                double chord = 2 * sp.radius * cos;
                double travelled = sub(again.location, rec.location).length();
                assertTrue(travelled >= 0.5 * chord - 8 * rec.error, "ray leaving the inside re-hit " + travelled
                        + " from its start (chord " + chord + "); " + rec + ", " + sp + ", spawned " + out);
            }
        });
    }

    /**
     * Trap: a shadow ray re-hitting its own surface (acne) or, for a one-sided mesh, the neighbouring
     * triangle across an edge. A shadow ray from a hit on the outside of a sphere to a random point above
     * the hit's tangent plane (at 1e-6 to 1e6 radii, from 1e-9 to 1 in cosine, but higher above the plane
     * than 4 error bounds: closer is on the surface to the precision the hit is known) is never blocked.
     */
    @Test
    void shadowRayFromSphereToOutsidePointIsNotBlockedByIt() {
        forEachSeed(0x5ad0L, 20000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e6));
            Sphere sp = RobustSupport.sphere(c, s * logUniform(r, 0.1, 10));
            Ray[] in = new Ray[1];
            IntersectionRecord rec = randomHit(r, sp, in);
            if (rec == null || !rec.frontFace) {
                return;
            }
            double dist = sp.radius * logUniform(r, 1e-6, 1e6), cos = logUniform(r, 1e-9, 1);
            if (dist * cos < 4 * rec.error) {
                return;       // a target within the hit point's own rounding error is on the surface, not above it
            }
            Vector3d target = add(rec.location, dist, atAngle(r, rec.normal, cos));
            Ray shadow = rec.spawnRayTo(target);
            IntersectionRecord again = new IntersectionRecord();
            assertFalse(sp.intersects(shadow, again, null), "shadow ray to " + target + " blocked by its own sphere at t "
                    + again.t + "; " + rec + ", " + sp + ", shadow " + shadow);
        });
    }

    /**
     * Trap: on a convex mesh, a ray leaving one triangle near an edge hitting the neighbour (the offset
     * must clear every triangle of the mesh, not just the one hit). Icospheres and boxes at any scale and
     * position; rays leave random hits in outward directions down to 1e-9 from tangent, and shadow rays go
     * to points more than 4 error bounds above the hit's plane; no triangle of the mesh may be hit, checked
     * through the BVH.
     */
    @Test
    void rayLeavingConvexMeshNeverRehitsIt() {
        forEachSeed(0xc0e7L, 60, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d t = unit(r);
            t.scale(s * logUniform(r, 1e-3, 1e6));
            ClosedMesh m = (r.nextBoolean() ? ClosedMesh.icosphere(2) : ClosedMesh.cubeGrid(4)).transformed(s, new Vector3d(1, 1, 1), t);
            List<Triangle> tris = m.triangles();
            Scene scene = RobustSupport.scene(tris);
            int tested = 0;
            for (int i = 0; i < 300; i++) {
                Vector3d o = add(t, s * logUniform(r, 2, 1e4), unit(r));
                Vector3d aim = add(t, s * 0.9, unit(r));
                Ray ray = new Ray(o, unnormalised(r, sub(aim, o)));
                ray.tMin = 0;
                IntersectionRecord rec = new IntersectionRecord();
                if (!scene.intersect(ray, rec)) {
                    continue;
                }
                tested++;
                double cos = r.nextInt(4) == 0 ? 1 : logUniform(r, 1e-9, 1);
                Ray out = rec.spawnRay(unnormalised(r, atAngle(r, rec.normal, cos)));
                IntersectionRecord again = new IntersectionRecord();
                assertFalse(scene.intersect(out, again), "ray leaving " + rec + " (cos " + cos + ") hit the convex mesh again at "
                        + again + "; spawned " + out);
                double dist = s * logUniform(r, 1e-6, 1e6);
                if (dist * cos < 4 * rec.error) {
                    continue;
                }
                Ray shadow = rec.spawnRayTo(add(rec.location, dist, atAngle(r, rec.normal, cos)));
                assertFalse(scene.occluded(shadow), "shadow ray from " + rec + " (cos " + cos + ") blocked by the convex mesh");
            }
            assertTrue(tested > 100, "too few hits: " + tested);
        });
    }

    /**
     * Trap: a light sitting exactly on a surface (a lamp on a wall, a light at a sphere's top) being
     * shadowed by that surface, because the shadow ray reaches the surface at t = 1 up to rounding. The
     * scene format says the surface does not shadow it. Lights at a point of a sphere or a triangle
     * (rounded, so maybe an ulp inside) up to a million sizes from the origin, seen from 1e-5 to 1e2
     * sizes away at angles from 1e-3 to 1 (in cosine) to the surface.
     */
    @Test
    void surfaceALightSitsOnDoesNotShadowIt() {
        forEachSeed(0x119e7L, 20000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e6));
            Surface on;
            Vector3d light, n;
            if (r.nextBoolean()) {
                Sphere sp = RobustSupport.sphere(c, s);
                n = unit(r);
                light = add(c, s, n);
                on = sp;
            } else {
                Vector3d a = add(c, s, unit(r)), b = add(c, s, unit(r)), d = add(c, s, unit(r));
                Triangle tri = RobustSupport.triangle(a, b, d);
                if (tri.isDegenerate()) {
                    return;
                }
                double u = r.nextDouble(), v = r.nextDouble() * (1 - u);
                light = add(add(a, u, sub(b, a)), v, sub(d, a));
                n = new Vector3d();
                n.cross(sub(b, a), sub(d, a));
                n.normalize();
                on = tri;
            }
            // a shading point on a small sphere that sees the light from the front of `on`
            Vector3d dir = atAngle(r, n, logUniform(r, 1e-3, 1));
            double dist = s * logUniform(r, 1e-5, 1e2);
            Vector3d p = add(light, dist, dir);
            Sphere viewer = RobustSupport.sphere(p, dist * 1e-3);
            Scene scene = RobustSupport.scene(List.of(on, viewer));
            // hit the viewer sphere on the side facing the light
            Vector3d toLight = sub(light, p);
            toLight.normalize();
            Vector3d from = add(p, dist * 2e-3, toLight);
            Ray ray = new Ray(from, sub(p, from));
            ray.tMin = 0;
            IntersectionRecord rec = new IntersectionRecord();
            assertTrue(scene.intersect(ray, rec), "missed the viewer sphere");
            LightSample sample = new LightSample();
            sample.position.set(light);
            assertFalse(scene.occluded(rec, sample), "the " + on.getClass().getSimpleName() + " the light sits on shadows it: light "
                    + light + ", " + on + ", shading point " + rec.location);
        });
    }

    /**
     * Trap: offsetting along the wrong side, or by the direction instead of the normal. The spawned
     * origin lies on the side of the surface the ray leaves to, within a few error bounds of the hit.
     */
    @Test
    void spawnedOriginIsOnTheLeavingSideAndClose() {
        forEachSeed(0x0ff5e7L, 5000, r -> {
            double s = logUniform(r, 1e-6, 1e6);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e6));
            Sphere sp = RobustSupport.sphere(c, s);
            Ray[] in = new Ray[1];
            IntersectionRecord rec = randomHit(r, sp, in);
            if (rec == null) {
                return;
            }
            double sign = r.nextBoolean() ? 1 : -1;
            Vector3d dir = atAngle(r, rec.normal, sign * logUniform(r, 1e-6, 1));
            Ray out = rec.spawnRay(dir);
            double side = RobustSupport.sphereResidual(out.origin, c, s) * (rec.frontFace ? 1 : -1) * sign;
            assertTrue(side > 0, "spawned origin not on the leaving side: residual " + side + ", " + rec);
            double moved = sub(out.origin, rec.location).length();
            assertTrue(moved <= 4 * rec.error, "spawned origin " + moved + " from the hit, error bound " + rec.error);
        });
    }
}
