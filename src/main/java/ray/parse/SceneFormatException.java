package ray.parse;

/**
 * A mistake in a scene file, located: {@link #getMessage()} is one line, {@code file:line: what is
 * wrong (what was expected)}. The only exception the parser lets out for bad input.
 */
public final class SceneFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final int line;
    private final String problem;

    public SceneFormatException(String file, int line, String problem) {
        super(file + ":" + line + ": " + problem);
        this.file = file;
        this.line = line;
        this.problem = problem;
    }

    public String file() {
        return file;
    }

    public int line() {
        return line;
    }

    /** The message without the {@code file:line: } prefix. */
    public String problem() {
        return problem;
    }
}
