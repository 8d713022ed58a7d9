import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;

/**
 * Test doubles: stand-ins for the other classes, so each test checks one of your methods alone and a
 * mistake in one method fails only that method's tests.
 */
final class Doubles {

    private Doubles() {
    }

    /** A light with a fixed intensity arriving from a fixed direction (no shadows of its own). */
    static final class FixedLight extends Light {
        final Vector3d intensity, direction;
        int calls;

        FixedLight(Vector3d intensity, Vector3d direction) {
            this.intensity = new Vector3d(intensity);
            this.direction = new Vector3d(direction);
            this.direction.normalize();
        }

        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            calls++;
            return new Vector3d(intensity);
        }

        @Override
        public Vector3d getDirection(IntersectionRecord record) {
            return new Vector3d(direction);
        }
    }

    /** A material that shades every point with one colour (always returning the same vector object). */
    static final class FixedMaterial extends Material {
        final Vector3d fixed;
        final List<IntersectionRecord> records = new ArrayList<>();

        FixedMaterial(Vector3d fixed) {
            this.fixed = fixed;
        }

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            records.add(record);
            return fixed;
        }
    }

    /** Fills {@code into} with a hit at {@code at} if it lies in the ray's span (the test surfaces' common part). */
    static boolean hit(Ray ray, double at, Vector3d normal, Surface s, IntersectionRecord into) {
        if (!(at >= ray.tMin && at <= ray.tMax)) {
            return false;
        }
        into.t = at;
        into.location.scaleAdd(at, ray.direction, ray.origin);
        into.normal.normalize(normal);
        into.surface = s;
        return true;
    }

    /** A surface every ray hits at one t, if that t lies in the ray's span. */
    static final class FixedSurface extends Surface {
        final double t;

        FixedSurface(double t, Material m) {
            this.t = t;
            this.material = m;
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            Vector3d facing = new Vector3d(ray.direction);
            facing.scale(-1);
            return hit(ray, t, facing, this, record);
        }

        @Override
        public String toString() {
            return "a surface at t = " + t;
        }
    }

    /** An infinite plane z = height, hit from either side (a wall between a point and a light). */
    static final class Wall extends Surface {
        final double height;

        Wall(double height) {
            this.height = height;
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            if (ray.direction.z == 0) {
                return false;
            }
            return hit(ray, (height - ray.origin.z) / ray.direction.z, new Vector3d(0, 0, ray.direction.z > 0 ? -1 : 1), this, record);
        }
    }

    /** A scene whose trace returns a fixed colour and remembers the rays it was given. */
    static final class TracingScene extends Scene {
        final Vector3d seen;
        final List<Ray> rays = new ArrayList<>();

        TracingScene(Vector3d seen) {
            this.seen = seen;
        }

        @Override
        public Vector3d trace(Ray ray) {
            rays.add(ray);
            return new Vector3d(seen);
        }
    }

    /** A hit record at {@code location} with unit normal {@code normal}. */
    static IntersectionRecord record(Vector3d location, Vector3d normal) {
        IntersectionRecord r = new IntersectionRecord();
        r.location.set(location);
        r.normal.set(normal);
        r.normal.normalize();
        r.t = 1;
        return r;
    }

    static Scene scene() {
        Scene s = new Scene();
        s.width = 4;
        s.height = 3;
        return s;
    }
}
