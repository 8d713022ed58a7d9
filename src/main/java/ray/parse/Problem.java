package ray.parse;

/**
 * A user-facing message without a location, thrown by the parser's helpers; the parser turns it into
 * a {@link SceneFormatException} for the line it is reading.
 */
final class Problem extends Exception {
    private static final long serialVersionUID = 1L;

    Problem(String message) {
        super(message, null, false, false);
    }
}
