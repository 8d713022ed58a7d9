package ray.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;

/**
 * The grade tests' material, made once per test JVM: a lean test set over the installed distribution's
 * course kit (four checks and two scenes of the course's rubric, short limits), three hand-ins (the
 * reference solution; the solution with a planted bug, as a zip; the handout's stubs)
 * and {@code raytracer grade}'s own reports of them, which the Spark runs must reproduce.
 */
final class GradeFixture {

    static final Path COURSE_SOURCES = Path.of(System.getProperty("raytracer.courseSources", "../src/course"));
    /** The checks and scenes of the course rubric the lean test set keeps. */
    static final Set<String> KEPT = Set.of("CheckSphere.hitInFront", "CheckTriangle.backIsInvisible", "CheckPointLight.inverseSquare",
            "CheckShading.diffuseLambert", "one-sided-shadows.txt", "material-diffuse.txt");

    static Path dir, tests, expected;
    static List<Path> handIns;
    static String raytracerOut;

    private GradeFixture() {
    }

    /** Makes the test set and hand-ins and grades them with {@code raytracer grade -j 2} (once per JVM). */
    static synchronized void prepare() throws IOException {
        if (dir != null) {
            return;
        }
        Path d = Files.createTempDirectory("raytracer-spark-grade-test-");
        Runtime.getRuntime().addShutdownHook(new Thread(() -> SceneBundle.deleteTree(d)));
        Path course = SparkClusterTest.HOME.resolve("course").toAbsolutePath();
        Path t = Files.createDirectories(d.resolve("tests"));
        StringBuilder rubric = new StringBuilder();
        for (String line : Files.readAllLines(course.resolve("grading/rubric.txt"))) {
            String[] w = line.trim().split("\\s+");
            switch (w[0]) {
                case "framework", "scenes", "references", "checks" ->
                        rubric.append(w[0]).append(' ').append(course.resolve("grading").resolve(w[1]).normalize()).append('\n');
                case "limit" -> {
                }
                case "check", "scene" -> {
                    if (KEPT.contains(w[2])) {
                        rubric.append(line).append('\n');
                    }
                }
                default -> rubric.append(line).append('\n');
            }
        }
        rubric.append("limit check-seconds 5\nlimit scene-seconds 20\nlimit total-seconds 150\n");
        Files.writeString(t.resolve("rubric.txt"), rubric);

        Path solution = COURSE_SOURCES.resolve("solution/java");
        Path subs = Files.createDirectories(d.resolve("hand-ins"));
        Path solved = copy(solution, subs.resolve("solved"));
        String light = Files.readString(solution.resolve("PointLight.java"));
        String bug = "arriving.scale(1 / toLight.lengthSquared());";
        if (!light.contains(bug)) {
            throw new IllegalStateException("the solution's PointLight.java no longer holds the line the planted bug replaces: " + bug);
        }
        Path zip = subs.resolve("inverse-r.zip");
        try (ZipOutputStream z = new ZipOutputStream(Files.newOutputStream(zip)); Stream<Path> files = Files.list(solved)) {
            for (Path f : files.sorted().toList()) {
                String name = f.getFileName().toString();
                z.putNextEntry(new ZipEntry("src/" + name));
                z.write((name.equals("PointLight.java") ? light.replace(bug, "arriving.scale(1 / toLight.length());")
                        : Files.readString(f)).getBytes(StandardCharsets.UTF_8));
                z.closeEntry();
            }
        }
        Path stub = copy(course.resolve("handout/src/main/java"), subs.resolve("stub"));
        List<Path> h = List.of(solved, zip, stub);

        Path out = d.resolve("raytracer");
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        List<String> args = new ArrayList<>(List.of("grade", "-j", "2", "--tests", t.toString(), "-o", out.toString()));
        h.forEach(p -> args.add(p.toString()));
        int status = ray.app.Main.run(new PrintStream(o, true, StandardCharsets.UTF_8), System.err, args.toArray(new String[0]));
        raytracerOut = o.toString(StandardCharsets.UTF_8);
        assertEquals(0, status, "raytracer grade: " + raytracerOut);
        tests = t;
        handIns = h;
        expected = out;
        dir = d;
    }

    static Path copy(Path from, Path to) throws IOException {
        Files.createDirectories(to);
        try (Stream<Path> s = Files.list(from)) {
            for (Path p : s.filter(p -> p.toString().endsWith(".java")).toList()) {
                Files.copy(p, to.resolve(p.getFileName().toString()));
            }
        }
        return to;
    }

    /**
     * {@code actual} holds the files {@code raytracer grade} wrote into {@link #expected}: grades.csv and
     * every picture byte for byte, results.json and the pages but for their times (and the class page's
     * "N at a time" and the order of its slowest submissions).
     */
    static void assertSameReports(Path actual) throws IOException {
        List<String> want = files(expected), got = files(actual);
        assertEquals(want, got, "the same report files");
        for (String f : want) {
            byte[] a = Files.readAllBytes(expected.resolve(f)), b = Files.readAllBytes(actual.resolve(f));
            if (f.equals("index.html")) {
                // the class page: its "slowest submissions" table is in the order of times measured
                assertEquals(withoutTimes(new String(a, StandardCharsets.UTF_8)).lines().sorted().toList(),
                        withoutTimes(new String(b, StandardCharsets.UTF_8)).lines().sorted().toList(), f);
            } else if (f.endsWith(".json") || f.endsWith(".html")) {
                assertEquals(withoutTimes(new String(a, StandardCharsets.UTF_8)), withoutTimes(new String(b, StandardCharsets.UTF_8)), f);
            } else {
                assertArrayEquals(a, b, f + " byte for byte");
            }
        }
    }

    static String withoutTimes(String s) {
        return s.replaceAll("\"execution_time\": ?\\d+", "\"execution_time\":T").replaceAll("\"value\": ?[0-9.eE+-]+", "\"value\":T")
                .replaceAll("\\d+(\\.\\d+)? s\\b", "T s").replaceAll("with \\d+ at a time", "with N at a time");
    }

    static List<String> files(Path root) throws IOException {
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(Files::isRegularFile).map(p -> root.relativize(p).toString()).sorted().toList();
        }
    }

    static final PrintStream NOWHERE = new PrintStream(OutputStream.nullOutputStream());
}
