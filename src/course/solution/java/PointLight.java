import javax.vecmath.Vector3d;

/**
 * A light at a point, shining equally in all directions, falling off as I / r^2, with hard shadows.
 *
 * <pre>
 * Light PointLight
 * Vector3d position [5 5 5]
 * Vector3d intensity [20 20 20]
 * </pre>
 */
public class PointLight extends Light {

    public Vector3d position = new Vector3d();
    public Vector3d intensity = new Vector3d(1, 1, 1);

    /**
     * Method 5 of 11. The light arriving at {@code record.location}: intensity / r^2, r the distance
     * from the point to the light, or black (0, 0, 0) when the point is in shadow.
     *
     * <p>The point is in shadow when some surface of {@code scene.surfaces} is hit by the shadow ray
     * from record.location towards the light, between the point and the light: nothing beyond the
     * light counts. Hint: with direction = position - location, the light is at t = 1; end the shadow
     * ray just short of it (tMax = 1 - Ray.EPSILON) so a surface the light sits on does not shadow it.
     * The shadow ray's tMin (Ray.EPSILON) keeps the point's own surface from shadowing it. Return a new
     * vector; never change {@code intensity} itself.
     */
    @Override
    public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 5 of 11
        // STUB: return null;
        Vector3d toLight = new Vector3d();
        toLight.sub(position, record.location);
        Ray shadowRay = new Ray(record.location, toLight);
        shadowRay.tMax = 1 - Ray.EPSILON;
        IntersectionRecord blocker = new IntersectionRecord();
        for (Surface surface : scene.surfaces) {
            if (surface.intersects(shadowRay, blocker, scene)) {
                return new Vector3d();
            }
        }
        Vector3d arriving = new Vector3d(intensity);
        arriving.scale(1 / toLight.lengthSquared());
        return arriving;
        // END SOLUTION
    }

    /** The unit vector from {@code record.location} towards {@link #position}. */
    @Override
    public Vector3d getDirection(IntersectionRecord record) {
        Vector3d l = new Vector3d();
        l.sub(position, record.location);
        l.normalize();
        return l;
    }

    @Override
    public String toString() {
        return "PointLight[position " + position + ", intensity " + intensity + "]";
    }
}
