import javax.vecmath.Vector3d;

/**
 * A one-sided triangle: only rays arriving from the side of n = (v1 - v0) x (v2 - v0) hit it, where
 * its corners run counter-clockwise.
 *
 * <pre>
 * Surface Triangle
 * Vector3d v0 [0 0 0]
 * Vector3d v1 [1 0 0]
 * Vector3d v2 [0 1 0]
 * ref material red
 * </pre>
 */
public class Triangle extends Surface {

    public Vector3d v0 = new Vector3d();
    public Vector3d v1 = new Vector3d(1, 0, 0);
    public Vector3d v2 = new Vector3d(0, 1, 0);

    /**
     * Method 2 of 11. The hit of {@code ray} with this triangle, with t in [ray.tMin, ray.tMax].
     *
     * <p>The triangle is one-sided: a ray arriving from the back (d.n >= 0, with
     * n = (v1 - v0) x (v2 - v0)) misses it, and so does a ray lying in its plane. Otherwise solve
     * o + t d = v0 + beta (v1 - v0) + gamma (v2 - v0) for t, beta and gamma (Cramer's rule, or the
     * Moller-Trumbore form); the point is inside when beta >= 0, gamma >= 0 and beta + gamma <= 1.
     * On a hit fill in record.t, record.location, record.normal (n made unit length) and
     * record.surface, and return true; on a miss return false and leave the record alone.
     */
    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 2 of 11
        // STUB: return false;
        Vector3d edge1 = new Vector3d(), edge2 = new Vector3d(), n = new Vector3d();
        edge1.sub(v1, v0);
        edge2.sub(v2, v0);
        n.cross(edge1, edge2);
        if (!(ray.direction.dot(n) < 0)) {
            return false;                 // seen from the back, or the ray lies in the plane
        }
        Vector3d p = new Vector3d(), s = new Vector3d(), q = new Vector3d();
        p.cross(ray.direction, edge2);
        double det = edge1.dot(p);
        s.sub(ray.origin, v0);
        double beta = s.dot(p) / det;
        if (beta < 0 || beta > 1) {
            return false;
        }
        q.cross(s, edge1);
        double gamma = ray.direction.dot(q) / det;
        if (gamma < 0 || beta + gamma > 1) {
            return false;
        }
        double t = edge2.dot(q) / det;
        if (t < ray.tMin || t > ray.tMax) {
            return false;
        }
        record.t = t;
        record.location.set(ray.evaluate(t));
        n.normalize();
        record.normal.set(n);
        record.surface = this;
        return true;
        // END SOLUTION
    }

    @Override
    public String toString() {
        return "Triangle[" + v0 + ", " + v1 + ", " + v2 + "]";
    }
}
