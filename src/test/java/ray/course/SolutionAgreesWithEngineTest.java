package ray.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.lang.reflect.Method;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.IntStream;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import ray.parse.Parser;

/**
 * The reference solution (a loop over surfaces, Ray.EPSILON offsets) renders every scene the 2003 features
 * cover as the engine does (BVH, error-bound offsets), within the golden tolerance of one 8-bit step per
 * channel. Large scenes are compared on an evenly spread subset of their pixels (every k-th row and column,
 * k chosen so each scene costs at most about {@value #BUDGET} ray-surface tests): the naive loop renders the
 * whole showcase in minutes.
 */
@Tag("slow")
class SolutionAgreesWithEngineTest {

    static final double BUDGET = 1e7;
    static final int TOLERANCE = 1;

    /** One loader for all scenes: the solution's classes are compiled by the JIT once. */
    static final java.util.function.Supplier<ClassLoader> SOLUTION = new java.util.function.Supplier<>() {
        private ClassLoader loader;

        @Override
        public synchronized ClassLoader get() {
            if (loader == null) {
                loader = Course.loader(Course.SOLUTION_CLASSES);
            }
            return loader;
        }
    };

    static List<String> scenes() throws java.io.IOException {
        return Handout.scenes2003(Path.of("scenes"), Path.of("reference-images"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void solutionMatchesTheEngine(String name) throws Exception {
        Path file = Path.of("scenes", name + ".txt");
        java.awt.image.BufferedImage engine = new ray.render.Renderer(Parser.parse(file)).render().toBufferedImage();

        ClassLoader course = SOLUTION.get();
        Class<?> parser = course.loadClass("Parser"), rayTracer = course.loadClass("RayTracer"), sceneClass = course.loadClass("Scene");
        Object scene = parser.getMethod("parse", File.class).invoke(null, file.toFile());
        rayTracer.getMethod("prepare", sceneClass).invoke(null, scene);
        Method renderPixel = sceneClass.getMethod("renderPixel", int.class, int.class);
        int w = sceneClass.getField("width").getInt(scene), h = sceneClass.getField("height").getInt(scene);
        int n = sceneClass.getField("samplesPerPixel").getInt(scene);
        int surfaces = ((List<?>) sceneClass.getField("surfaces").get(scene)).size(), lights = ((List<?>) sceneClass.getField("lights").get(scene)).size();
        boolean mirrors = ((List<?>) sceneClass.getField("materials").get(scene)).stream()
                .anyMatch(m -> m.getClass().getSimpleName().equals("GlazedMaterial"));
        int depth = mirrors ? Math.min(3, sceneClass.getField("maxDepth").getInt(scene)) : 0;
        double cost = (double) w * h * n * n * surfaces * (1 + lights) * (1 + depth);
        // at least about 100 pixels, however costly the scene
        int k = (int) Math.max(1, Math.min(Math.ceil(Math.sqrt(cost / BUDGET)), Math.floor(Math.sqrt(w * h / 100.0))));
        assertEquals(w, engine.getWidth());
        assertEquals(h, engine.getHeight());

        AtomicInteger compared = new AtomicInteger(), differing = new AtomicInteger();
        StringBuffer first = new StringBuffer();
        IntStream.range(0, (h + k - 1) / k).parallel().forEach(row -> {
            int y = Math.min(h - 1, row * k + (k / 2) * (row & 1));   // alternate rows shifted: no two sampled columns line up
            for (int x = (row * 7) % k; x < w; x += k) {
                Vector3d c;
                try {
                    c = (Vector3d) renderPixel.invoke(scene, x, y);
                } catch (ReflectiveOperationException e) {
                    throw new IllegalStateException(e.getCause());
                }
                compared.incrementAndGet();
                int a = rgb(c), b = engine.getRGB(x, y) & 0xFFFFFF;
                if (maxChannelDifference(a, b) > TOLERANCE && differing.getAndIncrement() == 0) {
                    first.append(String.format("pixel (%d, %d): solution #%06x, engine #%06x", x, y, a, b));
                }
            }
        });
        assertTrue(compared.get() >= Math.min(w * h, 90), name + ": compared " + compared.get() + " pixels");
        assertEquals(0, differing.get(), name + ": " + differing.get() + " of " + compared.get() + " compared pixels (every " + k
                + "th row and column) differ by more than " + TOLERANCE + " step; first " + first);
    }

    static int rgb(Vector3d c) {
        return (channel(c.x) << 16) | (channel(c.y) << 8) | channel(c.z);
    }

    static int channel(double v) {
        return (int) Math.floor(255 * Math.min(1, Math.max(0, v)) + 0.5);
    }

    static int maxChannelDifference(int a, int b) {
        int d = 0;
        for (int s = 0; s <= 16; s += 8) {
            d = Math.max(d, Math.abs(((a >> s) & 255) - ((b >> s) & 255)));
        }
        return d;
    }
}
