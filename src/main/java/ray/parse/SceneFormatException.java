package ray.parse;

/**
 * A mistake in a scene file, located: {@link #getMessage()} is one line, {@code file:line: what was
 * found (what was expected)}, or {@code file: ...} for a file that cannot be read at all (line 0).
 * Control characters and line breaks in the message are shown escaped, so the message stays one
 * line whatever the file held. The only exception the parser lets out for bad input.
 */
public final class SceneFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final int line;
    private final String problem;

    public SceneFormatException(String file, int line, String problem) {
        super(oneLine(line > 0 ? file + ":" + line + ": " + problem : file + ": " + problem), null, false, false);
        this.file = file;
        this.line = line;
        this.problem = problem;
    }

    public String file() {
        return file;
    }

    /** The 1-based line, or 0 when the whole file is at fault (missing, a directory, unreadable). */
    public int line() {
        return line;
    }

    /** The message without the {@code file:line: } prefix. */
    public String problem() {
        return problem;
    }

    private static String oneLine(String s) {
        StringBuilder b = null;
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c < 0x20 || c == 0x7f || c == 0x85 || c == 0x2028 || c == 0x2029) {
                if (b == null) {
                    b = new StringBuilder(s.length() + 16).append(s, 0, i);
                }
                b.append(String.format("\\u%04X", (int) c));
            } else if (b != null) {
                b.append(c);
            }
        }
        return b == null ? s : b.toString();
    }
}
