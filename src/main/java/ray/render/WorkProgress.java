package ray.render;

import java.util.concurrent.atomic.AtomicLong;

/**
 * How far a render is, by work done rather than by tiles: each finished region counts its pixels
 * (a 16 x 16 tile counts 256, a sliver at the image's edge only its own pixels), so the fraction is
 * pixels done over pixels in the image. The remaining time is extrapolated from the elapsed time and
 * that fraction. Thread-safe: render threads report, any thread reads. No user interface: the viewer
 * and the command line are two readers.
 */
public final class WorkProgress implements ProgressListener {

    private final long total;
    private final long startNanos;
    private final AtomicLong done = new AtomicLong();
    private final ProgressListener next;

    /** A render of {@code width x height} pixels starting now, passing each report on to {@code next}. */
    public WorkProgress(int width, int height, ProgressListener next) {
        this(width, height, System.nanoTime(), next);
    }

    /** As above with an explicit start time ({@link System#nanoTime()} scale), for tests. */
    public WorkProgress(int width, int height, long startNanos, ProgressListener next) {
        this.total = Math.max(1L, (long) width * height);
        this.startNanos = startNanos;
        this.next = next;
    }

    @Override
    public void tileDone(Image image, int x0, int y0, int x1, int y1, int doneTiles, int totalTiles) {
        done.addAndGet((long) (x1 - x0) * (y1 - y0));
        next.tileDone(image, x0, y0, x1, y1, doneTiles, totalTiles);
    }

    /** Work done, from 0 to 1. */
    public double fraction() {
        return Math.min(1.0, (double) done.get() / total);
    }

    public long elapsedNanos(long nowNanos) {
        return nowNanos - startNanos;
    }

    /**
     * The time left at {@code nowNanos} if the rest goes as fast as what is done: elapsed x (1 - f) / f;
     * -1 while nothing is done (no basis for an estimate).
     */
    public long remainingNanos(long nowNanos) {
        double f = fraction();
        if (f <= 0) {
            return -1;
        }
        return Math.round(elapsedNanos(nowNanos) * (1 - f) / f);
    }
}
