package ray;

/**
 * Why a ray was cast. Every ray the renderer casts is counted under exactly one kind, in the one
 * method of {@link Scene} that casts that kind ({@link Scene#traceCamera}, {@link Scene#occluded},
 * {@link Scene#traceMirror}, {@link Scene#traceRefraction}, and {@link Scene#trace(Ray)} /
 * {@link Scene#intersect} for rays a user's own class casts). {@link #key()} is the name used in
 * {@code --stats --json} under {@code "rays"}.
 */
public enum RayKind {
    /** Primary rays: exactly one per sample. */
    CAMERA,
    /** Shadow (any-hit) queries towards a light sample. */
    SHADOW,
    /** Ideal mirror reflections cast by built-in materials. */
    MIRROR,
    /** Transmitted rays cast by refracting materials. */
    REFRACTION,
    /** Rays a user's own class casts through {@link Scene#trace(Ray)} or {@link Scene#intersect}. */
    USER;

    private static final RayKind[] ALL = values();

    /** Lower-case name: {@code camera}, {@code shadow}, {@code mirror}, {@code refraction}, {@code user}. */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }

    /** All kinds in declaration order (a shared array: do not modify). */
    static RayKind[] all() {
        return ALL;
    }
}
