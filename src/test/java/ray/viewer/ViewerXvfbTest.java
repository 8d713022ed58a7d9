package ray.viewer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.Point;
import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.app.Main;

/**
 * The viewer as a user meets it, on a throw-away X server (Xvfb), driven from outside by xdotool and
 * photographed by ImageMagick's {@code import}: the window shows exactly the command line's pixels,
 * saving over an existing file happens only after "Replace", watch mode renders a scene changed on
 * disk, and closing the window in the middle of
 * a long render ends the process at once. Run by the {@code viewerTest} task (tag {@code xvfb}), which
 * {@code gradle test} runs too; skipped with a message where Xvfb, xdotool or ImageMagick are not
 * installed, unless {@code RAYTRACER_REQUIRE_XVFB} is set (CI sets it), where that is a failure.
 */
@Tag("xvfb")
class ViewerXvfbTest {

    private static Process xvfb;
    private static String display;
    @TempDir
    static Path work;

    @BeforeAll
    static void startX() throws IOException {
        boolean x11 = Files.exists(Path.of(System.getProperty("java.home"), "lib", "libawt_xawt.so"));
        for (String tool : new String[] {"Xvfb", "xdotool", "import", x11 ? "" : "libawt_xawt.so"}) {
            if (!tool.isEmpty() && !(tool.endsWith(".so") ? x11 : onPath(tool))) {
                String why = tool + " is not installed (apt-get install xvfb xdotool imagemagick, and a JDK with its X11 "
                        + "libraries, not only -headless); the viewer's window test needs it";
                if (System.getenv("RAYTRACER_REQUIRE_XVFB") != null) {
                    fail(why);
                }
                Assumptions.abort(why);
            }
        }
        // -displayfd: the server picks a free display and writes its number once it accepts clients; -noreset:
        // it does not reset (refusing clients meanwhile) each time its last client, a viewer that quit, leaves
        xvfb = new ProcessBuilder("Xvfb", "-displayfd", "1", "-screen", "0", "1280x1024x24", "-nolisten", "tcp", "-noreset")
                .redirectError(work.resolve("xvfb.log").toFile()).start();
        BufferedReader r = new BufferedReader(new InputStreamReader(xvfb.getInputStream(), StandardCharsets.US_ASCII));
        String n = r.readLine();
        assertTrue(n != null && n.trim().matches("\\d+"), "Xvfb did not start: " + Files.readString(work.resolve("xvfb.log")));
        display = ":" + n.trim();
    }

    @AfterAll
    static void stopX() throws InterruptedException {
        if (xvfb != null) {
            xvfb.destroy();
            xvfb.waitFor(10, TimeUnit.SECONDS);
        }
    }

