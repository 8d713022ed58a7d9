package ray.render;

import java.util.concurrent.atomic.AtomicLong;
import ray.Scene;
import ray.settings.RenderSettings;

/**
 * How far a render is, by work done rather than by tiles: each finished tile counts its pixels times
 * the samples per pixel its pass takes (a 16 x 16 tile counts 256 pixels, a sliver at the image's edge
 * only its own; in a progressive render the first look of 1 sample per pixel counts far less than the
 * pass of 12 that follows), over the whole render's pixel-samples. The remaining time is extrapolated
 * from the elapsed time and that fraction. Thread-safe: render threads report, any thread reads. No
 * user interface: the viewer and the command line are two readers.
 */
public final class WorkProgress implements ProgressListener {

    private final long pixels;
    /** Samples per pixel of each pass, in order (one entry for a render without passes). */
    private final int[] passSamples;
    private final long total;
    private final long startNanos;
    private final AtomicLong done = new AtomicLong();
    private volatile int pass;
    private final ProgressListener next;

    /** A render of {@code width x height} pixels without passes, starting now, passing each report on to {@code next}. */
    public WorkProgress(int width, int height, ProgressListener next) {
        this(width, height, new int[] {1}, System.nanoTime(), next);
    }

    /**
     * A render of {@code width x height} pixels in passes of {@code passSamples[p]} samples per pixel
     * each, started at {@code startNanos} ({@link System#nanoTime()} scale).
     */
    public WorkProgress(int width, int height, int[] passSamples, long startNanos, ProgressListener next) {
        this.pixels = Math.max(1L, (long) width * height);
        this.passSamples = passSamples.clone();
        long perPixel = 0;
        for (int s : passSamples) {
            perPixel += s;
        }
        this.total = pixels * Math.max(1, perPixel);
        this.startNanos = startNanos;
        this.next = next;
    }

    /**
     * The progress of {@code scene} rendered with {@code settings}, starting now: its passes as the
     * renderer will make them (1, 4, 16, ... samples per pixel when progressive; an adaptive render's
     * second pass counted at its most, so it may end early).
     */
    public static WorkProgress of(Scene scene, RenderSettings settings, ProgressListener next) {
        RenderSettings s = settings.resolve(scene);
        int ns = s.samples(), all = ns * ns;
        int[] passes;
        if (!s.progressive()) {
            passes = new int[] {all};
        } else if (s.adaptive()) {
            int first = Math.min(4, all);                          // a first look of 4, then per-pixel refinement
            passes = new int[] {first, Math.max(1, all - first)};
        } else {
            int[] bounds = SampledRender.passBounds(all);
            passes = new int[bounds.length - 1];
            for (int p = 0; p < passes.length; p++) {
                passes[p] = bounds[p + 1] - bounds[p];
            }
        }
        return new WorkProgress(scene.width, scene.height, passes, System.nanoTime(), next);
    }

    @Override
    public void tileDone(Image image, int x0, int y0, int x1, int y1, int doneTiles, int totalTiles) {
        int p = Math.min(pass, passSamples.length - 1);
        done.addAndGet((long) (x1 - x0) * (y1 - y0) * passSamples[p]);
        next.tileDone(image, x0, y0, x1, y1, doneTiles, totalTiles);
    }

    @Override
    public void passDone(Image image, int finished, int passes) {
        pass = finished + 1;
        next.passDone(image, finished, passes);
    }

    /** The pass being rendered, from 0 (the last one once the render is over). */
    public int pass() {
        return Math.min(pass, passSamples.length - 1);
    }

    public int passes() {
        return passSamples.length;
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
