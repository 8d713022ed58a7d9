import javax.vecmath.Vector3d;

/** A light source. A scene names its class: {@code Light PointLight}. */
public abstract class Light {

    /**
     * The light arriving at {@code record.location} from this light (for a point light I / r^2), or
     * black (0, 0, 0) where a surface lies between the point and the light (a shadow). A new vector.
     */
    public abstract Vector3d getIntensity(IntersectionRecord record, Scene scene);

    /**
     * The unit vector l from {@code record.location} towards this light, the direction the light
     * arrives from (for n.l and the half vector). Given: not one of the methods you write.
     */
    public abstract Vector3d getDirection(IntersectionRecord record);
}
