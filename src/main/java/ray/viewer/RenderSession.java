package ray.viewer;

import java.nio.file.Path;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.atomic.AtomicBoolean;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.ProgressListener;
import ray.render.RenderCancelledException;
import ray.settings.RenderSettings;
import ray.render.Renderer;
import ray.render.WorkProgress;

/**
 * The viewer's model, without Swing: one scene at a time is read and rendered on a background thread
 * (parsing included, so the window never freezes), a newer request or {@link #stop()} cancels the
 * running one at once, and the session remembers which finished image is on screen, which is the only
 * thing that can be saved.
 *
 * <p>All methods are called, and every {@link View} callback arrives, on the session's thread: the
 * {@code executor} given to the constructor ({@code SwingUtilities::invokeLater} in the viewer, a
 * queue in tests). Background threads only post to it. Events of a job that is no longer the current
 * one are dropped, so a late tile of a cancelled render never reaches the screen.
 */
public final class RenderSession {

    /** What the window does with the session's events (all on the session's thread). */
    public interface View {
        /** {@code job} has started reading its file. */
        default void parsing(RenderJob job) {
        }

        /** The scene is read; its image (of the scene's size, black so far) replaces the one shown. */
        default void rendering(RenderJob job) {
        }

        /** Pixels [x0, x1) x [y0, y1) of {@code image} are final. */
        default void tile(RenderJob job, Image image, int x0, int y0, int x1, int y1) {
        }

        /**
         * {@code job} ended: done, stopped or failed. After a failure {@link #shown()} is the last finished
         * image of the same file, which the window puts back, or null (the window then shows none).
         */
        default void ended(RenderJob job) {
        }
    }

    private final Executor executor;
    private final View view;
    private final int threads;
    /** The settings every render starts from (the command line's, for {@code raytracer --view}); the scene's globals fill the rest. */
    private final RenderSettings base;
    private RenderJob current;
    private RenderJob shown;
    private RenderJob lastDone;

    public RenderSession(Executor executor, View view) {
        this(executor, view, Runtime.getRuntime().availableProcessors());
    }

    public RenderSession(Executor executor, View view, int threads) {
        this(executor, view, threads, new RenderSettings());
    }

    /** A session whose renders use {@code base} over each scene's globals (every render option the command line takes). */
    public RenderSession(Executor executor, View view, int threads, RenderSettings base) {
        this.executor = executor;
        this.view = view;
        this.threads = threads;
        this.base = base;
    }

    /** The job being read or rendered, or the last one if none is (null before the first). */
    public RenderJob current() {
        return current;
    }

    /** The finished job whose whole image is on screen, or null (nothing yet, a render in progress or stopped). */
    public RenderJob shown() {
        return shown;
    }

    /**
     * What Save writes now: the finished job whose image is on screen, or a render stopped part way whose
     * finished tiles are on screen (saved as a partial image, {@link RenderJob#partial()}); null when
     * there is nothing (nothing read yet, a render running, a failure).
     */
    public RenderJob saveable() {
        if (shown != null) {
            return shown;
        }
        RenderJob c = current;
        return c != null && c.state() == RenderJob.State.STOPPED && c.stoppedWhileRendering ? c : null;
    }

    /** True when there is an image to save ({@link #saveable()}). */
    public boolean canSave() {
        return saveable() != null;
    }

    public boolean busy() {
        return current != null && !current.finished();
    }

    /** Cancels whatever runs and starts reading and rendering {@code file} anew (reload and re-render too). */
    public RenderJob open(Path file) {
        stop();
        RenderJob job = new RenderJob(file);
        current = job;
        view.parsing(job);
        Thread t = new Thread(() -> run(job), "viewer-job");
        t.setDaemon(true);
        t.start();
        return job;
    }

    /** Stops the running job at once (its late events are dropped); the partial image stays on screen. */
    public void stop() {
        RenderJob job = current;
        if (job == null || job.finished()) {
            return;
        }
        job.cancel();
        if (job.state() == RenderJob.State.RENDERING) {
            shown = null;                 // the partial image of the stopped render is on screen
            job.stoppedWhileRendering = true;
        }
        job.state(RenderJob.State.STOPPED);
        view.ended(job);
    }

    // ---- the background thread: everything below posts back to the session's thread ----

