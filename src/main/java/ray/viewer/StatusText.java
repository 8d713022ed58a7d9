package ray.viewer;

import java.util.Locale;
import ray.Scene;

/** The status bar's one line for a job, from the job alone (so it is tested without a window). */
final class StatusText {

    private StatusText() {
    }

    static String of(RenderJob job, long nowNanos) {
        String name = job.file().getFileName().toString();
        return switch (job.state()) {
            case PARSING -> name + ": reading the scene...";
            case RENDERING -> name + ": " + rendering(job, nowNanos);
            case DONE -> name + ": " + done(job);
            case STOPPED -> name + ": stopped" + (job.progress() == null ? "" : " at " + percent(job.progress().fraction()))
                    + (job.partial() ? "; Save writes the finished tiles as a partial image" : "");
            case FAILED -> name + ": failed (details above)";
        };
    }

    /** {@code 42% · 1.2 s elapsed · about 1.7 s left · 0.61 M rays/s · 640x480, 3x3 AA}. */
    static String rendering(RenderJob job, long nowNanos) {
        var p = job.progress();
        long elapsed = p.elapsedNanos(nowNanos) + job.parseNanos();
        long left = p.remainingNanos(nowNanos);
        String pass = p.passes() > 1 ? "pass " + (p.pass() + 1) + " of " + p.passes() + " · " : "";
        long rays = job.raysSoFar(), rendering = p.elapsedNanos(nowNanos);
        String rate = rays > 0 && rendering > 0 ? String.format(Locale.ROOT, " · %.2f M rays/s", rays / (rendering / 1e9) / 1e6) : "";
        return pass + percent(p.fraction()) + " · " + seconds(elapsed) + " elapsed"
                + (left < 0 ? "" : " · about " + seconds(left) + " left") + rate + " · " + size(job) + plan(job);
    }

    /** {@code done in 2.31 s (read 0.05 s, render 2.26 s) · 1,234,567 rays, 0.53 M rays/s · 640x480, 3x3 AA}. */
    static String done(RenderJob job) {
        long total = job.parseNanos() + job.renderNanos();
        long rays = job.stats().total();
        double perSecond = job.renderNanos() > 0 ? rays / (job.renderNanos() / 1e9) : 0;
        return "done in " + seconds(total) + " (read " + seconds(job.parseNanos()) + ", render " + seconds(job.renderNanos())
                + ") · " + String.format(Locale.ROOT, "%,d rays, %.2f M rays/s", rays, perSecond / 1e6)
                + " · " + size(job) + plan(job);
    }

    private static String plan(RenderJob job) {
        return job.planSummary() == null ? "" : " · " + job.planSummary();
    }

    /** The image size and n_s the render uses (its resolved settings: the command line's override, else the scene's). */
    static String size(RenderJob job) {
        Scene s = job.scene();
        int ns = job.settings() != null ? job.settings().samples() : Math.max(1, s.samplesPerPixel);
        return s.width + "x" + s.height + ", " + ns + "x" + ns + " AA";
    }

    static String percent(double f) {
        return (int) Math.floor(100 * f) + "%";
    }

    /** 0.42 s, 12.3 s, 2 min 05 s. */
    static String seconds(long nanos) {
        double s = nanos / 1e9;
        if (s < 10) {
            return String.format(Locale.ROOT, "%.2f s", s);
        }
        if (s < 60) {
            return String.format(Locale.ROOT, "%.1f s", s);
        }
        long whole = Math.round(s);
        return whole / 60 + " min " + String.format(Locale.ROOT, "%02d", whole % 60) + " s";
    }
}
