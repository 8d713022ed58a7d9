package ray.accel;

/**
 * A user's {@code Surface.bounds()} returned null. The message names the class and the method, e.g.
 * {@code MyShape.bounds() returned null (...)}; it carries no stack trace, so no report blames the BVH's
 * build, where it was found, instead of the class that broke the contract.
 */
public final class BadBoundsException extends IllegalStateException {
    private static final long serialVersionUID = 1L;

    BadBoundsException(Class<?> surface) {
        super(surface.getSimpleName() + ".bounds() returned null (expected a box around the surface, or not to override bounds() "
                + "for a surface without one)");
    }

    @Override
    public synchronized Throwable fillInStackTrace() {
        return this;
    }
}
