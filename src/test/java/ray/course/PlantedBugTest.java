package ray.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.platform.engine.TestExecutionResult.Status;

/**
 * The student tests find the classic mistakes of the assignment, and only in the method that makes them: the
 * reference solution with one planted bug fails tests of that method's class (every message starting with the
 * method's name), and no other method's tests. The golden-image test may fail too (it renders everything).
 */
@Tag("slow")
class PlantedBugTest {

    @TempDir
    Path dir;

    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiterString = " § ", quoteCharacter = '"', value = {
        "triangles seen from behind § Triangle § if (!(ray.direction.dot(n) < 0)) { § if (ray.direction.dot(n) == 0) { § TriangleIntersectsTest",
        "shadows never tested § PointLight § if (surface.intersects(shadowRay, blocker, scene)) { § if (surface == null) { § PointLightGetIntensityTest",
        "I / r instead of I / r^2 § PointLight § arriving.scale(1 / toLight.lengthSquared()); § arriving.scale(1 / toLight.length()); § PointLightGetIntensityTest",
        "one sample per pixel § Scene § int n = samplesPerPixel; § int n = 1; § SceneRenderPixelTest",
        "the last hit kept, not the closest § Scene § if (surface.intersects(ray, record, this) && (closest == null || record.t < closest.t)) {"
                + " § if (surface.intersects(ray, record, this)) { § SceneTraceTest",
        "the image upside down § Scene § image[x][y] = renderPixel(x, y); § image[x][height - 1 - y] = renderPixel(x, y); § SceneRenderAllTest",
        "Phong's reflection vector § BlinnPhong § double highlight = Math.pow(Math.max(0, record.normal.dot(h)), exponent);"
                + " § Vector3d r = new Vector3d(); r.scale(2 * nl, record.normal); r.sub(l);"
                + " double highlight = Math.pow(Math.max(0, r.dot(toViewer)), exponent); § BlinnPhongShadeTest",
        "a Glazed without a base crashing § GlazedMaterial § if (base != null) { § if (base != null || base == null) { § GlazedMaterialShadeTest",
        "the y axis of the image plane not flipped § Camera § double b = (1 - 2 * y / height) * halfHeight; § double b = (2 * y / height - 1) * halfHeight;"
                + " § CameraGetRayThroughTest",
        "the sphere's normal not unit length § Sphere § record.normal.scale(1 / radius); § record.normal.scale(1); § SphereIntersectsTest",
    })
    void aPlantedBugFailsOnlyItsMethodsTests(String bug, String cls, String line, String planted, String testClass) throws Exception {
        List<Course.Outcome> outcomes = plant(bug, cls, line, planted, "camera-axes");
        String method = StudentTestsTest.methodOf().get(testClass);
        List<String> wrong = new ArrayList<>();
        int failedHere = 0;
        for (Course.Outcome o : outcomes) {
            if (o.status() != Status.FAILED || o.testClass().equals("GoldenImageTest")) {
                continue;
            }
            if (o.testClass().equals(testClass) && o.message() != null && o.message().startsWith(method)) {
                failedHere++;
            } else {
                wrong.add(o.testClass() + " " + o.test() + ": " + o.message());
            }
        }
        assertTrue(failedHere > 0, bug + ": no test of " + testClass + " failed; outcomes: "
                + outcomes.stream().filter(o -> o.status() != Status.SUCCESSFUL).map(Course.Outcome::toString).collect(Collectors.toList()));
        assertEquals(List.of(), wrong, bug + ": only " + method + "'s tests may fail");
    }

    /** The golden-image test says what kind of difference a planted bug makes. */
    @ParameterizedTest(name = "{0}")
    @CsvSource(delimiterString = " § ", quoteCharacter = '"', value = {
        "shadows never tested § PointLight § if (surface.intersects(shadowRay, blocker, scene)) { § if (surface == null) { § one-sided-shadows"
                + " § yours is brighter in part of the image, likely where the reference has shadows",
        "Phong's reflection vector § BlinnPhong § double highlight = Math.pow(Math.max(0, record.normal.dot(h)), exponent);"
                + " § Vector3d r = new Vector3d(); r.scale(2 * nl, record.normal); r.sub(l);"
                + " double highlight = Math.pow(Math.max(0, r.dot(toViewer)), exponent); § material-blinnphong § only highlights differ",
        "the image plane's y not flipped § Camera § double b = (1 - 2 * y / height) * halfHeight; § double b = (2 * y / height - 1) * halfHeight;"
                + " § material-diffuse § the whole image is off",
    })
    void theGoldenTestSaysWhatKindOfDifference(String bug, String cls, String line, String planted, String scene, String kind) throws Exception {
        List<Course.Outcome> golden = plant(bug, cls, line, planted, scene).stream()
                .filter(o -> o.testClass().equals("GoldenImageTest")).collect(Collectors.toList());
        assertEquals(1, golden.size());
        String m = golden.get(0).message();
        assertTrue(m != null && m.startsWith(scene + ": ") && m.contains(" pixels differ by more than 2 ") && m.contains(": " + kind)
                && m.endsWith("(reference | yours | difference)"), bug + ": " + m);
        assertTrue(Files.isRegularFile(dir.resolve("golden").resolve(scene + ".png")), "the side-by-side image is written");
    }

    /** The student tests run on the solution with {@code line} of {@code cls} replaced by {@code planted}, on one scene. */
    private List<Course.Outcome> plant(String bug, String cls, String line, String planted, String scene) throws Exception {
        String source = Course.read(Course.SOLUTION_SOURCES.resolve(cls + ".java"));
        assertTrue(source.contains(line), bug + ": the solution has the line " + line);
        Path src = Files.createDirectories(dir.resolve("src")).resolve(cls + ".java");
        Files.writeString(src, source.replace(line, planted));
        Path classes = Files.createDirectories(dir.resolve("classes"));
        assertEquals("", Course.compileWith(Course.SOLUTION_CLASSES.toAbsolutePath().toString(), classes, src), bug);
        Path scenes = Files.createDirectories(dir.resolve("scenes")), refs = Files.createDirectories(dir.resolve("refs"));
        Files.copy(Path.of("scenes", scene + ".txt"), scenes.resolve(scene + ".txt"));
        Files.copy(Path.of("reference-images", scene + ".png"), refs.resolve(scene + ".png"));
        return Course.runTests(Course.loader(classes, Course.SOLUTION_CLASSES, Course.TEST_CLASSES),
                Course.TEST_CLASSES, Map.of("course.scenes", scenes.toString(), "course.references", refs.toString(),
                        "course.out", dir.resolve("golden").toString()));
    }
}
