package ray.course;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The handout's viewer as a student sees it, on a throw-away X server: {@code java RayTracer --view scene.txt}
 * with the reference solution shows the image row by row as the student's renderPixel computes it (a
 * screenshot with the top rows done and the rest not yet drawn), and ends showing exactly the reference image.
 * Photographed from outside with ImageMagick's {@code import}. Tag xvfb: run by {@code gradle viewerTest}.
 */
@Tag("xvfb")
class HandoutViewerXvfbTest {

    @TempDir
    Path dir;

    @Test
    void theViewerShowsRenderPixelRowByRowThenTheWholeImage() throws Exception {
        for (String tool : new String[] {"Xvfb", "import"}) {
            boolean found = false;
            for (String d : System.getenv().getOrDefault("PATH", "").split(":")) {
                found |= !d.isEmpty() && Files.isExecutable(Path.of(d, tool));
            }
            if (!found) {
                String why = tool + " is not installed (apt-get install xvfb imagemagick): the handout viewer's window test needs it";
                if (System.getenv("RAYTRACER_REQUIRE_XVFB") != null) {
                    fail(why);
                }
                Assumptions.abort(why);
            }
        }
        Process x = new ProcessBuilder("Xvfb", "-displayfd", "1", "-screen", "0", "800x600x24", "-nolisten", "tcp")
                .redirectError(dir.resolve("xvfb.log").toFile()).start();
        Process viewer = null;
        try {
            String n = new BufferedReader(new InputStreamReader(x.getInputStream(), StandardCharsets.US_ASCII)).readLine();
            assertTrue(n != null && n.trim().matches("\\d+"), "Xvfb did not start: " + Files.readString(dir.resolve("xvfb.log")));
            String display = ":" + n.trim();
            // a scene slow enough with a loop over its 1475 surfaces to be seen half done
            Files.copy(Path.of("scenes/antialias-3.txt"), dir.resolve("s.txt"));
            BufferedImage ref = ImageIO.read(new File("reference-images/antialias-3.png"));
            ProcessBuilder pb = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                    "-cp", Course.SOLUTION_CLASSES.toAbsolutePath() + File.pathSeparator + Course.jars(), "RayTracer", "--view", "s.txt")
                    .directory(dir.toFile()).redirectErrorStream(true).redirectOutput(dir.resolve("viewer.log").toFile());
            pb.environment().put("DISPLAY", display);
            viewer = pb.start();
            List<int[]> partial = new ArrayList<>();
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(150);
            int[] at = null;
            int shots = 0;
            while (at == null && System.nanoTime() < end && viewer.isAlive()) {
                BufferedImage shot = screenshot(display);
                shots++;
                at = find(shot, ref);
                int[] p = at == null ? partiallyDrawn(shot, ref) : null;
                if (p != null) {
                    partial.add(p);
                }
            }
            assertTrue(at != null, "after " + shots + " screenshots the window never showed the whole reference image; viewer log: "
                    + Files.readString(dir.resolve("viewer.log")));
            assertTrue(!partial.isEmpty(), "no screenshot of " + shots + " showed the image half drawn (top rows done, the rest not yet):"
                    + " the viewer must show renderPixel's results as they come in");
        } finally {
            if (viewer != null) {
                viewer.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            }
            x.destroy();
            x.waitFor(10, TimeUnit.SECONDS);
        }
    }

    private BufferedImage screenshot(String display) throws IOException, InterruptedException {
        Path png = dir.resolve("shot.png");
        Process p = new ProcessBuilder("import", "-display", display, "-window", "root", png.toString())
                .redirectErrorStream(true).redirectOutput(dir.resolve("import.log").toFile()).start();
        if (!p.waitFor(30, TimeUnit.SECONDS) || p.exitValue() != 0) {
            p.destroyForcibly();
            return new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        }
        BufferedImage b = ImageIO.read(png.toFile());
        return b == null ? new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB) : b;
    }

    /** Where {@code ref} appears whole in {@code shot} (x, y of its top-left corner), or null. */
    static int[] find(BufferedImage shot, BufferedImage ref) {
        for (int oy = 0; oy + ref.getHeight() <= shot.getHeight(); oy++) {
            for (int ox = 0; ox + ref.getWidth() <= shot.getWidth(); ox++) {
                if (rowsMatching(shot, ref, ox, oy) == ref.getHeight()) {
                    return new int[] {ox, oy};
                }
            }
        }
        return null;
    }

    /** Where {@code ref}'s top rows appear with only black (not yet drawn) below them: {x, y, rows done}, or null. */
    static int[] partiallyDrawn(BufferedImage shot, BufferedImage ref) {
        int w = ref.getWidth(), h = ref.getHeight();
        for (int oy = 0; oy + h <= shot.getHeight(); oy++) {
            for (int ox = 0; ox + w <= shot.getWidth(); ox++) {
                int done = rowsMatching(shot, ref, ox, oy);
                if (done > 0 && done < h - 1) {
                    boolean restBlack = true;
                    for (int y = done + 1; y < h && restBlack; y++) {
                        for (int x = 0; x < w && restBlack; x++) {
                            restBlack = (shot.getRGB(ox + x, oy + y) & 0xFFFFFF) == 0;
                        }
                    }
                    if (restBlack) {
                        return new int[] {ox, oy, done};
                    }
                }
            }
        }
        return null;
    }

    /** How many of {@code ref}'s rows, from the top, equal the shot's at (ox, oy). */
    static int rowsMatching(BufferedImage shot, BufferedImage ref, int ox, int oy) {
        for (int y = 0; y < ref.getHeight(); y++) {
            for (int x = 0; x < ref.getWidth(); x++) {
                if ((shot.getRGB(ox + x, oy + y) & 0xFFFFFF) != (ref.getRGB(x, y) & 0xFFFFFF)) {
                    return y;
                }
            }
        }
        return ref.getHeight();
    }
}
