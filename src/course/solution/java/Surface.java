/** Something a ray can hit. A scene names its class: {@code Surface Sphere}, {@code Surface Triangle}, or your own. */
public abstract class Surface {

    /** How the surface reflects light: {@code ref material <name>} in a scene. */
    public Material material;

    /**
     * Intersects {@code ray} with this surface. Returns true when the ray hits it at a t with
     * {@code ray.tMin <= t <= ray.tMax}, and then fills in every field of {@code record}: t, location,
     * normal (unit length, on the side the ray came from) and surface ({@code this}). On a miss it
     * returns false and leaves {@code record} as it was.
     */
    public abstract boolean intersects(Ray ray, IntersectionRecord record, Scene scene);
}
