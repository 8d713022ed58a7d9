import javax.vecmath.Vector3d;

/**
 * A sphere.
 *
 * <pre>
 * Surface Sphere
 * Vector3d center [0 0 0]
 * double radius 1
 * ref material red
 * </pre>
 */
public class Sphere extends Surface {

    public Vector3d center = new Vector3d();
    public double radius = 1;

    /**
     * Method 1 of 11. The first hit of {@code ray} with this sphere with t in [ray.tMin, ray.tMax].
     *
     * <p>Put p = o + t d into |p - c|^2 = R^2 and solve the quadratic for t. Of its two roots take the
     * smaller one that lies in the ray's span: the larger one when the smaller is below tMin (the ray
     * starts inside the sphere). On a hit fill in record.t, record.location, record.normal (unit
     * length: (p - c) / R, turned around when the ray comes from inside so that it faces the ray) and
     * record.surface, and return true. On a miss return false and leave the record alone.
     */
    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 1 of 11
        // STUB: return false;
        Vector3d oc = new Vector3d();
        oc.sub(ray.origin, center);
        double a = ray.direction.dot(ray.direction);
        double halfB = ray.direction.dot(oc);
        double c = oc.dot(oc) - radius * radius;
        double discriminant = halfB * halfB - a * c;
        if (discriminant < 0) {
            return false;
        }
        double root = Math.sqrt(discriminant);
        double t = (-halfB - root) / a;
        if (t < ray.tMin) {
            t = (-halfB + root) / a;
        }
        if (t < ray.tMin || t > ray.tMax) {
            return false;
        }
        record.t = t;
        record.location.set(ray.evaluate(t));
        record.normal.sub(record.location, center);
        record.normal.scale(1 / radius);
        if (record.normal.dot(ray.direction) > 0) {
            record.normal.negate();
        }
        record.surface = this;
        return true;
        // END SOLUTION
    }

    @Override
    public String toString() {
        return "Sphere[center " + center + ", radius " + radius + "]";
    }
}
