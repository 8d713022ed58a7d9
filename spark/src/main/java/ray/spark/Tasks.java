package ray.spark;

import java.io.Serializable;
import org.apache.spark.api.java.function.Function;
import org.apache.spark.broadcast.Broadcast;
import ray.app.RenderReport;
import ray.render.SplitRender;

/** What a render job's tasks get and give back, and the function that runs on the executors. */
final class Tasks {

    private Tasks() {
    }

    /** One task: a rectangle of scene {@code scene}'s image, or (adaptive sampler) one tile of its error probes. */
    record Task(int scene, int x0, int y0, int x1, int y1, SplitRender.ProbeTile probes) implements Serializable {
        static Task tile(int scene, int x0, int y0, int x1, int y1) {
            return new Task(scene, x0, y0, x1, y1, null);
        }

        static Task probes(int scene, SplitRender.ProbeTile t) {
            return new Task(scene, t.x0, t.y0, t.x0 + t.width, t.y0 + t.height, t);
        }

        long pixels() {
            return (long) (x1 - x0) * (y1 - y0);
        }
    }

    /**
     * A task's result: the piece or the probes, or the one-line failure of a user's class (a failure
     * that would happen again: returned, not thrown, so Spark does not retry it); the executor's parse
     * and BVH figures for --stats.
     */
    record Result(int scene, SplitRender.Piece piece, SplitRender.ProbeResult probes, String failure, long buildNanos,
                  long bvhBytes, long primitives, String executor) implements Serializable {
    }

    /**
     * Renders one task on an executor with the scene from the broadcast, parsed and prepared once per JVM.
     * A failure a retry cannot mend (a user's class throwing, a StackOverflowError of its recursion) comes
     * back as the result's message; running out of memory is thrown, so Spark retries the task elsewhere.
     */
    static final class Render implements Function<Task, Result> {
        private static final long serialVersionUID = 1L;
        private final Broadcast<SceneBundle[]> bundles;
        private final int threads;

        Render(Broadcast<SceneBundle[]> bundles, int threads) {
            this.bundles = bundles;
            this.threads = threads;
        }

        @Override
        public Result call(Task t) {
            SceneBundle b = bundles.value()[t.scene()];
            String executor = org.apache.spark.SparkEnv.get() == null ? "" : org.apache.spark.SparkEnv.get().executorId();
            SceneBundle.Loaded l;
            try {
                l = b.load();
            } catch (RuntimeException e) {
                return new Result(t.scene(), null, null, "reading the scene on the executor failed: " + RenderReport.failure(e), 0, 0, 0, executor);
            }
            try {
                if (t.probes() != null) {
                    return new Result(t.scene(), null, SplitRender.probe(l.prepared, threads, t.probes()), null, l.buildNanos, l.bvhBytes,
                            l.primitives, executor);
                }
                SplitRender.Piece p = SplitRender.render(l.prepared, threads, t.x0(), t.y0(), t.x1(), t.y1());
                return new Result(t.scene(), p, null, null, l.buildNanos, l.bvhBytes, l.primitives, executor);
            } catch (OutOfMemoryError e) {
                throw e;
            } catch (Throwable e) {       // a user's own class failing, whatever it throws: the same on any retry
                return new Result(t.scene(), null, null, "rendering failed: " + RenderReport.failure(e), 0, 0, 0, executor);
            }
        }
    }
}