    private void run(RenderJob job) {
        Scene scene;
        long t0 = System.nanoTime();
        try {
            scene = Parser.parse(job.file, job.warnings);
        } catch (SceneFormatException e) {
            fail(job, e.getMessage());
            return;
        } catch (OutOfMemoryError e) {
            fail(job, job.file + ": the scene is too large for this JVM's heap (raise it, e.g. JAVA_OPTS=-Xmx16g)");
            return;
        } catch (Throwable e) {     // a user class's init() (any Error too) or a parser bug: the job must end, never hang
            fail(job, ErrorTexts.describe(job.file + ": reading the scene failed", e));
            return;
        }
        job.parseNanos = System.nanoTime() - t0;
        if (job.cancelled) {
            return;
        }
        // a first look of one sample per pixel (then 4, 16, ...) where there are several; the final image is
        // the same bit for bit, and with one sample per pixel the grid's own fast path stays
        RenderSettings resolved = base.resolve(scene);
        RenderSettings settings = resolved.progressive(resolved.samples() > 1 || !"grid".equals(resolved.sampler()));
        job.settings = settings;
        Renderer renderer = new Renderer(scene).threads(threads).settings(settings);
        AtomicBoolean started = new AtomicBoolean(), drainPosted = new AtomicBoolean();
        Queue<Object[]> finished = new ConcurrentLinkedQueue<>();
        // Finished tiles are queued and handed over in batches, with at most one hand-over waiting on the
        // session's thread: thousands of small tiles a second must not flood the event queue (a window
        // that cannot paint or hear its Close).
        Runnable drain = () -> {
            drainPosted.set(false);
            for (Object[] t; (t = finished.poll()) != null; ) {
                int[] r = (int[]) t[1];
                view.tile(job, (Image) t[0], r[0], r[1], r[2], r[3]);
            }
        };
        Image partial = new Image(scene.width, scene.height);
        ProgressListener tiles = new ProgressListener() {
            @Override
            public void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                if (!started.getAndSet(true)) {
                    job.planSummary = PlanSummary.of(renderer.plan());     // the render's own plan, derived before the first tile
                }
                if (job.cancelled) {
                    return;                  // stopped: the partial image keeps what the window was given
                }
                // the finished tile, copied at once (a progressive render's next pass rewrites the render's
                // own image): the window shows, and a stopped render saves, finished tiles only
                for (int y = y0; y < y1; y++) {
                    int i = 3 * (y * image.width + x0);
                    System.arraycopy(image.rgb, i, partial.rgb, i, 3 * (x1 - x0));
                }
                finished.add(new Object[] {partial, new int[] {x0, y0, x1, y1}});
                if (!drainPosted.getAndSet(true)) {
                    post(job, drain);
                }
            }
        };
        job.progress = WorkProgress.of(scene, settings, tiles);
        renderer.listener(job.progress);
        job.scene = scene;
        job.partial = partial;
        job.renderer = renderer;
        if (job.cancelled) {              // stop() came between the check above and the renderer being set
            return;
        }
        post(job, () -> {
            job.state(RenderJob.State.RENDERING);
            shown = null;
            view.rendering(job);
        });
        long t1 = System.nanoTime();
        try {
            Image image = renderer.render();
            job.renderNanos = System.nanoTime() - t1;
            post(job, () -> {
                job.image = image;
                job.stats = renderer.stats();
                job.state(RenderJob.State.DONE);
                shown = job;
                lastDone = job;
                view.ended(job);
            });
        } catch (RenderCancelledException e) {
            // stop() or a newer job: already reported
        } catch (OutOfMemoryError e) {
            fail(job, job.file + ": out of memory while rendering (raise the heap, e.g. JAVA_OPTS=-Xmx16g)");
        } catch (Throwable e) {     // whatever a user's class throws (AssertionError, a checked one sneakily): never a hang
            fail(job, ErrorTexts.describe(job.file + ": rendering failed", e));
        }
    }

    private void fail(RenderJob job, String message) {
        post(job, () -> {
            job.error = ray.Failures.oneLine(message);
            job.state(RenderJob.State.FAILED);
            // the last finished image comes back only if it is of this very file (a re-render that failed):
            // another scene's image, title and Save suggestion beside this file's error would mix two states
            shown = lastDone != null && lastDone.file.equals(job.file) ? lastDone : null;
            view.ended(job);
        });
    }

    /** Runs {@code r} on the session's thread if {@code job} is still current and running by then. */
    private void post(RenderJob job, Runnable r) {
        executor.execute(() -> {
            if (job == current && !job.finished()) {
                r.run();
            }
        });
    }
}
