package ray;

/**
 * Something a scene file can declare. After the parser has set an object's fields (at the blank
 * line that ends it) it calls {@link #init()}, which derives cached values and rejects bad ones by
 * throwing {@link IllegalArgumentException}; the parser turns that message into
 * {@code file:line: message} for the object's header line.
 */
public interface SceneObject {
    default void init() {
    }
}
