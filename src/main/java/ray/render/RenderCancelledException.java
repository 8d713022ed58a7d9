package ray.render;

/** Thrown by {@link Renderer#render()} when the render was cancelled before it finished. */
public final class RenderCancelledException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    public RenderCancelledException() {
        super("render cancelled");
    }
}
