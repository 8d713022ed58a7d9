package ray.viewer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.parse.Parser;
import ray.render.Image;
import ray.render.Renderer;

/**
 * The viewer's model without a window: the session's thread is a queue the test drains, so every
 * event is seen in order. Images must equal the command line's renderer; errors must be whole and
 * keep the last finished image; stop must end the work and drop late events.
 */
class RenderSessionTest {

    static final String GOOD = """
            Width 40
            Height 30
            AASamples 2
            BGColor [0.1 0.2 0.3]
            AmbientLight [0.2 0.2 0.2]

            Camera Camera
            Vector3d eye [0 0 5]
            Vector3d target [0 0 0]
            double yFOV 40

            Material Diffuse red
            Vector3d diffuseColor [0.8 0.1 0.1]

            Surface Sphere
            Vector3d center [0 0 0]
            double radius 1
            ref material red

            Light PointLight
            Vector3d position [3 3 3]
            Vector3d intensity [20 20 20]
            """;

    /** Large and heavily supersampled: takes long enough to be stopped in the middle. */
    static final String SLOW = GOOD.replace("Width 40", "Width 1600").replace("Height 30", "Height 1200")
            .replace("AASamples 2", "AASamples 12");

    private final BlockingQueue<Runnable> thread = new LinkedBlockingQueue<>();
    private final Recorder events = new Recorder();
    private final RenderSession session = new RenderSession(thread::add, events, 2);

    /** Records the events and checks each tile belongs to the job being rendered. */
    static final class Recorder implements RenderSession.View {
        final List<String> log = new ArrayList<>();
        long pixels;
        /** The tiles' values as handed over (the last one of each pixel), and which pixels were. */
        Image seenImage;
        boolean[] seen;
        long seenPixels;
        RenderJob rendering;

        @Override
        public void parsing(RenderJob job) {
            log.add("parsing " + job.file().getFileName());
        }

        @Override
        public void rendering(RenderJob job) {
            rendering = job;
            pixels = 0;
            log.add("rendering " + job.file().getFileName());
        }

        @Override
        public void tile(RenderJob job, Image image, int x0, int y0, int x1, int y1) {
            assertSame(rendering, job, "a tile of a job that is not the one rendering");
            pixels += (long) (x1 - x0) * (y1 - y0);
            assertSame(job.partialImage(), image, "tiles arrive in the job's own copy");
            if (seenImage == null || seenImage.width != image.width || seenImage.height != image.height) {
                seenImage = new Image(image.width, image.height);
                seen = new boolean[image.width * image.height];
            }
            for (int y = y0; y < y1; y++) {
                for (int x = x0; x < x1; x++) {
                    int p = y * image.width + x;
                    System.arraycopy(image.rgb, 3 * p, seenImage.rgb, 3 * p, 3);
                    seenPixels += seen[p] ? 0 : 1;
                    seen[p] = true;
                }
            }
        }

        @Override
        public void ended(RenderJob job) {
            log.add("ended " + job.file().getFileName() + " " + job.state());
        }
    }

