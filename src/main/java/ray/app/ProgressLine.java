package ray.app;

import java.io.PrintStream;
import ray.render.Image;
import ray.render.ProgressListener;

/**
 * A one-line progress report on a terminal ({@code scene.txt: 42%}), redrawn at most ten times a
 * second from whichever render thread finishes a tile, and erased when the render ends. Not used when
 * the output is not a terminal, so logs and pipes stay clean.
 */
final class ProgressLine implements ProgressListener {

    private static final long INTERVAL_NANOS = 100_000_000L;

    private final PrintStream err;
    private final String label;
    private final long start = System.nanoTime();
    private long lastDraw = start;
    private int width;

    ProgressLine(PrintStream err, String label) {
        this.err = err;
        this.label = label;
    }

    @Override
    public synchronized void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
        long now = System.nanoTime();
        if (now - lastDraw < INTERVAL_NANOS && done < total) {
            return;
        }
        lastDraw = now;
        String s = String.format("%s: %3d%%  %.1f s", label, 100L * done / total, (now - start) / 1e9);
        width = Math.max(width, s.length());
        err.print("\r" + s);
        err.flush();
    }

    /** Erases the line. */
    synchronized void clear() {
        if (width > 0) {
            err.print("\r" + " ".repeat(width) + "\r");
            err.flush();
        }
    }
}
