package ray.app;

import java.io.PrintStream;
import ray.render.Image;
import ray.render.ProgressListener;

/**
 * The progress bar on a terminal's stderr:
 * {@code scene.txt  42% [========>           ] 3.1 s, about 4.2 s left}. The share is of the work, not
 * of the tiles: pixels done (weighted by each tile's area) out of all the image's pixels, over all of a
 * progressive render's passes; as the renderer hands tiles out spread over the image, pixels done are
 * an unbiased sample of the work. The time left is the elapsed time scaled by the share still to do,
 * shown once there is a measure to scale (2% or a second). A timer redraws the line four times a second
 * even when no tile finishes, so a slow tile still shows the clock running; the line is erased when the
 * render ends, fails or is interrupted (Ctrl+C, through {@link ExitGuard}). Used only when stderr is a
 * terminal ({@link Terminal}), never with {@code --quiet}.
 */
final class ProgressLine implements ProgressListener {

    private static final long REDRAW_NANOS = 250_000_000L;
    private static final int BAR = 20;
    /** Columns the line may use when the terminal's width is not known: 80 columns less the last (it wraps on some). */
    static final int WIDTH = 79;

    private final PrintStream err;
    private final String label;
    private final long start = System.nanoTime();
    private final long pixels;
    private long pixelsDone;
    private int pass;
    private int passes = 1;
    private int drawn;
    private boolean closed;
    private final Thread timer;

    /** The terminal's columns now, asked at each redraw (a window resized mid-render is followed). */
    private final java.util.function.IntSupplier columns;

    ProgressLine(PrintStream err, String label, long pixels) {
        this(err, label, pixels, TerminalWidth::columns);
    }

    ProgressLine(PrintStream err, String label, long pixels, java.util.function.IntSupplier columns) {
        this.columns = columns;
        this.err = err;
        this.label = label;
        this.pixels = Math.max(1, pixels);
        ProgressLine self = this;
        timer = new Thread("progress") {      // (not a lambda: linking one costs start-up time)
            @Override
            public void run() {
                try {
                    do {
                        Thread.sleep(REDRAW_NANOS / 1_000_000L);    // a render over in a blink draws nothing
                    } while (self.redraw());
                } catch (InterruptedException e) {
                    // cleared
                }
            }
        };
        timer.setDaemon(true);
    }

    /** Starts the timer that redraws the line. */
    ProgressLine start() {
        timer.start();
        return this;
    }

    @Override
    public synchronized void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
        pixelsDone += (long) (x1 - x0) * (y1 - y0);
    }

    @Override
    public synchronized void passDone(Image image, int pass, int passes) {
        this.pass = pass + 1;
        this.passes = Math.max(1, passes);
        pixelsDone = 0;
    }

    /** The share of the work done, 0 to 1. */
    synchronized double share() {
        double inPass = Math.min(1.0, (double) pixelsDone / pixels);
        return Math.min(1.0, (Math.min(pass, passes) + (pass < passes ? inPass : 0)) / passes);
    }

    /** Draws the line now; false once it has been cleared. */
    synchronized boolean redraw() {
        if (closed) {
            return false;
        }
        int width = Math.max(1, columns.getAsInt() - 1);        // never the last column: the cursor would wrap
        String s = line(label, share(), System.nanoTime() - start, width);
        // what is left of a longer line drawn before (at most the width: padding must not wrap either)
        int pad = Math.max(0, Math.min(drawn, width) - s.length());
        err.print("\r" + s + " ".repeat(pad));
        err.flush();
        drawn = Math.min(width, Math.max(drawn, s.length()));
        lastWidth = width;
        return true;
    }

    private int lastWidth = WIDTH;

    /** {@code label  42% [========>           ] 3.1 s, about 4.2 s left}, at most {@link #WIDTH} columns. */
    static String line(String label, double share, long elapsedNanos) {
        return line(label, share, elapsedNanos, WIDTH);
    }

    /**
     * The line in at most {@code width} columns, giving up first the label's start, then the bar's
     * length (down to 5), the label, the time left, the bar and the time, so that on a narrow terminal
     * it never wraps: {@code 42% [==>  ] 3.1 s}.
     */
    static String line(String label, double share, long elapsedNanos, int width) {
        int pct = (int) Math.floor(100 * share);
        double elapsed = elapsedNanos / 1e9;
        String time = duration(elapsed);
        String left = share >= 0.02 || share > 0 && elapsed >= 1 ? ", about " + duration(elapsed * (1 - share) / share) + " left" : "";
        String percent = (pct < 10 ? "  " : pct < 100 ? " " : "") + pct + "%";
        // the parts without the label, longest first; the bar shrinks before anything is dropped, the time
        // left goes before the label (at least its last 8 characters) does
        for (boolean named : new boolean[] {true, false}) {
            for (String t : new String[] {time + left, time, ""}) {
                for (int bar = BAR; bar >= 5; bar--) {
                    String tail = " " + percent + " " + bar(share, bar) + (t.isEmpty() ? "" : " " + t);
                    int room = width - tail.length();
                    if (named ? room >= Math.min(label.length(), 8) : room >= 0) {
                        String name = label.length() <= room ? label : room > 3 ? "..." + label.substring(label.length() - room + 3) : "";
                        return name.isEmpty() ? tail.substring(1) : name + tail;
                    }
                }
            }
        }
        String bare = percent.trim();
        return bare.length() <= width ? bare : "";
    }

    private static String bar(double share, int n) {
        int fill = (int) Math.floor(n * share);
        StringBuilder bar = new StringBuilder(n + 2).append('[');
        for (int i = 0; i < n; i++) {
            bar.append(i < fill ? '=' : i == fill ? '>' : ' ');
        }
        return bar.append(']').toString();
    }

    /** 4.2 s, 3 min 05 s, 2 h 07 min. */
    static String duration(double seconds) {
        if (seconds < 60) {
            return Main.fixed(Math.round(seconds * 1e9), 1) + " s";
        }
        long s = Math.round(seconds);
        if (s < 3600) {
            return s / 60 + " min " + (s % 60 < 10 ? "0" : "") + s % 60 + " s";
        }
        long m = s / 60;
        return m / 60 + " h " + (m % 60 < 10 ? "0" : "") + m % 60 + " min";
    }

    /** Erases the line and stops the timer (from the render's end, a failure or the Ctrl+C hook). */
    void clear() {
        synchronized (this) {
            if (closed) {
                return;
            }
            closed = true;
            if (drawn > 0) {
                err.print("\r" + " ".repeat(Math.min(drawn, lastWidth)) + "\r");
                err.flush();
            }
        }
        timer.interrupt();
    }
}
