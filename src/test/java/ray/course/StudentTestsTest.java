package ray.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Collectors;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.engine.TestExecutionResult.Status;

/**
 * The student tests (src/course/tests) run on the reference solution (all pass) and on the stubbed handout
 * as generated (every method's tests fail, each message naming its method).
 */
@Tag("slow")
class StudentTestsTest {

    @TempDir
    Path dir;

    /** A few quick scenes for the golden-image tests (every scene is rendered by SolutionAgreesWithEngineTest). */
    static final List<String> QUICK = List.of("camera-axes", "inside-sphere", "sphere-through-triangle");

    private Map<String, String> quickScenes(Path scenes, Path references) throws IOException {
        Files.createDirectories(scenes);
        Files.createDirectories(references);
        for (String n : QUICK) {
            Files.copy(Path.of("scenes", n + ".txt"), scenes.resolve(n + ".txt"));
            Files.copy(Path.of("reference-images", n + ".png"), references.resolve(n + ".png"));
        }
        return Map.of("course.scenes", scenes.toString(), "course.references", references.toString(),
                "course.out", dir.resolve("golden").toString());
    }

    @Test
    void theReferenceSolutionPassesEveryStudentTest() throws IOException {
        Map<String, String> props = quickScenes(dir.resolve("scenes"), dir.resolve("refs"));
        List<Course.Outcome> outcomes = Course.runTests(Course.loader(Course.SOLUTION_CLASSES, Course.TEST_CLASSES), Course.TEST_CLASSES, props);
        List<String> failed = outcomes.stream().filter(o -> o.status() != Status.SUCCESSFUL)
                .map(o -> o.testClass() + " " + o.test() + ": " + o.message()).collect(Collectors.toList());
        assertEquals(List.of(), failed);
        Map<String, Long> perClass = outcomes.stream().collect(Collectors.groupingBy(Course.Outcome::testClass, TreeMap::new, Collectors.counting()));
        assertEquals(12, perClass.size(), "11 method test classes and the golden-image test: " + perClass);
        assertEquals(QUICK.size(), perClass.get("GoldenImageTest"));
        assertTrue(outcomes.size() >= 60, "tests run: " + outcomes.size());
    }

    /** A golden-image failure names the scene, says what kind of difference it is and writes reference | yours | difference. */
    @Test
    void aGoldenFailureWritesTheSideBySideImageAndSaysWhatKind() throws IOException {
        Map<String, String> props = quickScenes(dir.resolve("scenes"), dir.resolve("refs"));
        // the reference made brighter in a block away from edges: the solution is "darker in part of the image"
        Path ref = dir.resolve("refs/inside-sphere.png");
        BufferedImage img = ImageIO.read(ref.toFile());
        for (int y = 60; y < 90; y++) {
            for (int x = 80; x < 120; x++) {
                int c = img.getRGB(x, y);
                int r = Math.min(255, ((c >> 16) & 255) + 40), g = Math.min(255, ((c >> 8) & 255) + 40), b = Math.min(255, (c & 255) + 40);
                img.setRGB(x, y, (r << 16) | (g << 8) | b);
            }
        }
        ImageIO.write(img, "png", ref.toFile());
        List<Course.Outcome> outcomes = Course.runTests(Course.loader(Course.SOLUTION_CLASSES, Course.TEST_CLASSES), Course.TEST_CLASSES, props);
        List<Course.Outcome> failed = outcomes.stream().filter(o -> o.status() == Status.FAILED).collect(Collectors.toList());
        assertEquals(1, failed.size(), failed.toString());
        String m = failed.get(0).message();
        Path out = dir.resolve("golden/inside-sphere.png");
        assertTrue(m.startsWith("inside-sphere: 1200 of 30000 pixels differ by more than 2 (largest difference 40 of 255): yours is darker"), m);
        assertTrue(m.endsWith("; open " + out + " (reference | yours | difference)"), m);
        BufferedImage side = ImageIO.read(out.toFile());
        assertEquals(3 * 200 + 8, side.getWidth());
        assertEquals(150, side.getHeight());
        assertEquals(0x202020, side.getRGB(2 * 204 + 10, 10) & 0xFFFFFF, "within the tolerance: dark grey");
        assertEquals(64 + 160, side.getRGB(2 * 204 + 100, 70) & 0xFF, "yours darker by 40: blue, 64 + 4 x 40");
    }

    /** Test class to method, from the kit's methods.tsv (SphereIntersectsTest to Sphere.intersects ...). */
    static Map<String, String> methodOf() throws IOException {
        Map<String, String> methodOf = new TreeMap<>();
        for (String row : Files.readAllLines(Course.KIT.resolve("methods.tsv"))) {
            if (!row.startsWith("#")) {
                String[] f = row.split("\t");
                methodOf.put(f[5], f[1]);
            }
        }
        return methodOf;
    }

    /**
     * The handout as generated: it compiles; with its stubs every test of each method's class fails with a
     * message naming that method, and the golden-image tests name the first method that returns nothing.
     */
    @Test
    void theStubbedHandoutCompilesAndEveryMethodsTestsFailNamingIt() throws IOException {
        Path classes = Files.createDirectories(dir.resolve("classes"));
        String errors = Course.compile(classes, Course.HANDOUT.resolve("src/main/java"), Course.HANDOUT.resolve("src/test/java"));
        assertEquals("", errors, "the stubbed handout compiles");
        Map<String, String> props = quickScenes(dir.resolve("scenes"), dir.resolve("refs"));
        List<Course.Outcome> outcomes = Course.runTests(Course.loader(classes), classes, props);
        Map<String, String> methodOf = methodOf();
        assertEquals(11, methodOf.size());
        List<String> wrong = new ArrayList<>();
        for (Course.Outcome o : outcomes) {
            String method = methodOf.get(o.testClass());
            if (method != null) {
                if (o.status() != Status.FAILED || o.message() == null || !o.message().startsWith(method)) {
                    wrong.add(o.testClass() + " " + o.test() + ": " + o.status() + " " + o.message());
                }
            } else if (!(o.testClass().equals("GoldenImageTest") && o.status() == Status.FAILED
                    && o.message().endsWith(": Camera.getRayThrough returned null for pixel (0, 0) (expected a new Ray)"))) {
                wrong.add(o.testClass() + " " + o.test() + ": " + o.status() + " " + o.message());
            }
        }
        assertEquals(List.of(), wrong);
        assertEquals(methodOf.keySet(), outcomes.stream().map(Course.Outcome::testClass).filter(methodOf::containsKey)
                .collect(Collectors.toCollection(java.util.TreeSet::new)), "every method's tests ran");
    }
}
