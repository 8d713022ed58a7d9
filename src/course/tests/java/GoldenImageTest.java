import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import javax.imageio.ImageIO;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Renders every scene in scenes/ with your code and compares it with its reference image in
 * reference-images/. On a difference it writes build/golden/SCENE.png: reference | yours | difference
 * side by side, and says what kind of difference it looks like.
 *
 * <p>How close is close enough: a pixel matches when each channel is within 2 of the reference's
 * (of 0..255). Pixels on an edge of the reference (a silhouette or shadow border, where a neighbour
 * differs by more than 24) may differ, up to 1% of the image: at an edge a tiny difference in where a
 * sample lands flips the pixel. Scenes that take long with a loop over all surfaces (more than
 * {@value #SLOW} ray-surface tests) are skipped unless you run {@code gradle test -PallScenes}.
 */
@Order(12)
@Tag("golden")
@DisplayName("12. The sample scenes against their reference images")
class GoldenImageTest {

    static final int TOLERANCE = 2, EDGE = 24;
    static final double EDGE_SHARE = 0.01;
    /** Estimated ray-surface tests above which a scene runs only with -PallScenes. */
    static final double SLOW = 4e8;

    static File scenes() {
        return new File(System.getProperty("course.scenes", "scenes"));
    }

    static File references() {
        return new File(System.getProperty("course.references", "reference-images"));
    }

    static File output() {
        return new File(System.getProperty("course.out", "build/golden"));
    }

    static List<String> sceneNames() {
        String[] files = scenes().list((d, n) -> n.endsWith(".txt"));
        List<String> names = new ArrayList<>();
        for (String f : files == null ? new String[0] : files) {
            String name = f.substring(0, f.length() - 4);
            if (new File(references(), name + ".png").isFile()) {
                names.add(name);
            }
        }
        names.sort(null);
        if (names.isEmpty()) {
            Expect.fail("no scenes with reference images in " + scenes().getAbsolutePath() + " and " + references().getAbsolutePath());
        }
        return names;
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("sceneNames")
    void matchesReference(String name) throws Exception {
        File sceneFile = new File(scenes(), name + ".txt");
        Scene scene;
        try {
            scene = Parser.parse(sceneFile);
        } catch (Parser.SceneFormatException e) {
            Expect.fail(e.getMessage());
            return;
        }
        double cost = (double) scene.width * scene.height * scene.samplesPerPixel * scene.samplesPerPixel
                * Math.max(1, scene.surfaces.size()) * (1 + scene.lights.size());
        Assumptions.assumeTrue(cost < SLOW || Boolean.getBoolean("course.allScenes"), name + " is slow with a loop over its "
                + scene.surfaces.size() + " surfaces (about " + String.format("%.0e", cost) + " ray-surface tests): run gradle test -PallScenes");
        Vector3d[][] image;
        try {
            RayTracer.prepare(scene);
            image = RayTracer.render(scene);
        } catch (RayTracer.RenderException e) {
            Expect.fail(sceneFile.getPath() + ": " + e.getMessage());
            return;
        }
        BufferedImage yours = RayTracer.toImage(image);
        BufferedImage reference = ImageIO.read(new File(references(), name + ".png"));
        String verdict = compare(reference, yours, scene);
        if (verdict != null) {
            File out = new File(output(), name + ".png");
            writeSideBySide(reference, yours, out);
            Expect.fail(name + ": " + verdict + "; open " + out.getPath() + " (reference | yours | difference)");
        }
    }

    /**
     * Null when the images match under the tolerance above; otherwise what kind of difference it is. To tell
     * highlights, the differing pixels are rendered again with your code and every BlinnPhong's specular
     * colour set to black: where either image is brighter than that, it has a highlight.
     */
    static String compare(BufferedImage ref, BufferedImage yours, Scene scene) {
        int w = ref.getWidth(), h = ref.getHeight();
        int pixels = w * h;
        Highlights highlights = new Highlights(scene);
        int bad = 0, badEdge = 0, badOffEdge = 0, brighter = 0, darker = 0, badHighlight = 0, worst = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int a = ref.getRGB(x, y), b = yours.getRGB(x, y);
                int d = maxChannelDifference(a, b);
                if (d <= TOLERANCE) {
                    continue;
                }
                bad++;
                worst = Math.max(worst, d);
                if (isEdge(ref, x, y)) {
                    badEdge++;
                } else {
                    badOffEdge++;
                }
                if (luminance(b) > luminance(a)) {
                    brighter++;
                } else {
                    darker++;
                }
                if (highlights.at(x, y, a, b)) {
                    badHighlight++;
                }
            }
        }
        if (badOffEdge == 0 && badEdge <= EDGE_SHARE * pixels) {
            return null;
        }
        String counts = String.format("%d of %d pixels differ by more than %d (largest difference %d of 255)", bad, pixels, TOLERANCE, worst);
        String kind;
        if (bad > pixels / 2) {
            kind = "the whole image is off: check the camera (recalculate, getRayThrough), then the shading of the most common material";
        } else if (badEdge >= 0.8 * bad) {
            kind = "only edges differ (silhouettes, shadow borders): check the pixel centres (x + 0.5), the AASamples grid,"
                    + " and where intersects counts a hit at the rims (tMin, tMax, the inside test of triangles)";
        } else if (badHighlight >= 0.8 * bad) {
            kind = "only highlights differ: check BlinnPhong's half vector h = normalize(l + v), v = -d made unit length,"
                    + " and the exponent";
        } else if (brighter >= 0.8 * bad) {
            kind = "yours is brighter in part of the image, likely where the reference has shadows: check PointLight.getIntensity's"
                    + " shadow ray (every surface, from the point towards the light, only between them)";
        } else if (darker >= 0.8 * bad) {
            kind = "yours is darker in part of the image: shadows where the reference has none (shadow acne: the shadow ray must"
                    + " start at t >= Ray.EPSILON and stop short of the light), missing light or a missing mirror reflection";
        } else {
            kind = "part of the image differs";
        }
        return counts + ": " + kind;
    }

    /** Where a scene has highlights: your render of a pixel with every BlinnPhong's specular colour black. */
    static final class Highlights {
        private final Scene scene;
        private final java.util.List<BlinnPhong> shiny = new ArrayList<>();

        Highlights(Scene scene) {
            this.scene = scene;
            if (scene != null) {
                for (Material m : scene.materials) {
                    if (m instanceof BlinnPhong && ((BlinnPhong) m).specularColor != null && ((BlinnPhong) m).specularColor.length() > 0) {
                        shiny.add((BlinnPhong) m);
                    }
                }
            }
        }

        /** True when the reference pixel {@code a} or yours {@code b} is brighter than pixel (x, y) without highlights. */
        boolean at(int x, int y, int a, int b) {
            if (shiny.isEmpty()) {
                return false;
            }
            Vector3d[] saved = new Vector3d[shiny.size()];
            for (int i = 0; i < saved.length; i++) {
                saved[i] = shiny.get(i).specularColor;
                shiny.get(i).specularColor = new Vector3d();
            }
            try {
                int plain = RayTracer.rgb(scene.renderPixel(x, y));
                return brighter(a, plain) || brighter(b, plain);
            } catch (RuntimeException e) {
                return false;
            } finally {
                for (int i = 0; i < saved.length; i++) {
                    shiny.get(i).specularColor = saved[i];
                }
            }
        }
    }

    /** True when a channel of {@code a} is above {@code b}'s by more than the tolerance. */
    static boolean brighter(int a, int b) {
        for (int shift = 0; shift <= 16; shift += 8) {
            if (((a >> shift) & 255) > ((b >> shift) & 255) + TOLERANCE) {
                return true;
            }
        }
        return false;
    }

    static boolean isEdge(BufferedImage ref, int x, int y) {
        int c = ref.getRGB(x, y);
        for (int dy = -1; dy <= 1; dy++) {
            for (int dx = -1; dx <= 1; dx++) {
                int nx = x + dx, ny = y + dy;
                if (nx >= 0 && ny >= 0 && nx < ref.getWidth() && ny < ref.getHeight()
                        && maxChannelDifference(c, ref.getRGB(nx, ny)) > EDGE) {
                    return true;
                }
            }
        }
        return false;
    }

    static int maxChannelDifference(int a, int b) {
        int d = 0;
        for (int s = 0; s <= 16; s += 8) {
            d = Math.max(d, Math.abs(((a >> s) & 255) - ((b >> s) & 255)));
        }
        return d;
    }

    static double luminance(int c) {
        return 0.2126 * ((c >> 16) & 255) + 0.7152 * ((c >> 8) & 255) + 0.0722 * (c & 255);
    }

    /**
     * reference | yours | difference: the difference shows pixels within the tolerance dark grey, the
     * others red where yours is brighter and blue where it is darker, brighter the larger the difference.
     */
    static void writeSideBySide(BufferedImage ref, BufferedImage yours, File out) throws IOException {
        int w = ref.getWidth(), h = ref.getHeight(), gap = 4;
        BufferedImage all = new BufferedImage(3 * w + 2 * gap, h, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = all.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, all.getWidth(), h);
        g.drawImage(ref, 0, 0, null);
        g.drawImage(yours, w + gap, 0, null);
        g.dispose();
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int a = ref.getRGB(x, y), b = yours.getRGB(x, y);
                int d = maxChannelDifference(a, b);
                int shade = d <= TOLERANCE ? 0x202020 : Math.min(255, 64 + 4 * d);
                int rgb = d <= TOLERANCE ? shade : luminance(b) > luminance(a) ? shade << 16 : shade;
                all.setRGB(2 * (w + gap) + x, y, rgb);
            }
        }
        out.getAbsoluteFile().getParentFile().mkdirs();
        ImageIO.write(all, "png", out);
    }
}
