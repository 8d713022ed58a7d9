package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Overrides;
import ray.Ray;
import ray.Scene;
import ray.SceneObject;
import ray.accel.Aabb;
import ray.material.Material;

/**
 * Something a ray can hit. The framework's contract is {@link #intersects}: true for a hit with t in
 * {@code [ray.tMin, ray.tMax]}, and then {@code record} is filled in (location, unit normal facing the
 * ray, t, surface); on a miss the record is left as it was.
 *
 * <p>A subclass that also overrides {@link #bounds()} goes into the scene's BVH; one that does not is
 * tested against every ray (correct, just slower).
 */
public abstract class Surface implements SceneObject {

    private static final Class<?>[] INTERSECTS = {Ray.class, IntersectionRecord.class, Scene.class};

    /**
     * Per class: whether a built-in's fast path is still this class's own, i.e. {@code intersects} is
     * not overridden below the class that declared it (a student's {@code MySphere extends Sphere} or
     * {@code MyMesh extends Mesh} overriding only {@code intersects} is tested by its override).
     */
    private static final ClassValue<Boolean> OWN_PACKED_TYPE = fastPathFor("primitiveType");
    private static final ClassValue<Boolean> OWN_PARTS = fastPathFor("collectPrimitives", List.class);
    private static final ClassValue<Boolean> OWN_COUNT = fastPathFor("primitiveCount");

    private static ClassValue<Boolean> fastPathFor(String name, Class<?>... params) {
        return Overrides.trusted(null, "intersects", INTERSECTS, name, params);
    }

    /**
     * What the BVH holds for this surface (called once per build): {@link #collectPrimitives}'s parts, or
     * this surface itself when its class overrides {@code intersects} below the class that split it.
     */
    public final void addPrimitives(List<Surface> out) {
        if (OWN_PARTS.get(getClass())) {
            collectPrimitives(out);
        } else {
            out.add(this);
        }
    }

    /** {@link #primitiveCount()} under the rule of {@link #addPrimitives}. */
    public final long plannedPrimitiveCount() {
        return OWN_COUNT.get(getClass()) && OWN_PARTS.get(getClass()) ? primitiveCount() : 1;
    }

    /**
     * The packed type the BVH uses (once per build): {@link #primitiveType()}, or null (the generic set,
     * which calls {@code intersects}) when the class overrides {@code intersects} below the class that
     * chose the type.
     */
    public final ray.accel.PrimitiveSet.Type packedType() {
        return OWN_PACKED_TYPE.get(getClass()) ? primitiveType() : null;
    }

    /** {@code ref material <name>} in a scene file. */
    public Material material;

    public abstract boolean intersects(Ray ray, IntersectionRecord record, Scene scene);

    /** World-space bounding box; the default (infinite) keeps the surface out of the BVH. */
    public Aabb bounds() {
        return Aabb.infinite();
    }

    /**
     * True when the surface bounds a solid: every ray from outside that enters leaves again, and
     * {@code intersects} reports hits from inside too, with {@code frontFace} telling which side the ray
     * came from. Only closed surfaces can be CSG operands. The default is false.
     */
    public boolean isClosed() {
        return false;
    }

    /**
     * The surfaces this one is built from and that are not rendered on their own (a CSG's operands).
     * The parser leaves them out of the scene's surfaces. The default is none.
     */
    public List<Surface> operands() {
        return List.of();
    }

    /**
     * The primitives the acceleration structure holds for this scene object: by default the object
     * itself. A surface made of many parts (a mesh of triangles) adds its parts instead, each a
     * {@code Surface} with its own {@link #bounds()} and {@link #intersects} and its {@link #material}
     * set; a hit then reports the part as {@code record.surface}. Called once per {@link Scene#prepare()}.
     */
    public void collectPrimitives(java.util.List<Surface> out) {
        out.add(this);
    }

    /**
     * How many primitives {@link #collectPrimitives} adds (1 by default), for the render plan's geometry
     * line; a surface of many parts that overrides one overrides both.
     */
    public long primitiveCount() {
        return 1;
    }

    /**
     * The packed type the BVH holds this surface in, for a fast path with its own kernel
     * ({@link ray.accel.PrimitiveSet}); null (the default): the BVH calls {@link #intersects}, which is
     * all a new primitive needs. Return a type only for your exact class
     * ({@code getClass() == MyShape.class}), so a subclass overriding {@code intersects} keeps its test.
     */
    public ray.accel.PrimitiveSet.Type primitiveType() {
        return null;
    }

    /**
     * Calls {@code s.intersects}. Framework code may point the record's vectors at its own objects
     * ({@code record.normal = normal}); the record gets its own vectors back, holding the values, so
     * later writes into the record (the next hit's fill) cannot change the surface's fields.
     */
    public static boolean intersectInto(Surface s, Ray ray, IntersectionRecord rec, Scene scene) {
        javax.vecmath.Vector3d location = rec.location, normal = rec.normal;
        boolean hit = s.intersects(ray, rec, scene);
        if (rec.location != location) {
            location.set(rec.location);
            rec.location = location;
        }
        if (rec.normal != normal) {
            normal.set(rec.normal);
            rec.normal = normal;
        }
        return hit;
    }

    /** True when the surface can never be hit (e.g. a zero-area triangle); it is left out of the scene. */
    public boolean isDegenerate() {
        return false;
    }
}
