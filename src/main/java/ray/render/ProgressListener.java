package ray.render;

/**
 * Told about a render as it goes (the viewer repaints finished tiles; the CLI shows a progress line).
 * Called from the render threads: implementations must be thread-safe and quick.
 */
public interface ProgressListener {

    ProgressListener NONE = new ProgressListener() {
    };

    /** Pixels [x0, x1) x [y0, y1) of {@code image} are final; {@code done} of {@code total} tiles are. */
    default void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
    }
}