    /** Runs the session's events until {@code job} has finished (or 60 s pass, a failure). */
    private void runUntilFinished(RenderJob job) throws InterruptedException {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!job.finished()) {
            Runnable r = thread.poll(end - System.nanoTime(), TimeUnit.NANOSECONDS);
            assertNotNull(r, "no event within 60 s; log: " + events.log);
            r.run();
        }
    }

    private void runUntilRendering(RenderJob job) throws InterruptedException {
        while (job.state() == RenderJob.State.PARSING) {
            Runnable r = thread.poll(60, TimeUnit.SECONDS);
            assertNotNull(r, "no event within 60 s; log: " + events.log);
            r.run();
        }
    }

    static Path write(Path dir, String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text);
    }

    @Test
    void finishedImageIsTheCommandLinesImage(@TempDir Path dir) throws Exception {
        Path scene = write(dir, "good.txt", GOOD);
        RenderJob job = session.open(scene);
        runUntilFinished(job);
        assertEquals(RenderJob.State.DONE, job.state(), events.log::toString);
        Image expected = new Renderer(Parser.parse(scene)).render();
        assertArrayEquals(expected.rgb, job.image().rgb);
        assertEquals(2, job.progress().passes(), "2x2 samples: a first look of 1 per pixel, then the other 3");
        assertEquals(40 * 30 * 2, events.pixels, "every pixel arrives in exactly one tile per pass");
        assertEquals(1.0, job.progress().fraction());
        assertSame(job, session.shown());
        assertTrue(session.canSave());
        assertEquals(List.of("parsing good.txt", "rendering good.txt", "ended good.txt DONE"), events.log);
        // 4,800 camera rays, and a shadow ray at most for those of the 576 pixels that can see the sphere's box
        // (the plan's skips change nothing here: none is named)
        assertEquals("plan: direct light; at most 7,104 rays", job.planSummary());
        assertTrue(job.stats().get(ray.RayKind.CAMERA) == 40 * 30 * 4, "camera rays: " + job.stats());
    }

    /**
     * {@code raytracer --view --samples 4 --sampler jittered scene.txt}: the session renders with the
     * command line's settings over the scene's globals (it used to render the scene's own 2x2 grid), and
     * the image is the command line renderer's with the same settings.
     */
    @Test
    void theSessionsSettingsOverrideTheScenesGlobals(@TempDir Path dir) throws Exception {
        Path scene = Files.writeString(dir.resolve("good.txt"), GOOD);
        ray.settings.RenderSettings cli = new ray.settings.RenderSettings().samples(4).sampler("jittered").maxDepth(0);
        RenderSession s = new RenderSession(thread::add, events, 2, cli);
        RenderJob job = s.open(scene);
        runUntilFinished(job);
        assertEquals(RenderJob.State.DONE, job.state(), events.log::toString);
        assertEquals("jittered", job.settings().sampler());
        assertEquals(4, job.settings().samples());
        assertEquals(0, job.settings().maxDepth());
        assertEquals(40 * 30 * 16, job.stats().get(ray.RayKind.CAMERA), "4x4 samples per pixel: " + job.stats());
        ray.Scene parsed = Parser.parse(scene);
        assertArrayEquals(new Renderer(parsed).settings(cli).render().rgb, job.image().rgb);
        assertEquals(2, parsed.samplesPerPixel, "the scene's own global is left as it was read");
        assertTrue(StatusText.size(job).contains("4x4 AA"), StatusText.size(job));
    }

    @Test
    void badSceneShowsFileAndLineAndKeepsTheLastImage(@TempDir Path dir) throws Exception {
        Path scene = write(dir, "s.txt", GOOD);
        RenderJob good = session.open(scene);
        runUntilFinished(good);
        write(dir, "s.txt", GOOD.replace("double radius 1", "double radus 1"));
        RenderJob bad = session.open(scene);
        runUntilFinished(bad);
        assertEquals(RenderJob.State.FAILED, bad.state());
        assertTrue(bad.error().startsWith(scene + ":17: "), bad.error());
        assertTrue(bad.error().contains("radus"), bad.error());
        assertSame(good, session.shown(), "the last finished image stays and can be saved");
        assertFalse(events.log.contains("rendering s.txt") && events.log.lastIndexOf("rendering s.txt") > 2,
                "a scene that cannot be read never replaces the image: " + events.log);
        // fixing the file and rendering again works
        write(dir, "s.txt", GOOD);
        RenderJob fixed = session.open(scene);
        runUntilFinished(fixed);
        assertEquals(RenderJob.State.DONE, fixed.state());
        assertSame(fixed, session.shown());
    }

    @Test
    void userClassFailureNamesTheMethodOnOneLine(@TempDir Path dir) throws Exception {
        Path good = write(dir, "good.txt", GOOD);
        RenderJob first = session.open(good);
        runUntilFinished(first);
        Path scene = write(dir, "throws.txt", GOOD.replace("Material Diffuse red", "Material ThrowingMaterial red")
                .replace("Vector3d diffuseColor [0.8 0.1 0.1]\n", ""));
        RenderJob job = session.open(scene);
        runUntilFinished(job);
        assertEquals(RenderJob.State.FAILED, job.state());
        String e = job.error();
        assertTrue(e.startsWith(scene + ": rendering failed in ThrowingMaterial.shade (ThrowingMaterial.java:"), e);
        assertTrue(e.endsWith("UnsupportedOperationException: student code not finished"), e);
        assertNull(session.shown(), "another scene's image does not come back beside this scene's error");
        assertFalse(session.canSave());
        assertTrue(events.log.contains("rendering throws.txt"), events.log::toString);
    }

    /**
     * Whatever a user's class throws (an Error in terms() or shade(), an exception whose getMessage()
     * throws) ends the job as failed with one line: the viewer never waits for ever.
     */
    @Test
    void anyUserFailureEndsTheJob(@TempDir Path dir) throws Exception {
        String[][] cases = {
            {"ray.app.HostileRunTest$TermsError", "AssertionError: terms not written yet"},
            {"ray.app.UserFailureTest$Asserting", "AssertionError: invariant broken"},
            {"ray.app.UserFailureTest$BadMessage", "its getMessage() threw IllegalStateException"},
        };
        for (String[] c : cases) {
            Path scene = write(dir, "u.txt", GOOD.replace("Material Diffuse red", "Material " + c[0] + " red")
                    .replace("Vector3d diffuseColor [0.8 0.1 0.1]\n", ""));
            RenderJob job = session.open(scene);
            runUntilFinished(job);
            assertEquals(RenderJob.State.FAILED, job.state(), c[0]);
            assertTrue(job.error().startsWith(scene + ": rendering failed in ") && job.error().endsWith(c[1]), job.error());
        }
    }

    /** A FIFO opened in the viewer is refused at once, never waited on. */
    @Test
    void aFifoIsRefusedNotWaitedOn(@TempDir Path dir) throws Exception {
        Path fifo = dir.resolve("pipe.txt");
        org.junit.jupiter.api.Assumptions.assumeTrue(new ProcessBuilder("mkfifo", fifo.toString()).start().waitFor() == 0);
        RenderJob job = session.open(fifo);
        runUntilFinished(job);
        assertEquals(RenderJob.State.FAILED, job.state());
        assertTrue(job.error().startsWith(fifo + ": cannot read the scene: not a regular file (a FIFO)"), job.error());
    }

    @Test
    void aBadSceneAfterAGoodOneLeavesNoMixedState(@TempDir Path dir) throws Exception {
        RenderJob good = session.open(write(dir, "good.txt", GOOD));
        runUntilFinished(good);
        Path badFile = write(dir, "bad.txt", GOOD.replace("double radius 1", "double radus 1"));
        RenderJob bad = session.open(badFile);
        runUntilFinished(bad);
        assertEquals(RenderJob.State.FAILED, bad.state());
        assertNull(session.shown(), "good.txt's image would be shown (and saved as bad.png) beside bad.txt's error");
        assertFalse(session.canSave());
        assertSame(bad, session.current(), "Re-render targets the file whose error is shown");
    }

    @Test
    void missingFileIsReportedAndNothingCanBeSaved(@TempDir Path dir) throws Exception {
        RenderJob job = session.open(dir.resolve("nope.txt"));
        runUntilFinished(job);
        assertEquals(RenderJob.State.FAILED, job.state());
        assertEquals(dir.resolve("nope.txt") + ": cannot read the scene: no such file", job.error());
        assertNull(session.shown());
        assertFalse(session.canSave());
    }

    @Test
    void stopEndsTheRenderAndDropsItsLateEvents(@TempDir Path dir) throws Exception {
        Path scene = write(dir, "slow.txt", SLOW);
        RenderJob job = session.open(scene);
        runUntilRendering(job);
        while (events.seenPixels == 0) {                     // a few tiles on screen first
            Runnable r = thread.poll(60, TimeUnit.SECONDS);
            assertNotNull(r, "no tile within 60 s");
            r.run();
        }
        assertTrue(session.busy());
        session.stop();
        assertEquals(RenderJob.State.STOPPED, job.state());
        assertFalse(session.busy());
        assertSame(job, session.saveable(), "a stopped render's finished tiles can be saved, as a partial image");
        assertTrue(job.partial());
        assertTrue(SaveRules.suggestedTarget(job.file(), job.partial()).endsWith("slow-partial.png"));
        awaitNoRenderThreads();
        long pixelsAtStop = events.pixels;
        for (Runnable r; (r = thread.poll()) != null; ) {
            r.run();
        }
        assertEquals(pixelsAtStop, events.pixels, "tiles after stop are dropped");
        // the partial image is what the window showed: the tiles handed over, copied at once, black elsewhere
        Image partial = job.imageToSave();
        assertSame(job.partialImage(), partial);
        assertTrue(events.seenPixels > 0, "no tile before stop");
        for (int p = 0; p < partial.width * partial.height; p++) {
            if (events.seen[p]) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(events.seenImage.rgb[3 * p + c], partial.rgb[3 * p + c], "pixel " + p + ": not the tile shown");
                }
            }
        }
        assertTrue(job.progress().fraction() < 1, "the slow scene was stopped before its end");
        assertEquals("ended slow.txt STOPPED", events.log.get(events.log.size() - 1));
    }

    @Test
    void openingAnotherSceneStopsTheRunningOne(@TempDir Path dir) throws Exception {
        RenderJob slow = session.open(write(dir, "slow.txt", SLOW));
        runUntilRendering(slow);
        RenderJob good = session.open(write(dir, "good.txt", GOOD));
        assertEquals(RenderJob.State.STOPPED, slow.state());
        runUntilFinished(good);
        assertEquals(RenderJob.State.DONE, good.state());
        assertEquals(40 * 30 * 2, events.pixels, "no tile of the stopped scene reached the new image");
        assertSame(good, session.shown());
    }

    /** The stopped renderer's threads end (each finishes at most its current tile). */
    static void awaitNoRenderThreads() throws InterruptedException {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().startsWith("render-")) {
                t.join(30_000);
                assertFalse(t.isAlive(), t.getName() + " still runs 30 s after stop");
            }
        }
    }
}
