package ray.spark;

import java.io.PrintStream;

/**
 * The driver's progress line on stderr (only when it is a terminal, as {@code raytracer}'s): tasks done
 * of total, scenes written, and the time left at the rate so far.
 */
final class Progress {

    private final PrintStream err;
    private final boolean show;
    private long total, done, scenes, start, lastDraw;
    private int width;

    /** What a job is done with, counted beside the tasks: scene (the render) or submission (grade). */
    private final String noun;

    Progress(PrintStream err, boolean show) {
        this(err, show, "scene");
    }

    Progress(PrintStream err, boolean show, String noun) {
        this.err = err;
        this.show = show;
        this.noun = noun;
    }

    void start(long tasks, long sceneCount) {
        total = tasks;
        scenes = sceneCount;
        start = System.nanoTime();
    }

    /** More tasks (a second stage) on top of the total. */
    void more(long tasks) {
        total += tasks;
    }

    void done(long tasks, long scenesDone) {
        done += tasks;
        long now = System.nanoTime();
        if (show && now - lastDraw > 250_000_000L) {
            lastDraw = now;
            String s = line(done, total, scenesDone, scenes, noun, now - start);
            width = Math.max(width, s.length());
            err.print("\r" + s + " ".repeat(width - s.length()));
            err.flush();
        }
    }

    /** {@code 12 of 40 tasks, 1 of 3 scenes, about 20 s left}. */
    static String line(long done, long total, long scenesDone, long scenes, long elapsedNanos) {
        return line(done, total, scenesDone, scenes, "scene", elapsedNanos);
    }

    static String line(long done, long total, long unitsDone, long units, String noun, long elapsedNanos) {
        String left = done == 0 ? "" : ", about " + seconds((double) elapsedNanos / done * (total - done) / 1e9) + " left";
        return "raytracer-spark: " + done + " of " + total + " tasks, " + unitsDone + " of " + units + " " + noun + (units == 1 ? "" : "s")
                + left;
    }

    private static String seconds(double s) {
        return s < 90 ? Math.round(s) + " s" : s < 5400 ? Math.round(s / 60) + " min" : Math.round(s / 360) / 10.0 + " h";
    }

    void clear() {
        if (width > 0) {
            err.print("\r" + " ".repeat(width) + "\r");
            err.flush();
            width = 0;
        }
    }
}
