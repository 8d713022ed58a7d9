package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.material.Diffuse;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * A user's own surface found through the BVH keeps the record its {@code intersects} filled in, and a
 * scene object can expand into several primitives ({@link Surface#collectPrimitives}).
 */
class UserSurfaceInBvhTest {

    /** A student's sphere that knows the extended record: normal facing the ray, frontFace, error bound. */
    static final class StudentSphere extends Surface {
        final Vector3d center;
        final double radius;
        final double errorBound;

        StudentSphere(Vector3d center, double radius, double errorBound) {
            this.center = center;
            this.radius = radius;
            this.errorBound = errorBound;
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            Vector3d f = new Vector3d(ray.origin);
            f.sub(center);
            double a = ray.direction.dot(ray.direction), b = f.dot(ray.direction), c = f.dot(f) - radius * radius;
            double disc = b * b - a * c;
            if (disc < 0) {
                return false;
            }
            double t = (-b - Math.sqrt(disc)) / a;
            if (t < ray.tMin) {
                t = (-b + Math.sqrt(disc)) / a;
            }
            if (t < ray.tMin || t > ray.tMax) {
                return false;
            }
            record.t = t;
            record.location = ray.evaluate(t);
            Vector3d n = new Vector3d(record.location);
            n.sub(center);
            n.normalize();
            record.frontFace = n.dot(ray.direction) <= 0;
            if (!record.frontFace) {
                n.negate();
            }
            record.normal = n;
            record.error = errorBound;
            record.surface = this;
            return true;
        }

        @Override
        public Aabb bounds() {
            return new Aabb(center.x - radius, center.y - radius, center.z - radius,
                    center.x + radius, center.y + radius, center.z + radius);
        }
    }

    /** Written against the framework alone: outward normal, no frontFace, no error bound, no surface. */
    static final class FrameworkSphere extends Surface {
        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            Vector3d o = ray.origin, d = ray.direction;
            double b = o.dot(d), a = d.dot(d), disc = b * b - a * (o.dot(o) - 1);
            double t = (-b + Math.sqrt(disc)) / a;   // from inside: the far root
            if (!(disc >= 0) || t < ray.tMin || t > ray.tMax) {
                return false;
            }
            record.t = t;
            record.location = ray.evaluate(t);
            record.normal = new Vector3d(record.location);   // outward: along the ray here
            return true;
        }

        @Override
        public Aabb bounds() {
            return new Aabb(-1, -1, -1, 1, 1, 1);
        }
    }

    /** A few triangles far off, so the tree has inner nodes and the sphere is found through traversal. */
    private static List<Surface> withClutter(Surface s) {
        List<Surface> all = new ArrayList<>();
        for (int i = 0; i < 20; i++) {
            Triangle t = new Triangle();
            t.v0 = new Vector3d(10 + i, 10, 10);
            t.v1 = new Vector3d(11 + i, 10, 10);
            t.v2 = new Vector3d(10 + i, 11, 10);
            all.add(t);
        }
        all.add(s);
        return all;
    }

    private static IntersectionRecord hitFromInside(List<Surface> surfaces) {
        Scene scene = new Scene();
        scene.surfaces = surfaces;
        Bvh bvh = Bvh.build(surfaces, scene);
        assertTrue(bvh.nodeCount() > 0, "the test needs a tree with inner nodes");
        Ray ray = new Ray(new Vector3d(0.1, 0.2, 0.3), new Vector3d(0.3, -0.2, 0.9));
        IntersectionRecord rec = new IntersectionRecord();
        rec.error = 123;        // stale values from an earlier hit must not survive
        assertTrue(bvh.closestHit(ray, rec, new TraceContext(4)));
        return rec;
    }

    @Test
    void studentSphereHitFromInsideKeepsFrontFaceAndErrorBound() {
        StudentSphere student = new StudentSphere(new Vector3d(), 1, 4e-15);
        IntersectionRecord rec = hitFromInside(withClutter(student));
        assertFalse(rec.frontFace, "hit from inside: back face, as the surface said");
        assertEquals(4e-15, rec.error, "the surface's own error bound");
        assertSame(student, rec.surface);
        assertTrue(rec.normal.dot(new Vector3d(0.3, -0.2, 0.9)) < 0, "normal faces the ray: " + rec.normal);

        // the built-in sphere gives the same flags through the same path
        Sphere builtIn = new Sphere();
        IntersectionRecord b = hitFromInside(withClutter(builtIn));
        assertFalse(b.frontFace);
        assertTrue(b.error > 0 && b.error < 1e-14, "built-in bound " + b.error);
        assertEquals(b.t, rec.t, 1e-12);
    }

    @Test
    void frameworkOnlySphereGetsItsNormalTurnedAndTheBackFaceFlag() {
        FrameworkSphere s = new FrameworkSphere();
        IntersectionRecord rec = hitFromInside(withClutter(s));
        assertFalse(rec.frontFace, "outward normal along the ray: seen from the back");
        assertEquals(0, rec.error, "no bound given: 0 (unknown), the spawn routine's fallback applies");
        assertSame(s, rec.surface, "the surface named when it names none");
        assertTrue(rec.normal.dot(new Vector3d(0.3, -0.2, 0.9)) < 0, "normal turned to face the ray");
    }

    @Test
    void missLeavesTheRecordAsItWas() {
        StudentSphere s = new StudentSphere(new Vector3d(0, 0, -5), 1, 1e-15);
        Scene scene = new Scene();
        List<Surface> all = withClutter(s);
        Bvh bvh = Bvh.build(all, scene);
        IntersectionRecord rec = new IntersectionRecord();
        rec.error = 7;
        rec.frontFace = false;
        rec.t = 42;
        // through the sphere's box corner region but missing the sphere itself
        Ray ray = new Ray(new Vector3d(0.95, 0.95, 0), new Vector3d(0, 0, -1));
        assertFalse(bvh.closestHit(ray, rec, new TraceContext(4)));
        assertEquals(7, rec.error);
        assertFalse(rec.frontFace);
        assertEquals(42, rec.t);
        assertEquals(null, rec.surface);
    }

    /** One scene object expanding into two triangles: the BVH holds both, a hit names the part. */
    @Test
    void aSurfaceCanExpandIntoManyPrimitives() {
        Diffuse m = new Diffuse();
        Triangle a = new Triangle(), b = new Triangle();
        a.v0 = new Vector3d(-1, -1, 0); a.v1 = new Vector3d(1, -1, 0); a.v2 = new Vector3d(1, 1, 0);
        b.v0 = new Vector3d(-1, -1, 0); b.v1 = new Vector3d(1, 1, 0); b.v2 = new Vector3d(-1, 1, 0);
        a.material = m;
        b.material = m;
        Surface quad = new Surface() {
            @Override
            public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
                throw new AssertionError("the parts are tested, not the whole");
            }

            @Override
            public void collectPrimitives(List<Surface> out) {
                out.add(a);
                out.add(b);
            }
        };
        List<Surface> all = withClutter(quad);
        Scene scene = new Scene();
        Bvh bvh = Bvh.build(all, scene);
        assertEquals(22, bvh.primitiveCount());
        IntersectionRecord rec = new IntersectionRecord();
        TraceContext ctx = new TraceContext(4);
        assertTrue(bvh.closestHit(new Ray(new Vector3d(0.5, -0.5, 3), new Vector3d(0, 0, -1)), rec, ctx));
        assertSame(a, rec.surface);
        assertSame(m, rec.surface.material);
        assertTrue(bvh.closestHit(new Ray(new Vector3d(-0.5, 0.5, 3), new Vector3d(0, 0, -1)), rec, ctx));
        assertSame(b, rec.surface);
        assertTrue(bvh.anyHit(new Ray(new Vector3d(-0.5, 0.5, 3), new Vector3d(0, 0, -1)), ctx));
    }
}
