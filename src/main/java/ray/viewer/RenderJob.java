package ray.viewer;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import ray.RayStats;
import ray.Scene;
import ray.render.Image;
import ray.render.Renderer;
import ray.render.WorkProgress;
import ray.settings.RenderSettings;

/**
 * One attempt at showing a scene: read the file, then render it. Created and read on the session's
 * thread (the Swing event thread in the viewer); the parse and the render run on a background thread,
 * which fills in the fields below before handing the job back through the session.
 */
public final class RenderJob {

    /** Where a job is. Only the last three are final. */
    public enum State { PARSING, RENDERING, DONE, STOPPED, FAILED }

    final Path file;
    final long startNanos = System.nanoTime();
    final List<String> warnings = new ArrayList<>();
    volatile boolean cancelled;
    volatile Renderer renderer;
    volatile Scene scene;
    /** The render's settings, resolved against the scene (null until it is read). */
    volatile RenderSettings settings;
    volatile WorkProgress progress;
    /** The finished tiles so far (black elsewhere), copied as each tile ends: the window's and a partial save's image. */
    volatile Image partial;
    boolean stoppedWhileRendering;
    private State state = State.PARSING;
    long parseNanos;
    long renderNanos;
    Image image;
    RayStats stats;
    String error;
    volatile String planSummary;

    RenderJob(Path file) {
        this.file = file;
    }

    /** Rays the render has cast so far (a live figure while it runs), 0 before it starts. */
    long raysSoFar() {
        Renderer r = renderer;
        return r == null ? 0 : r.raysSoFar();
    }

    public Path file() {
        return file;
    }

    public State state() {
        return state;
    }

    void state(State s) {
        state = s;
    }

    public boolean finished() {
        return state == State.DONE || state == State.STOPPED || state == State.FAILED;
    }

    /** The scene as read (null while parsing or when it could not be read). */
    /** The settings the render resolved: the session's (e.g. the command line's) over the scene's globals; null before. */
    public RenderSettings settings() {
        return settings;
    }

    public Scene scene() {
        return scene;
    }

    /** Render progress by work (null before the render starts). */
    public WorkProgress progress() {
        return progress;
    }

    /** The finished image (null unless {@link State#DONE}). */
    public Image image() {
        return image;
    }

    /** The image rendered so far: finished tiles, black elsewhere (null before the render starts). */
    public Image partialImage() {
        return partial;
    }

    /** True when this job was stopped part way: what it can save is {@link #partialImage()}, named as partial. */
    public boolean partial() {
        return state == State.STOPPED && stoppedWhileRendering;
    }

    /** What Save writes for this job: the finished image, or the partial one of a stopped render. */
    public Image imageToSave() {
        return image != null ? image : partial() ? partial : null;
    }

    /** The whole error, e.g. {@code scene.txt:12: Sphere has no field 'radus' (...)} (null unless failed). */
    public String error() {
        return error;
    }

    /** Rays cast by the finished render, by kind (null unless {@link State#DONE}). */
    public RayStats stats() {
        return stats;
    }

    public long parseNanos() {
        return parseNanos;
    }

    public long renderNanos() {
        return renderNanos;
    }

    /** Parser warnings, e.g. zero-area triangles, as {@code file:line: warning: ...}. */
    public List<String> warnings() {
        return warnings;
    }

    /** The render plan's one-line summary, or null where there is none. */
    public String planSummary() {
        return planSummary;
    }

    /** Asks the job to stop: the renderer stops handing out work; a parse in progress is discarded. */
    void cancel() {
        cancelled = true;
        Renderer r = renderer;
        if (r != null) {
            r.cancel();
        }
    }
}