    private static boolean onPath(String tool) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(":")) {
            if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, tool))) {
                return true;
            }
        }
        return false;
    }

    @Test
    void windowShowsTheCommandLinesPixelsAndSavingAsksBeforeReplacing() throws Exception {
        Path dir = Files.createDirectories(work.resolve("save"));
        Path scene = Files.writeString(dir.resolve("scene.txt"), RenderSessionTest.GOOD
                .replace("Width 40", "Width 200").replace("Height 30", "Height 150"));
        Path cliPng = dir.resolve("cli.png");
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assertEquals(0, Main.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err), scene.toString(), "-o", cliPng.toString()),
                err::toString);
        BufferedImage expected = ImageIO.read(cliPng.toFile());
        // an earlier image (a PNG: a file that is no PNG is never replaced, asked or not) that must survive until the user agrees
        byte[] precious = "\u0089PNG\r\n\u001a\nan earlier image that must survive".getBytes(StandardCharsets.ISO_8859_1);
        Path suggested = Files.write(dir.resolve("scene.png"), precious);     // where Save suggests writing

        Process viewer = startViewer(scene);
        try {
            String window = waitForWindow("RayTracer viewer - scene.txt", viewer);
            // the render done, the window holds the CLI's image pixel for pixel (1:1: it fits the window)
            Point at = waitForImage(expected, viewer);
            assertTrue(at.x >= 0, "image found at " + at);

            // Save: the suggested scene.png exists, so the viewer must ask; "Cancel" (the default) keeps it
            focus(window);
            key("ctrl+s");
            waitForWindow("Save image as PNG", viewer);
            key("Return");
            waitForWindow("Replace file?", viewer);
            assertArrayEquals(precious, Files.readAllBytes(suggested), "replaced before the user answered");
            key("Return");
            waitForNoWindow("Replace file?");
            waitForWindow("Save image as PNG", viewer);          // back in the chooser
            key("Escape");
            waitForNoWindow("Save image as PNG");
            assertArrayEquals(precious, Files.readAllBytes(suggested), "replaced although the user cancelled");

            // and "Replace" writes exactly the command line's PNG
            focus(window);
            key("ctrl+s");
            waitForWindow("Save image as PNG", viewer);
            key("Return");
            waitForWindow("Replace file?", viewer);
            key("shift+Tab", "space");
            byte[] cli = Files.readAllBytes(cliPng);
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
            while (!Arrays.equals(cli, Files.readAllBytes(suggested)) && System.nanoTime() < end) {
                Thread.sleep(100);
            }
            assertArrayEquals(cli, Files.readAllBytes(suggested), "the saved PNG is not the command line's");
            try (var files = Files.list(dir)) {
                assertEquals(List.of("cli.png", "scene.png", "scene.txt"), files.map(p -> p.getFileName().toString()).sorted().toList(),
                        "no temporary file left");
            }

            // watch mode: the scene changed on disk is rendered again, by itself
            focus(window);
            key("ctrl+shift+w");
            Thread.sleep(700);                                   // the watch starts from the file as it is now
            Path edited = Files.createDirectories(work.resolve("edited"));
            String greener = Files.readString(scene).replace("BGColor [0.1 0.2 0.3]", "BGColor [0.1 0.6 0.3]");
            assertEquals(0, Main.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err),
                    Files.writeString(edited.resolve("scene.txt"), greener).toString(), "-o", edited.resolve("cli.png").toString()), err::toString);
            Files.writeString(scene, greener);
            waitForImage(ImageIO.read(edited.resolve("cli.png").toFile()), viewer);

            focus(window);
            key("ctrl+q");
            assertTrue(viewer.waitFor(20, TimeUnit.SECONDS), "Quit did not end the process");
        } finally {
            viewer.destroyForcibly();
        }
    }

    @Test
    void closingTheWindowMidRenderEndsTheProcessWithoutFinishingTheRender() throws Exception {
        // 1600x1200 at 12x12 samples: minutes of work on any machine, so a process that waited for the render
        // to finish would still run after 20 s; the bound is generous because a loaded machine (xdotool's key
        // event, AWT's shutdown) can take seconds where an idle one takes about 0.2 s (printed below).
        Path scene = Files.writeString(work.resolve("slow.txt"), RenderSessionTest.SLOW);
        Process viewer = startViewer(scene);
        try {
            String window = waitForWindow("RayTracer viewer - slow.txt", viewer);   // titled once rendering starts
            Thread.sleep(1000);
            assertTrue(viewer.isAlive(), "the viewer ended on its own");
            focus(window);
            key("ctrl+w");
            long t0 = System.nanoTime();
            boolean ended = viewer.waitFor(20, TimeUnit.SECONDS);
            assertTrue(ended, "the process still runs 20 s after its only window was closed (is it finishing the render?)");
            assertEquals(0, viewer.exitValue());
            System.out.printf("viewer process ended %.2f s after Close window%n", (System.nanoTime() - t0) / 1e9);
        } finally {
            viewer.destroyForcibly();
        }
    }

    @Test
    void watchWithoutASceneSaysSoAndWatchRightAfterOpeningCatchesASameSizeEdit() throws Exception {
        Process empty = startViewer();
        try {
            String window = waitForWindow("RayTracer viewer", empty);
            focus(window);
            key("ctrl+shift+w");
            Thread.sleep(800);
            assertTrue(empty.isAlive());
            String log = Files.readString(work.resolve("viewer-none.log"));
            assertTrue(!log.contains("Exception"), "Watch with no scene: " + log);
            assertEquals(window, run("xdotool", "search", "--name", exactly("RayTracer viewer")).lines().findFirst().orElse(""),
                    "the title does not claim a watch");
            key("ctrl+q");
            assertTrue(empty.waitFor(20, TimeUnit.SECONDS));
        } finally {
            empty.destroyForcibly();
        }

        Path dir = Files.createDirectories(work.resolve("watch"));
        Path scene = Files.writeString(dir.resolve("w.txt"), RenderSessionTest.GOOD);
        Process viewer = startViewer(scene);
        try {
            String window = waitForWindow("RayTracer viewer - w.txt", viewer);
            focus(window);
            key("ctrl+shift+w");                                   // at once, while the first render may still run
            waitForWindow("RayTracer viewer - w.txt (watching)", viewer);
            String greener = Files.readString(scene).replace("BGColor [0.1 0.2 0.3]", "BGColor [0.1 0.6 0.3]");
            Path edited = Files.createDirectories(work.resolve("watch-edited"));
            ByteArrayOutputStream err = new ByteArrayOutputStream();
            assertEquals(0, Main.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err),
                    Files.writeString(edited.resolve("w.txt"), greener).toString(), "-o", edited.resolve("cli.png").toString()), err::toString);
            var time = Files.getLastModifiedTime(scene);
            Files.writeString(scene, greener);                     // the same size ...
            Files.setLastModifiedTime(scene, time);                // ... and time stamp: only the content tells
            waitForImage(ImageIO.read(edited.resolve("cli.png").toFile()), viewer);
        } finally {
            viewer.destroyForcibly();
        }
    }

    @Test
    void viewOpensAWindowPerSceneAndComparesWithTheScenesReference() throws Exception {
        Path dir = Files.createDirectories(work.resolve("compare/scenes"));
        Path refs = Files.createDirectories(work.resolve("compare/reference-images"));
        Path a = Files.writeString(dir.resolve("a.txt"), RenderSessionTest.GOOD.replace("Width 40", "Width 160").replace("Height 30", "Height 120"));
        Path b = Files.writeString(dir.resolve("b.txt"), RenderSessionTest.GOOD);
        // a's reference: the same scene with a brighter light, as a student's render would differ from the course's
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        Path refScene = Files.writeString(work.resolve("compare/ref.txt"), Files.readString(a).replace("[20 20 20]", "[26 26 26]"));
        assertEquals(0, Main.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err), refScene.toString(),
                "-o", refs.resolve("a.png").toString()), err::toString);
        assertEquals(0, Main.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err), a.toString(),
                "-o", work.resolve("compare/a-cli.png").toString()), err::toString);
        BufferedImage render = ImageIO.read(work.resolve("compare/a-cli.png").toFile()), ref = ImageIO.read(refs.resolve("a.png").toFile());
        Process viewer = startViewer(a, b);
        try {
            String window = waitForWindow("RayTracer viewer - a.txt", viewer);
            String other = waitForWindow("RayTracer viewer - b.txt", viewer);      // was silently dropped
            run("xdotool", "windowmove", other, "0", "600");        // no window manager: b would cover a
            waitForImage(render, viewer);
            focus(window);
            key("ctrl+4");                                         // the difference, from the scene's own reference-images/a.png
            Compare c = Compare.of(render, ref);
            assertTrue(c.overOneStep() > 100, "the two renders differ: " + c.summary());
            BufferedImage heat = c.heatMap();
            waitForImage(heat.getSubimage(0, 0, heat.getWidth(), heat.getHeight() / 2), viewer);
            key("ctrl+t");                                          // A/B: from the difference, the render ...
            waitForImage(render, viewer);
            key("ctrl+t");                                          // ... the reference ...
            waitForImage(ref, viewer);
            key("ctrl+2");                                          // ... and the render again
            waitForImage(render, viewer);
            key("ctrl+e", "ctrl+e");                                // one stop brighter
            BufferedImage brighter = new BufferedImage(render.getWidth(), render.getHeight(), BufferedImage.TYPE_INT_RGB);
            ray.render.Image lin = new ray.render.Renderer(ray.parse.Parser.parse(a)).render();
            for (int y = 0; y < lin.height; y++) {
                for (int x = 0; x < lin.width; x++) {
                    int i = 3 * (y * lin.width + x);
                    brighter.setRGB(x, y, ray.render.Image.toByte(2 * lin.rgb[i]) << 16 | ray.render.Image.toByte(2 * lin.rgb[i + 1]) << 8
                            | ray.render.Image.toByte(2 * lin.rgb[i + 2]));
                }
            }
            waitForImage(brighter, viewer);
            focus(window);
            key("ctrl+q");
            assertTrue(viewer.waitFor(20, TimeUnit.SECONDS), "Quit did not end the process");
        } finally {
            viewer.destroyForcibly();
        }
    }

    private Process startViewer(Path... scenes) throws IOException {
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of(java, "-cp", System.getProperty("java.class.path"),
                "-Djava.awt.headless=false", "-Djava.util.prefs.userRoot=" + work.resolve("prefs"), "RayTracer"));
        if (scenes.length > 0) {
            cmd.add("--view");
        }
        for (Path s : scenes) {
            cmd.add(s.toString());
        }
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().put("DISPLAY", display);
        String name = scenes.length == 0 ? "none" : scenes[0].getFileName().toString();
        pb.redirectErrorStream(true).redirectOutput(work.resolve("viewer-" + name + ".log").toFile());
        return pb.start();
    }

    private static String run(String... cmd) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true);
        pb.environment().put("DISPLAY", display);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        p.waitFor();
        return out;
    }

    private static void key(String... keys) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of("xdotool", "key", "--delay", "100"));
        cmd.addAll(List.of(keys));
        run(cmd.toArray(new String[0]));
    }

    /** A click into the window gives it the keyboard (there is no window manager to do it). */
    private static void focus(String window) throws IOException, InterruptedException {
        run("xdotool", "mousemove", "--window", window, "60", "60", "click", "1");
        Thread.sleep(400);
    }

    private static String waitForWindow(String title, Process viewer) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < end) {
            String ids = run("xdotool", "search", "--name", exactly(title));
            if (!ids.isEmpty() && ids.lines().allMatch(l -> l.matches("\\d+"))) {
                return ids.lines().findFirst().orElseThrow();
            }
            if (!viewer.isAlive()) {
                fail("the viewer ended while waiting for '" + title + "': " + log(viewer));
            }
            Thread.sleep(100);
        }
        shot("no-window");
        return fail("no window '" + title + "' within 60 s");
    }

    private static void waitForNoWindow(String title) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!run("xdotool", "search", "--name", exactly(title)).isEmpty()) {
            if (System.nanoTime() > end) {
                shot("window-stays");
                fail("window '" + title + "' still open after 20 s");
            }
            Thread.sleep(100);
        }
    }

    /** A POSIX regular expression (xdotool's) matching {@code title} only. */
    private static String exactly(String title) {
        return "^" + title.replaceAll("[.^$*+?()\\[\\]{}|\\\\]", "\\\\$0") + "$";
    }

    private static String log(Process viewer) throws IOException {
        try (var files = Files.list(work)) {
            return files.filter(p -> p.getFileName().toString().startsWith("viewer-")).map(p -> {
                try {
                    return Files.readString(p);
                } catch (IOException e) {
                    return "";
                }
            }).reduce("", String::concat);
        }
    }

    /** Screenshots until {@code expected} appears pixel for pixel somewhere on screen (60 s at most). */
    private static Point waitForImage(BufferedImage expected, Process viewer) throws Exception {
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (true) {
            BufferedImage screen = shot(null);
            Point at = find(screen, expected);
            if (at != null) {
                return at;
            }
            if (System.nanoTime() > end || !viewer.isAlive()) {
                Path saved = shot("image-not-found") != null ? Path.of("build", "viewer-test", "image-not-found.png") : null;
                return fail("the window never showed the CLI's image pixel for pixel (screenshot: " + saved + "); " + log(viewer));
            }
            Thread.sleep(300);
        }
    }

    /** The whole screen; with a name, also kept under build/viewer-test/ for a person to look at. */
    private static BufferedImage shot(String keep) throws IOException, InterruptedException {
        Path png = work.resolve("screen.png");
        run("import", "-window", "root", "png:" + png);
        if (keep != null) {
            Path dir = Files.createDirectories(Path.of("build", "viewer-test"));
            Files.copy(png, dir.resolve(keep + ".png"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        return ImageIO.read(png.toFile());
    }

    /** Where {@code img} occurs in {@code screen} exactly (RGB, every pixel), or null. */
    static Point find(BufferedImage screen, BufferedImage img) {
        int sw = screen.getWidth(), sh = screen.getHeight(), w = img.getWidth(), h = img.getHeight();
        int[] s = screen.getRGB(0, 0, sw, sh, null, 0, sw);
        int[] m = img.getRGB(0, 0, w, h, null, 0, w);
        for (int y = 0; y + h <= sh; y++) {
            for (int x = 0; x + w <= sw; x++) {
                if (((s[y * sw + x] ^ m[0]) & 0xffffff) == 0 && matches(s, sw, x, y, m, w, h)) {
                    return new Point(x, y);
                }
            }
        }
        return null;
    }

    private static boolean matches(int[] s, int sw, int x, int y, int[] m, int w, int h) {
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                if (((s[(y + j) * sw + x + i] ^ m[j * w + i]) & 0xffffff) != 0) {
                    return false;
                }
            }
        }
        return true;
    }
}
