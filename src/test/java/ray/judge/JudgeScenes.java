package ray.judge;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Random;
import java.util.function.Consumer;
import ray.IntersectionRecord;
import ray.Scene;
import ray.light.Light;
import ray.light.LightSample;
import ray.light.PointLight;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.Renderer;
import ray.settings.RenderSettings;

/** Renders of scenes/material-blinnphong.txt (three Blinn-Phong spheres on a floor, hard shadows) at 120 x 90, with planted changes. */
final class JudgeScenes {

    static final String BLINN_PHONG = "scenes/material-blinnphong.txt";

    private JudgeScenes() {
    }

    /**
     * The scene's text at 120 x 90 with {@code aa} x {@code aa} samples, after {@code replacements} (pairs: old,
     * new; each replaces the first occurrence only).
     */
    static String text(int aa, String... replacements) {
        try {
            String s = Files.readString(Path.of(BLINN_PHONG)).replace("Width 240", "Width 120").replace("Height 180", "Height 90");
            for (int i = 0; i < replacements.length; i += 2) {
                if (!s.contains(replacements[i])) {
                    throw new IllegalArgumentException("scene has no '" + replacements[i] + "'");
                }
                int at = s.indexOf(replacements[i]);
                s = s.substring(0, at) + replacements[i + 1] + s.substring(at + replacements[i].length());
            }
            return s + "\nAASamples " + aa + "\n";
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /** The render of {@code text}, rounded to 8 bits as the PNG holds it. */
    static Image render(String text, String sampler, Consumer<Scene> edit) {
        Scene scene;
        try {
            scene = Parser.parse(text, "judge-test.txt", new ArrayList<>());
        } catch (SceneFormatException e) {
            throw new IllegalStateException(e.getMessage(), e);
        }
        if (edit != null) {
            edit.accept(scene);
        }
        Renderer r = new Renderer(scene).threads(2);
        if (sampler != null) {
            r.settings(new RenderSettings().sampler(sampler));
        }
        return Images.quantised(r.render());
    }

    static Image render(String text) {
        return render(text, null, null);
    }

    /** A planted bug: every point light is replaced by one that claims its samples were shadow-tested, so nothing shadows it. */
    static void noShadows(Scene scene) {
        for (int i = 0; i < scene.lights.size(); i++) {
            Light l = scene.lights.get(i);
            if (l instanceof PointLight p) {
                PointLight bug = new PointLight() {
                    @Override
                    public boolean sample(IntersectionRecord record, Scene s, int index, LightSample out) {
                        boolean ok = super.sample(record, s, index, out);
                        out.shadowTested = true;
                        return ok;
                    }
                };
                bug.position = p.position;
                bug.intensity = p.intensity;
                bug.init();
                scene.lights.set(i, bug);
            }
        }
    }

    /**
     * {@code img} plus seeded independent noise of -amp to +amp whole steps per channel: harmless, zero-mean
     * noise, so values within amp of 0 or 255, which could move one way only, are left alone.
     */
    static Image noisy(Image img, int amp, long seed) {
        Random rnd = new Random(seed);
        Image out = new Image(img.width, img.height);
        for (int i = 0; i < img.rgb.length; i++) {
            int v = Image.toByte(img.rgb[i]), d = rnd.nextInt(2 * amp + 1) - amp;
            out.rgb[i] = (v >= amp && v <= 255 - amp ? v + d : v) / 255.0;
        }
        return out;
    }

    /** The largest channel difference in 8-bit steps: what a min/max judge looks at. */
    static int maxDifference(Image a, Image b) {
        int m = 0;
        for (int i = 0; i < a.rgb.length; i++) {
            m = Math.max(m, Math.abs(Image.toByte(a.rgb[i]) - Image.toByte(b.rgb[i])));
        }
        return m;
    }
}
