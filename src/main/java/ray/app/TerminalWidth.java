package ray.app;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;

/**
 * The terminal's width in columns, for the progress line: {@code COLUMNS} when the shell exports it,
 * else what {@code stty size} says of the controlling terminal ({@code /dev/tty}), else 80. Asked once,
 * then again only after the terminal says it was resized (SIGWINCH, where the JVM lets us listen), so a
 * redraw costs nothing. Java has no call for it: a child {@code stty} is the portable way on Unix.
 */
final class TerminalWidth {

    private static volatile int cached = -1;
    private static volatile boolean listening;

    private TerminalWidth() {
    }

    /** The columns now (at least 1). */
    static int columns() {
        int c = cached;
        if (c < 0) {
            listen();
            c = measure();
            cached = c;
        }
        return c;
    }

    /** COLUMNS, then stty, then 80. */
    static int measure() {
        int env = parse(System.getenv("COLUMNS"));
        if (env > 0) {
            return env;
        }
        int stty = stty();
        return stty > 0 ? stty : 80;
    }

    static int parse(String s) {
        if (s == null) {
            return -1;
        }
        try {
            int v = Integer.parseInt(s.trim());
            return v > 0 && v < 10_000 ? v : -1;
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    /** {@code stty size < /dev/tty}: "rows columns", or -1 (no terminal, no stty, Windows). */
    private static int stty() {
        File tty = new File("/dev/tty");
        if (!tty.exists()) {
            return -1;
        }
        try {
            Process p = new ProcessBuilder("stty", "size").redirectInput(tty).redirectError(ProcessBuilder.Redirect.DISCARD).start();
            String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.US_ASCII).trim();
            if (!p.waitFor(2, TimeUnit.SECONDS) || p.exitValue() != 0) {
                p.destroy();
                return -1;
            }
            String[] rc = out.split("\\s+");
            return rc.length == 2 ? parse(rc[1]) : -1;
        } catch (java.io.IOException | RuntimeException e) {
            return -1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return -1;
        }
    }

    /** On SIGWINCH the width is measured again at the next ask. */
    private static void listen() {
        if (listening) {
            return;
        }
        listening = true;
        try {
            sun.misc.Signal.handle(new sun.misc.Signal("WINCH"), s -> cached = -1);
        } catch (IllegalArgumentException | UnsupportedOperationException | LinkageError e) {
            // no such signal here (Windows) or not allowed: the width of the start stays
        }
    }
}
