package ray.course;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The generator of the handout (ray.course.Handout) and what it wrote into build/handout/ (by gradle
 * courseKit, which the test task depends on): markers, the 11 methods, no solution line in the handout.
 */
class HandoutTest {

    @Test
    void aRegionBecomesItsStubLinesAtTheirIndentation() {
        String src = "class A {\n    int f() {\n        // BEGIN SOLUTION\n        // STUB: return 0;\n        int secret = 42;\n"
                + "        return secret;\n        // END SOLUTION\n    }\n}\n";
        assertEquals("class A {\n    int f() {\n        return 0;\n    }\n}\n", Handout.stub(src, "A.java"));
    }

    @Test
    void malformedMarkersAreRefusedWithFileAndLine() {
        assertEquals("A.java:2: BEGIN SOLUTION without an END SOLUTION",
                assertThrows(Handout.MarkerException.class, () -> Handout.stub("x\n// BEGIN SOLUTION\ny\n", "A.java")).getMessage());
        assertEquals("A.java:1: END SOLUTION without a BEGIN SOLUTION",
                assertThrows(Handout.MarkerException.class, () -> Handout.stub("// END SOLUTION\n", "A.java")).getMessage());
        assertTrue(assertThrows(Handout.MarkerException.class,
                () -> Handout.stub("// BEGIN SOLUTION\n// BEGIN SOLUTION\n// END SOLUTION\n", "A.java")).getMessage().startsWith("A.java:2: "));
        assertTrue(assertThrows(Handout.MarkerException.class, () -> Handout.stub("x\n  // STUB: return 1;\n", "A.java"))
                .getMessage().startsWith("A.java:2: "), "a STUB line outside a region would reach the handout as a comment");
        assertTrue(assertThrows(Handout.MarkerException.class, () -> Handout.stub("//BEGIN SOLUTION\n", "A.java"))
                .getMessage().startsWith("A.java:1: "), "a misspelt marker must not let the region through");
    }

    @Test
    void theElevenMethodsInTheAssignmentsOrder() throws IOException {
        List<String> names = Handout.methods(Course.SOLUTION_SOURCES).stream().map(Handout.Method::qualified).collect(Collectors.toList());
        assertEquals(List.of("Sphere.intersects", "Triangle.intersects", "Camera.recalculate", "Camera.getRayThrough",
                "PointLight.getIntensity", "Diffuse.shade", "BlinnPhong.shade", "GlazedMaterial.shade", "Scene.trace",
                "Scene.renderPixel", "Scene.renderAll"), names);
        String readme = Course.read(Course.HANDOUT.resolve("README.md"));
        int at = -1;
        for (String n : names) {
            int i = readme.indexOf("`" + n + "(");
            assertTrue(i > at, "the student README lists " + n + " in the assignment's order");
            at = i;
        }
        assertFalse(readme.contains("@METHODS@"));
    }

    /** Each of the 11 stubs is exactly `return null;`, `return false;` or empty, as the assignment has them. */
    @Test
    void stubsAreNullFalseOrEmpty() throws IOException {
        for (Handout.Method m : Handout.methods(Course.SOLUTION_SOURCES)) {
            String expected = m.returnType().equals("boolean") ? "[return false;]" : m.returnType().equals("void") ? "[]" : "[return null;]";
            assertEquals(expected, m.stub().toString(), m.qualified());
        }
    }

    /** No line of a solution region reaches the handout: not its framework, not its tests, not its README. */
    @Test
    void noSolutionLineReachesTheHandout() throws IOException {
        Set<String> handoutLines = new HashSet<>();
        List<Path> files;
        try (Stream<Path> s = Files.walk(Course.HANDOUT)) {
            files = s.filter(Files::isRegularFile).filter(p -> p.toString().matches(".*\\.(java|gradle|md|txt|properties)$"))
                    .collect(Collectors.toList());
        }
        assertTrue(files.size() > 30, "build/handout has the framework, the tests and the scenes: " + files.size());
        for (Path p : files) {
            Course.read(p).lines().map(String::strip).forEach(handoutLines::add);
        }
        List<String> leaked = new ArrayList<>();
        int checked = 0;
        for (Path p : Handout.javaFiles(Course.SOLUTION_SOURCES)) {
            for (Handout.Region r : Handout.regions(Course.read(p), p.getFileName().toString())) {
                for (String line : r.solution()) {
                    String t = line.strip();
                    if (t.isEmpty() || t.matches("[{}();]*|\\} else \\{|return (true|false|null);|continue;|break;")) {
                        continue;
                    }
                    checked++;
                    if (handoutLines.contains(t)) {
                        leaked.add(p.getFileName() + ": " + t);
                    }
                }
            }
        }
        assertTrue(checked > 100, "the solution regions hold the solution: " + checked + " lines");
        assertEquals(List.of(), leaked, "solution lines found in build/handout");
        for (Path p : files) {
            String text = Course.read(p);
            assertFalse(text.contains("BEGIN SOLUTION") || text.contains("END SOLUTION") || text.contains("// STUB:"), p.toString());
        }
    }

    /** The handout's framework is the solution's, line for line, outside the regions. */
    @Test
    void outsideTheRegionsTheHandoutIsTheSolution() throws IOException {
        for (Path p : Handout.javaFiles(Course.SOLUTION_SOURCES)) {
            String name = p.getFileName().toString();
            assertEquals(Handout.stub(Course.read(p), name), Course.read(Course.HANDOUT.resolve("src/main/java").resolve(name)), name);
        }
    }

    @Test
    void onlyScenesOfThe2003ClassesAreHandedOut() throws IOException {
        assertTrue(Handout.is2003Scene("Width 2\nHeight 2\n\nCamera Camera\n\nMaterial Glazed g\n\nSurface Triangle\nref material g\n"));
        assertFalse(Handout.is2003Scene("Width 2\nHeight 2\nSampler jittered\n"));
        assertFalse(Handout.is2003Scene("Width 2\nHeight 2\n\nSurface Torus\n"));
        assertFalse(Handout.is2003Scene("Width 2\nHeight 2\n\nLight AreaLight\n"));
        List<String> scenes = Handout.scenes2003(Path.of("scenes"), Path.of("reference-images"));
        assertTrue(scenes.containsAll(List.of("material-diffuse", "material-blinnphong", "material-glazed", "showcase",
                "facing-mirrors-10", "one-sided-shadows")), scenes.toString());
        assertFalse(scenes.contains("csg") || scenes.contains("mesh") || scenes.contains("light-area"), scenes.toString());
        try (Stream<Path> s = Files.list(Course.HANDOUT.resolve("scenes"))) {
            assertEquals(scenes.size(), s.count());
        }
        for (String n : scenes) {
            assertTrue(Files.isRegularFile(Course.HANDOUT.resolve("reference-images/" + n + ".png")), n);
        }
    }

    @Test
    void theCourseKitHasTheHandoutTheSolutionAndTheMethodTable() throws IOException {
        assertTrue(Files.isRegularFile(Course.KIT.resolve("handout/src/main/java/RayTracer.java")));
        assertTrue(Files.isRegularFile(Course.KIT.resolve("solution/Sphere.java")));
        List<String> rows = Files.readAllLines(Course.KIT.resolve("methods.tsv"));
        assertEquals(12, rows.size(), rows.toString());
        assertEquals("1\tSphere.intersects\tboolean\tRay ray, IntersectionRecord record, Scene scene\treturn false;\tSphereIntersectsTest",
                rows.get(1));
        assertTrue(Files.isRegularFile(Path.of("src/course/tests/java", rows.get(11).split("\t")[5] + ".java")), rows.get(11));
    }
}
