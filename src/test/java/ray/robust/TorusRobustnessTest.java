package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.add;
import static ray.robust.RobustSupport.forEachSeed;
import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.unit;

import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.Torus;

/**
 * The torus's quartic at grazing angles, where closed-form solvers lose their digits: lines in the
 * torus's plane a relative 1e-6..1e-2 inside (outside) its outer silhouette hit (miss), and lines
 * skimming the top of the tube a relative 1e-6..1e-2 below (above) it hit (miss), at scales 1e-4..1e4,
 * up to 1e4 sizes from the origin, seen from up to 1e4 sizes away, with unnormalised directions.
 */
class TorusRobustnessTest {

    /** A random torus and an orthonormal frame (e1, e2 in its plane, w its axis). */
    private static final class Setup {
        final Torus torus;
        final Vector3d e1, e2, w;
        final double big, small;

        Setup(Random r) {
            double s = logUniform(r, 1e-4, 1e4);
            Vector3d c = unit(r);
            c.scale(s * logUniform(r, 1e-3, 1e4));
            w = unit(r);
            e1 = ClosedShapes.perpendicular(r, w);
            e2 = new Vector3d();
            e2.cross(w, e1);
            big = s * logUniform(r, 0.5, 2);
            small = big * logUniform(r, 0.02, 0.9);
            Vector3d axis = new Vector3d(w);
            axis.scale(logUniform(r, 1e-3, 1e3));
            ClosedShapes.TorusShape sh = new ClosedShapes.TorusShape(c, axis, big, small);
            torus = sh.t;
        }

        /** The line through center + a e1 + b w along e2, from distance dist before the closest point. */
        Ray line(Random r, double a, double b, double dist) {
            Vector3d o = add(add(add(torus.center, a, e1), b, w), -dist, e2);
            Vector3d d = new Vector3d(e2);
            d.scale(logUniform(r, 1e-3, 1e3));
            Ray ray = new Ray(o, d);
            ray.tMin = 0;
            return ray;
        }
    }

    private static void check(Setup su, Ray ray, boolean expectHit, String what) {
        IntersectionRecord rec = new IntersectionRecord();
        boolean hit = su.torus.intersects(ray, rec, null);
        String msg = what + ": " + su.torus + ", " + ray + (hit ? ", hit " + rec : "");
        assertEquals(expectHit, hit, msg);
        if (hit) {
            assertTrue(rec.frontFace, "grazing from outside enters: " + msg);
            double res = Math.abs(new ClosedShapes.TorusShape(su.torus.center, su.torus.axis, su.big, su.small)
                    .residual(rec.location));
            assertTrue(res <= rec.error, "hit point " + res + " off the torus (bound " + rec.error + "): " + msg);
            // leaving again: the same line crosses once more, from inside, just after
            Ray next = new Ray(ray.origin, ray.direction);
            next.tMin = Math.nextUp(rec.t);
            IntersectionRecord out = new IntersectionRecord();
            assertTrue(su.torus.intersects(next, out, null), "entered but never left: " + msg);
            assertFalse(out.frontFace, "second crossing leaves: " + msg + ", then " + out);
        }
    }

    @Test
    void linesJustInsideTheOuterSilhouetteHitAndJustOutsideMiss() {
        forEachSeed(0x70a05L, 4000, r -> {
            Setup su = new Setup(r);
            double delta = logUniform(r, 1e-6, 1e-2);
            double rim = su.big + su.small;
            double dist = rim * logUniform(r, 2, 1e4);
            boolean inside = r.nextBoolean();
            check(su, su.line(r, rim * (inside ? 1 - delta : 1 + delta), 0, dist), inside,
                    "in the plane at " + (inside ? "1 - " : "1 + ") + delta + " of the outer radius");
        });
    }

    @Test
    void linesSkimmingTheTopOfTheTubeHitBelowAndMissAbove() {
        forEachSeed(0x70b7L, 4000, r -> {
            Setup su = new Setup(r);
            double delta = logUniform(r, 1e-6, 1e-2);
            double dist = (su.big + su.small) * logUniform(r, 2, 1e4);
            boolean below = r.nextBoolean();
            check(su, su.line(r, su.big, su.small * (below ? 1 - delta : 1 + delta), dist), below,
                    "tangent to the middle circle at " + (below ? "1 - " : "1 + ") + delta + " of the tube's radius above it");
        });
    }
}
