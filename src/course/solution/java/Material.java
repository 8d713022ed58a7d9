import javax.vecmath.Vector3d;

/** How a surface reflects light. A scene names its class: {@code Material Diffuse red}. */
public abstract class Material {

    /**
     * The colour L leaving {@code record.location} back along {@code ray}: linear RGB in a new
     * Vector3d (x = red, y = green, z = blue), never null, never NaN.
     */
    public abstract Vector3d shade(Ray ray, IntersectionRecord record, Scene scene);
}
