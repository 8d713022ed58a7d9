package ray.robust;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static ray.robust.RobustSupport.add;
import static ray.robust.RobustSupport.atAngle;
import static ray.robust.RobustSupport.forEachSeed;
import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.sub;
import static ray.robust.RobustSupport.unit;
import static ray.robust.RobustSupport.unnormalised;

import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import ray.IntersectionRecord;
import ray.Ray;
import ray.surface.CSG;

/**
 * The closed primitives (0 Box, 1 Cylinder, 2 Cone, 3 Torus) at scales 1e-4..1e4 and up to a million
 * sizes from the origin, with unnormalised directions: rays aimed through the inside always hit; every
 * crossing lies on the surface within the record's own error bound (residual computed exactly);
 * crossings walked one by one alternate entering / leaving, starting with entering exactly when the
 * origin is outside, and end leaving; rays spawned off a hit never re-hit it.
 */
class ClosedSurfaceRobustnessTest {

    private static final String[] NAMES = {"box", "cylinder", "cone", "torus"};

    /** A random shape and a ray (tMin 0, unnormalised) aimed through its inside; {@code outside}: where the ray starts. */
    private record Case(ClosedShapes sh, Ray ray, boolean outside) {
    }

    /**
     * A shape of the kind at a scale of 1e-4..1e4 up to a million sizes from the origin, and a ray from
     * inside it, near it or far away through a point well inside it; null when the origin falls within
     * 1e-6 sizes of the surface (its side would be a matter of rounding).
     */
    private static Case randomCase(int kind, Random r) {
        ClosedShapes sh = ClosedShapes.random(kind, r, logUniform(r, 1e-4, 1e4), 1e6);
        Vector3d q = sh.inside(r);
        Vector3d o;
        switch (r.nextInt(3)) {
            case 0:
                o = sh.inside(r);
                break;
            case 1:
                o = add(q, sh.size() * logUniform(r, 0.5, 3), unit(r));
                break;
            default:
                o = add(q, sh.size() * logUniform(r, 3, 1e4), unit(r));
        }
        double res = sh.residual(o);
        if (Math.abs(res) < 1e-6 * sh.size() || sub(q, o).length() < 1e-6 * sh.size()) {
            return null;
        }
        Ray ray = new Ray(o, unnormalised(r, sub(q, o)));
        ray.tMin = 0;
        return new Case(sh, ray, res > 0);
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(ints = {0, 1, 2, 3})
    void raysThroughTheInsideHitOnTheSurfaceAndCrossingsAlternate(int kind) {
        forEachSeed(0x9e11L + 1000 * kind, 3000, r -> {
            Case c = randomCase(kind, r);
            if (c == null) {
                return;
            }
            ClosedShapes sh = c.sh();
            Ray ray = c.ray();
            String what = NAMES[kind] + " " + sh.surface + ", " + ray;
            boolean outside = c.outside();
            int crossings = 0;
            double lastT = -1;
            while (true) {
                IntersectionRecord rec = new IntersectionRecord();
                boolean hit = sh.surface.intersects(ray, rec, null);
                if (!hit) {
                    assertTrue(crossings > 0, "ray through the inside missed: " + what);
                    assertTrue(outside, "the last crossing left the ray inside: " + what);
                    return;
                }
                crossings++;
                String at = "crossing " + crossings + " " + rec + " of " + what;
                assertTrue(crossings <= (kind == 3 ? 4 : 2), "too many crossings: " + at);
                assertTrue(rec.t > lastT, "crossings out of order: " + at);
                assertEquals(outside, rec.frontFace, "entering/leaving does not alternate: " + at);
                double res = Math.abs(sh.residual(rec.location));
                assertTrue(res <= rec.error, "hit point " + res + " off the surface, error bound " + rec.error + ": " + at);
                assertEquals(1, rec.normal.length(), 1e-12, "normal not unit: " + at);
                assertTrue(rec.normal.dot(ray.direction) <= 0, "normal does not face the ray: " + at);
                outside = !outside;
                lastT = rec.t;
                ray.tMin = Math.nextUp(rec.t);
            }
        });
    }

    /**
     * A ray spawned off a hit, to either side at an angle down to cos 1e-3 (1e-12 for rays leaving a convex
     * shape outward), never meets the surface within a few error bounds of where it started; leaving a
     * convex shape outward it meets nothing, and going in it meets the far side, from behind.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(ints = {0, 1, 2, 3})
    void spawnedRaysDoNotRehitTheirOwnPoint(int kind) {
        boolean convex = kind != 3;
        forEachSeed(0x5be7L + 1000 * kind, 3000, r -> {
            Case c = randomCase(kind, r);
            if (c == null) {
                return;
            }
            ClosedShapes sh = c.sh();
            Ray ray = c.ray();
            IntersectionRecord rec = new IntersectionRecord();
            if (!sh.surface.intersects(ray, rec, null)) {
                return;                                    // the first test checks this
            }
            boolean back = r.nextBoolean();                // back to the side the ray came from, or through
            double cos = r.nextInt(4) == 0 ? 1 : logUniform(r, back && convex && rec.frontFace ? 1e-12 : 1e-3, 1);
            Vector3d n = new Vector3d(rec.normal);
            if (!back) {
                n.negate();
            }
            Ray out = rec.spawnRay(unnormalised(r, atAngle(r, n, cos)));
            IntersectionRecord again = new IntersectionRecord();
            boolean hit = sh.surface.intersects(out, again, null);
            String what = NAMES[kind] + " " + sh.surface + ": first hit " + rec + ", spawned "
                    + (back ? "back" : "through") + " at cos " + cos + ": " + out + (hit ? ", hit again " + again : "");
            if (hit) {
                double moved = sub(again.location, rec.location).length();
                assertTrue(moved > 8 * rec.error, "re-hit its own point (moved " + moved + "): " + what);
            }
            if (convex) {
                // outside after spawning: back from the outside, or through from the inside
                boolean nowOutside = back == rec.frontFace;
                assertEquals(!nowOutside, hit, "convex shape: " + what);
                if (hit) {
                    assertFalse(again.frontFace, "the far side is hit from behind: " + what);
                }
            }
        });
    }

    /**
     * As CSG operands (which walk an operand's crossings with tMin = nextUp(t)): the union and the
     * intersection of a shape with itself are the shape, record for record, on rays from inside and out.
     */
    @ParameterizedTest(name = "{0}")
    @ValueSource(ints = {0, 1, 2, 3})
    void shapeCombinedWithItselfInCsgIsTheShape(int kind) {
        forEachSeed(0xc5e1fL + 1000 * kind, 1000, r -> {
            Case c = randomCase(kind, r);
            if (c == null) {
                return;
            }
            ClosedShapes sh = c.sh();
            Ray ray = c.ray();
            IntersectionRecord alone = new IntersectionRecord();
            assertTrue(sh.surface.intersects(ray, alone, null), "missed: " + sh.surface + ", " + ray);
            for (String op : new String[] {"union", "intersection"}) {
                CSG csg = new CSG();
                csg.operation = op;
                csg.left = sh.surface;
                csg.right = sh.surface;
                csg.init();
                IntersectionRecord rec = new IntersectionRecord();
                String what = op + " of " + sh.surface + " with itself, " + ray + ": alone " + alone;
                assertTrue(csg.intersects(ray, rec, null), "missed: " + what);
                assertEquals(alone.t, rec.t, what + ", CSG " + rec);
                assertEquals(alone.frontFace, rec.frontFace, what + ", CSG " + rec);
                assertEquals(alone.location, rec.location, what + ", CSG " + rec);
            }
        });
    }
}
