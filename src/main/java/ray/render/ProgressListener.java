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

    /**
     * A progressive render ({@link ray.settings.RenderSettings#progressive}) finished pass {@code pass} (from 0) of
     * {@code passes}: every pixel of {@code image} now holds that pass's estimate (pass 0 is a cheap
     * first look, one sample per pixel; the last pass is the final image). Within a pass, {@link #tileDone}
     * reports its tiles as usual, done and total counting that pass's tiles.
     */
    default void passDone(Image image, int pass, int passes) {
    }
}
