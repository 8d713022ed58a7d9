package ray.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;
import org.junit.jupiter.api.io.TempDir;

/**
 * The grader on real submissions, each in its own sandboxed child JVM, all graded at once (two at a time)
 * before the tests look at the results: the reference solution (src/course/solution/java) on the course
 * test set (src/course/grading) scores full marks; the stubbed handout scores zero with a message per
 * method; one planted bug at a time loses points with every failed test naming the method at fault;
 * submissions that hang, call System.exit, try to read the references, write outside their folder, reach
 * the network or start a program are contained and reported.
 */
@Tag("slow")
@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class GraderTest {

    static final Path SOLUTION = Path.of("src/course/solution/java");
    static final Path GRADING = Path.of("src/course/grading");

    /** Planted bugs: name, file, text of the solution, replacement, the method at fault. */
    static final String[][] BUGS = {
        {"triangle-back", "Triangle.java", "if (!(ray.direction.dot(n) < 0)) {", "if (ray.direction.dot(n) == 0) {", "Triangle.intersects"},
        {"no-shadows", "PointLight.java", "if (surface.intersects(shadowRay, blocker, scene)) {",
            "if (surface == null && surface.intersects(shadowRay, blocker, scene)) {", "PointLight.getIntensity"},
        {"one-sample", "Scene.java", "int n = samplesPerPixel;", "int n = 1;", "Scene.renderPixel"},
        {"phong-reflection", "BlinnPhong.java", "h.add(l, toViewer);\n            h.normalize();\n            double highlight = Math.pow(Math.max(0, record.normal.dot(h)), exponent);",
            "h.scaleAdd(2 * nl, record.normal, new Vector3d(-l.x, -l.y, -l.z));\n            double highlight = Math.pow(Math.max(0, h.dot(toViewer)), exponent);",
            "BlinnPhong.shade"},
        {"glazed-no-base", "GlazedMaterial.java", "if (base != null) {\n            color.set(base.shade(ray, record, scene));\n        }",
            "color.set(base.shade(ray, record, scene));", "GlazedMaterial.shade"},
        {"upside-down", "Camera.java", "double b = (1 - 2 * y / height) * halfHeight;", "double b = (2 * y / height - 1) * halfHeight;",
            "Camera.getRayThrough"},
        {"inverse-r", "PointLight.java", "arriving.scale(1 / toLight.lengthSquared());", "arriving.scale(1 / toLight.length());",
            "PointLight.getIntensity"},
        {"last-hit", "Scene.java", "if (surface.intersects(ray, record, this) && (closest == null || record.t < closest.t)) {",
            "if (surface.intersects(ray, record, this)) {", "Scene.trace"},
    };

    @TempDir
    static Path tmp;

    Path leanTests;
    Path outside;
    ServerSocket server;
    volatile boolean connected;
    Grader full, lean;
    Sandbox box;
    ExecutorService pool;

    Future<SubmissionResult> pool(String name, Grader g, Path submission) {
        return pool.submit(() -> g.grade(Submission.read(submission), tmp.resolve("reports/" + name)));
    }

    /** {@code img} with independent zero-mean noise of -3..3 steps per channel (clamped as a PNG is). */
    static java.awt.image.BufferedImage noise(java.awt.image.BufferedImage img, java.util.Random r) {
        java.awt.image.BufferedImage out = new java.awt.image.BufferedImage(img.getWidth(), img.getHeight(),
                java.awt.image.BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int c = img.getRGB(x, y), v = 0;
                for (int shift = 16; shift >= 0; shift -= 8) {
                    v = v << 8 | Math.max(0, Math.min(255, (c >> shift & 255) + r.nextInt(7) - 3));
                }
                out.setRGB(x, y, v);
            }
        }
        return out;
    }
    final Map<String, SubmissionResult> results = new LinkedHashMap<>();

    @BeforeAll
    void gradeEverything() throws Exception {
        Assumptions.assumeTrue(Files.isDirectory(SOLUTION), "the reference solution (src/course/solution/java) is not in this tree");
        Path kit = tmp.resolve("kit");
        Path framework = Files.createDirectories(kit.resolve("handout/src/main/java"));
        for (Path f : javaFiles(SOLUTION)) {
            Files.writeString(framework.resolve(f.getFileName().toString()), stub(Files.readString(f)));
        }
        copyTree(Path.of("scenes"), kit.resolve("handout/scenes"));
        copyTree(Path.of("reference-images"), kit.resolve("handout/reference-images"));
        copyTree(GRADING, kit.resolve("grading"));
        // the lean test set: every check, two cheap scenes, short limits (the course's own runs longer)
        leanTests = kit.resolve("lean");
        Files.createDirectories(leanTests);
        StringBuilder rubric = new StringBuilder();
        for (String line : Files.readAllLines(kit.resolve("grading/rubric.txt"))) {
            String l = line.trim();
            if (l.startsWith("limit")) {
                continue;
            }
            if (l.startsWith("scene ") && !l.contains("one-sided-shadows.txt") && !l.contains("material-blinnphong.txt")) {
                continue;
            }
            rubric.append(line.replaceFirst("^(framework|scenes|references|checks)(\\s+)(\\S+)", "$1$2../grading/$3")).append('\n');
        }
        rubric.append("limit check-seconds 3\nlimit scene-seconds 5\nlimit total-seconds 120\n");
        Files.writeString(leanTests.resolve("rubric.txt"), rubric);

        // bubblewrap where it works (CI installs it); else the fallback, and the containment test is skipped
        box = Sandbox.choose("auto");
        Path work = Files.createDirectories(tmp.resolve("work"));
        full = new Grader(TestSet.load(kit.resolve("grading")), box, Judge.standard(), work);
        lean = new Grader(TestSet.load(leanTests), box, Judge.standard(), work);

        Map<String, Path> subs = new LinkedHashMap<>();
        Map<String, Future<SubmissionResult>> futures = new LinkedHashMap<>();
        pool = Executors.newFixedThreadPool(2);
        Path subsDir = Files.createDirectories(tmp.resolve("submissions"));
        subs.put("stub", copyTree(framework, subsDir.resolve("stub")));
        for (String[] bug : BUGS) {
            Path d = solved(subsDir.resolve(bug[0]));
            String src = Files.readString(SOLUTION.resolve(bug[1]));
            assertTrue(src.contains(bug[2]), "the solution's " + bug[1] + " no longer holds the line the bug " + bug[0] + " replaces");
            Files.writeString(d.resolve(bug[1]), unmark(src.replace(bug[2], bug[3])));
            subs.put(bug[0], d);
        }
        // hostile hand-ins: only the changed file, as a student may hand in
        String sphere = unmark(Files.readString(SOLUTION.resolve("Sphere.java")));
        String camera = unmark(Files.readString(SOLUTION.resolve("Camera.java")));
        String diffuse = unmark(Files.readString(SOLUTION.resolve("Diffuse.java")));
        subs.put("hang", write(solved(subsDir.resolve("hang")), "Camera.java",
                camera.replace("public void recalculate() {", "public void recalculate() {\n        while (eye != null) { Thread.onSpinWait(); }")));
        subs.put("exit", write(solved(subsDir.resolve("exit")), "Diffuse.java",
                diffuse.replace("Vector3d color = new Vector3d();", "if (scene != null) { System.exit(3); }\n        Vector3d color = new Vector3d();")));
        server = new ServerSocket(0, 5, java.net.InetAddress.getLoopbackAddress());
        Thread accept = new Thread(() -> {
            try {
                server.accept().close();
                connected = true;
            } catch (IOException e) {
                // closed at the end
            }
        });
        accept.setDaemon(true);
        accept.start();
        outside = tmp.resolve("outside.txt");
        Path reference = kit.resolve("handout/reference-images/one-sided-shadows.png").toAbsolutePath();
        String probe = "    static {\n        Probe.run(" + q(reference.toString()) + ", " + q(outside.toAbsolutePath().toString()) + ", "
                + server.getLocalPort() + ");\n    }\n";
        Path hostile = write(solved(subsDir.resolve("hostile")), "Sphere.java", sphere.replaceFirst("public class Sphere extends Surface \\{",
                "public class Sphere extends Surface {\n" + Matcher.quoteReplacement(probe)));
        Files.writeString(hostile.resolve("Probe.java"), PROBE);
        subs.put("hostile", hostile);

        // one hand-in misbehaving four ways, each in its own method: endless recursion, a file that does not
        // compile, running out of heap, printing megabytes
        Path bad = solved(subsDir.resolve("misbehaving"));
        edit(bad.resolve("Sphere.java"), "Vector3d oc = new Vector3d();",
                "if (ray != null) {\n            return intersects(ray, record, scene);\n        }\n        Vector3d oc = new Vector3d();");
        edit(bad.resolve("Triangle.java"), "public boolean intersects(", "int broken = ;\n\n    public boolean intersects(");
        edit(bad.resolve("Diffuse.java"), "Vector3d color = new Vector3d();",
                "if (scene != null) {\n            java.util.List<long[]> hog = new java.util.ArrayList<>();\n"
                + "            while (hog != null) {\n                hog.add(new long[1 << 24]);\n            }\n        }\n"
                + "        Vector3d color = new Vector3d();");
        edit(bad.resolve("BlinnPhong.java"), "Vector3d color = new Vector3d();",
                "for (int i = 0; i < 100000; i++) {\n            System.out.println(\"spam \" + i + \" spam spam spam spam spam spam spam spam\");\n"
                + "        }\n        Vector3d color = new Vector3d();");
        subs.put("misbehaving", bad);

        // a stochastic scene: four independent reference renders with zero-mean noise of +-3 steps, and two
        // noisy hand-ins, one unbiased, one 2 steps too bright (each noise alone hides the bias pixel by pixel)
        Path noisy = Files.createDirectories(kit.resolve("noisy"));
        Path noisyRefs = Files.createDirectories(noisy.resolve("refs"));
        java.awt.image.BufferedImage clean = javax.imageio.ImageIO.read(kit.resolve("handout/reference-images/material-diffuse.png").toFile());
        java.util.Random random = new java.util.Random(465);
        for (int k = 1; k <= 4; k++) {
            javax.imageio.ImageIO.write(noise(clean, random), "png", noisyRefs.resolve(TestSet.renderName("material-diffuse.txt", k)).toFile());
        }
        Files.writeString(noisy.resolve("rubric.txt"), "framework ../handout/src/main/java\nscenes ../handout/scenes\nreferences refs\n"
                + "checks ../grading/checks\nrender GraderRender.render\ngroup Noise\n"
                + "scene 4 material-diffuse.txt stochastic renders=4 uses=Scene.renderPixel  A noisy render\n");
        Grader stochastic = new Grader(TestSet.load(noisy), box, Judge.standard(), work);
        for (String[] n : new String[][] {{"noisy-unbiased", "0"}, {"noisy-biased", "2"}}) {
            Path d = solved(subsDir.resolve(n[0]));
            edit(d.resolve("Scene.java"), "sum.scale(1.0 / (n * n));", "sum.scale(1.0 / (n * n));\n"
                    + "        java.util.Random r = NOISE;\n"
                    + "        sum.x += (r.nextInt(7) - 3 + " + n[1] + ") / 255.0;\n        sum.y += (r.nextInt(7) - 3 + " + n[1] + ") / 255.0;\n"
                    + "        sum.z += (r.nextInt(7) - 3 + " + n[1] + ") / 255.0;");
            // seeded, so the test's outcome does not depend on luck (each render continues the sequence: independent)
            edit(d.resolve("Scene.java"), "public class Scene {", "public class Scene {\n    static final java.util.Random NOISE = new java.util.Random(7);");
            futures.put(n[0], pool(n[0], stochastic, d));
        }

        // the fallback: no isolation, the same limits, and every report says so
        Grader unsandboxed = new Grader(TestSet.load(leanTests), Sandbox.choose("none"), Judge.standard(), work);
        futures.put("exit-unsandboxed", pool.submit(() -> {
            try {
                return unsandboxed.grade(Submission.read(subs.get("exit")), tmp.resolve("reports/exit-unsandboxed"));
            } finally {
                unsandboxed.close();
            }
        }));
        futures.put("solution", pool.submit(() -> full.grade(Submission.read(SOLUTION), tmp.resolve("reports/solution"))));
        for (Map.Entry<String, Path> e : subs.entrySet()) {
            futures.put(e.getKey(), pool.submit(() -> lean.grade(Submission.read(e.getValue()), tmp.resolve("reports/" + e.getKey()))));
        }
        pool.shutdown();
        for (Map.Entry<String, Future<SubmissionResult>> e : futures.entrySet()) {
            results.put(e.getKey(), e.getValue().get());
            System.out.printf(java.util.Locale.ROOT, "graded %-18s %6.2f / %3.0f in %5.1f s (render %4.1f s)%n", e.getKey(),
                    results.get(e.getKey()).score(), results.get(e.getKey()).maxScore(), results.get(e.getKey()).seconds(),
                    results.get(e.getKey()).renderSeconds());
        }
    }

    @AfterAll
    void close() throws IOException {
        if (server != null) {
            server.close();
        }
        for (Grader g : new Grader[] {full, lean}) {
            if (g != null) {
                g.close();
            }
        }
    }

    @Test
    void referenceSolutionScoresFullMarks() throws IOException {
        SubmissionResult r = results.get("solution");
        assertEquals(r.maxScore(), r.score(), () -> failures(r));
        assertEquals(100, r.maxScore());
        assertTrue(r.tests().stream().allMatch(TestResult::passed), () -> failures(r));
        assertTrue(r.tests().stream().filter(t -> t.kind() == TestSet.Kind.SCENE).count() >= 10);
        // every scene's three pictures are in the report folder
        for (TestResult t : r.tests()) {
            if (t.images() != null) {
                assertTrue(Files.isRegularFile(tmp.resolve("reports/solution").resolve(t.images().yours())), t.name());
            }
        }
    }

    @Test
    void stubbedHandoutScoresZeroWithAMessagePerMethod() {
        SubmissionResult r = results.get("stub");
        assertEquals(0, r.score(), () -> failures(r));
        List<String> named = new ArrayList<>();
        for (TestResult t : r.tests()) {
            assertFalse(t.message().isBlank(), t.name() + " failed without a message");
            String m = lean.methodNamed(t.message());
            if (m != null && !named.contains(m)) {
                named.add(m);
            }
        }
        assertEquals(lean.testSet().methods(), named, "each of the 11 methods gets its own message, in the assignment's order");
    }

    @Test
    void eachPlantedBugLosesPointsAndNamesItsMethod() {
        for (String[] bug : BUGS) {
            SubmissionResult r = results.get(bug[0]);
            assertTrue(r.score() < r.maxScore(), bug[0] + " lost no points");
            List<TestResult> failed = r.tests().stream().filter(t -> !t.passed()).toList();
            assertTrue(failed.stream().anyMatch(t -> t.kind() == TestSet.Kind.CHECK && t.message().startsWith(bug[4] + ":")),
                    () -> bug[0] + ": no failed check names " + bug[4] + ":\n" + failures(r));
            for (TestResult t : failed) {
                assertTrue(t.message().contains(bug[4]), () -> bug[0] + ": the failure of \"" + t.name() + "\" does not name " + bug[4]
                        + ": " + t.message());
            }
        }
    }

    @Test
    void aHangCostsOnlyTheTestsItReaches() {
        SubmissionResult r = results.get("hang");
        for (TestResult t : r.tests()) {
            boolean camera = t.name().startsWith("Camera.recalculate") || t.kind() == TestSet.Kind.SCENE;
            assertEquals(camera ? "timeout" : "passed", t.status(), () -> t.name() + ": " + t.message());
            if (camera) {
                assertTrue(t.message().contains("did not finish within") && t.message().contains("Camera.recalculate"), t.message());
            }
        }
    }

    @Test
    void systemExitIsReportedOnTheTestsItEnded() {
        SubmissionResult r = results.get("exit");
        List<TestResult> crashed = r.tests().stream().filter(t -> !t.passed()).toList();
        assertFalse(crashed.isEmpty());
        for (TestResult t : crashed) {
            assertEquals("crashed", t.status(), t.name());
            assertTrue(t.message().contains("System.exit(3)"), t.message());
        }
        assertTrue(crashed.stream().anyMatch(t -> t.name().startsWith("Diffuse.shade")));
        // the tests after a crash still ran, in a new child JVM
        assertTrue(r.tests().stream().filter(t -> t.name().startsWith("Scene.")).allMatch(TestResult::passed), () -> failures(r));
    }

    @Test
    void hostileCodeIsContained() throws IOException {
        Assumptions.assumeTrue(box.kind() == Sandbox.Kind.BWRAP, box.description());
        SubmissionResult r = results.get("hostile");
        String printed = String.join("\n", r.tests().stream().map(TestResult::output).toList()) + r.console();
        for (String what : List.of("read-reference", "list-references", "write-outside", "network", "process", "read-tmp-of-host")) {
            Matcher m = Pattern.compile("PROBE " + what + " (\\w+)").matcher(printed);
            assertTrue(m.find(), () -> "the probe " + what + " did not report:\n" + printed);
            assertEquals("BLOCKED", m.group(1), () -> what + " was not blocked:\n" + printed);
        }
        assertFalse(Files.exists(outside), "the submission wrote outside its folder");
        assertFalse(connected, "the submission reached a server on 127.0.0.1");
        // and it is otherwise the reference solution: it still passes the sphere's tests
        assertTrue(r.tests().stream().filter(t -> t.name().startsWith("Sphere.")).allMatch(TestResult::passed), () -> failures(r));
    }

    @Test
    void reportsAreWritten() throws IOException {
        SubmissionResult r = results.get("triangle-back");
        Path dir = tmp.resolve("reports/triangle-back");
        Reports.writeSubmission(r, dir);
        String json = Files.readString(dir.resolve("results.json"));
        for (String key : List.of("\"score\"", "\"execution_time\"", "\"output\"", "\"tests\"", "\"max_score\"", "\"visibility\"",
                "\"leaderboard\"")) {
            assertTrue(json.contains(key), key);
        }
        String html = Files.readString(dir.resolve("index.html"));
        assertTrue(html.contains("What to fix first") && html.contains("Triangle.intersects"), html);
        List<SubmissionResult> all = new ArrayList<>(results.values());
        all.remove(results.get("solution"));
        String csv = Reports.gradesCsv(all, lean.testSet());
        assertTrue(csv.startsWith("submission,score,max_score,Intersections,Camera,Lights and materials,Rendering,Scenes\n"), csv);
        assertTrue(csv.contains("\nstub,0,"), csv);
        String page = Reports.classHtml(all, lean.testSet(), "bubblewrap", 1, 2);
        assertTrue(page.contains("Most common failures") && page.contains("Slowest submissions") && page.contains("<svg"));
    }

    /**
     * The Gradescope autograder's run_autograder, run by bash against the installed launcher on a fake
     * /autograder tree (AUTOGRADER_ROOT): the submission in ROOT/submission, results.json in ROOT/results.
     */
    @Test
    void autograderScriptGradesAFakeAutograderTree() throws Exception {
        String home = System.getProperty("ray.test.installHome");
        Assumptions.assumeTrue(home != null && Files.isExecutable(Path.of(home, "bin/raytracer")), "no installed launcher");
        Path root = tmp.resolve("autograder");
        Path source = Files.createDirectories(root.resolve("source"));
        Files.copy(Path.of("src/course/autograder/run_autograder"), source.resolve("run_autograder"));
        Files.createSymbolicLink(source.resolve("raytracer"), Path.of(home).toAbsolutePath());
        copyTree(tmp.resolve("submissions/upside-down"), root.resolve("submission"));
        ProcessBuilder pb = new ProcessBuilder("bash", source.resolve("run_autograder").toString()).redirectErrorStream(true);
        pb.environment().put("AUTOGRADER_ROOT", root.toString());
        // the lean test set stands in for the kit's: RAYTRACER_OPTS reaches the launcher's JVM
        Path kit = Files.createDirectories(tmp.resolve("kit-for-autograder"));
        copyTree(leanTests, kit.resolve("grading"));
        Files.writeString(kit.resolve("grading/rubric.txt"), Files.readString(leanTests.resolve("rubric.txt")).replace("../grading/",
                leanTests.getParent().resolve("grading").toAbsolutePath() + "/"));
        pb.environment().put("RAYTRACER_OPTS", "-Draytracer.course=" + kit.toAbsolutePath());
        Process p = pb.start();
        String printed = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), printed);
        String json = Files.readString(root.resolve("results/results.json"));
        Matcher score = Pattern.compile("\"score\": ([0-9.]+),").matcher(json);
        assertTrue(score.find(), json);
        assertEquals(results.get("upside-down").score(), Double.parseDouble(score.group(1)), 1e-9, json);
        assertTrue(json.contains("Camera.getRayThrough: a camera at (1, 2, 3)"), json);
        assertTrue(Files.isRegularFile(root.resolve("results/report/index.html")));
        Files.delete(source.resolve("raytracer"));   // the link, not the installation
    }

    @Test
    void misbehaviourCostsOnlyItsMethodWithAMessage() {
        SubmissionResult r = results.get("misbehaving");
        for (TestResult t : r.tests()) {
            if (t.kind() != TestSet.Kind.CHECK) {
                continue;
            }
            String method = t.name().substring(0, t.name().indexOf(':'));
            switch (method) {
                case "Sphere.intersects" -> assertTrue(!t.passed() && t.message().contains("endless recursion (StackOverflowError)")
                        && t.message().startsWith("Sphere.intersects"), t.message());
                case "Triangle.intersects" -> assertTrue(!t.passed() && t.message().startsWith("Triangle.intersects"), t.message());
                case "Diffuse.shade" -> assertTrue(!t.passed() && t.message().contains("ran out of memory")
                        && t.message().contains("Diffuse.shade"), t.message());
                case "BlinnPhong.shade" -> {
                    assertTrue(t.passed(), t.message());
                    assertTrue(t.output().length() < 20_000 && t.output().contains("more bytes of output left out"), t.output());
                }
                default -> assertTrue(t.passed(), () -> t.name() + ": " + t.message());
            }
        }
        assertTrue(r.notes().stream().anyMatch(n -> n.startsWith("Triangle.java did not compile, so the handout's Triangle.java was graded")
                && n.contains("Triangle.java:")), r.notes().toString());
    }

    @Test
    void aStochasticSceneIsJudgedByItsMeans() {
        SubmissionResult fair = results.get("noisy-unbiased"), biased = results.get("noisy-biased");
        assertEquals(fair.maxScore(), fair.score(), () -> failures(fair));
        assertTrue(biased.score() < biased.maxScore(), () -> failures(biased));
        assertTrue(biased.tests().get(0).message().contains("Scene.renderPixel"), biased.tests().get(0).message());
    }

    @Test
    void theFallbackGradesAlikeAndSaysSo() {
        SubmissionResult sandboxed = results.get("exit"), plain = results.get("exit-unsandboxed");
        assertEquals(sandboxed.score(), plain.score(), () -> failures(plain));
        assertTrue(plain.sandbox().contains("no sandbox"), plain.sandbox());
        assertTrue(Reports.summary(plain).contains("no sandbox") && Reports.studentHtml(plain).contains("no sandbox"));
    }

    static void edit(Path file, String from, String to) throws IOException {
        String s = Files.readString(file);
        assertTrue(s.contains(from), file + " no longer holds " + from);
        Files.writeString(file, s.replace(from, to));
    }

    static String failures(SubmissionResult r) {
        StringBuilder b = new StringBuilder(r.name() + " " + r.score() + "/" + r.maxScore() + " notes " + r.notes() + "\n");
        for (TestResult t : r.tests()) {
            if (!t.passed()) {
                b.append("  ").append(t.status()).append(' ').append(t.name()).append(": ").append(t.message()).append('\n');
            }
        }
        return b.toString();
    }

    /** The handout's form of a solution file: solution regions replaced by their STUB lines. */
    static String stub(String src) {
        StringBuilder out = new StringBuilder();
        boolean inside = false;
        for (String line : src.split("\n", -1)) {
            String t = line.trim();
            if (t.startsWith("// BEGIN SOLUTION")) {
                inside = true;
            } else if (t.startsWith("// END SOLUTION")) {
                inside = false;
            } else if (!inside) {
                out.append(line).append('\n');
            } else if (t.startsWith("// STUB:")) {
                out.append(line, 0, line.indexOf("//")).append(t.substring("// STUB:".length()).trim()).append('\n');
            }
        }
        return out.toString();
    }

    /** A solution file without its markers (as a student who solved it hands it in). */
    static String unmark(String src) {
        return src.replaceAll("(?m)^\\s*// (BEGIN SOLUTION|END SOLUTION|STUB:.*)\\R", "");
    }

    static List<Path> javaFiles(Path dir) throws IOException {
        try (var s = Files.list(dir)) {
            return s.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
    }

    static Path copyTree(Path from, Path to) throws IOException {
        try (var s = Files.walk(from)) {
            for (Path p : s.toList()) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.copy(p, target);
                }
            }
        }
        return to;
    }

    /** A folder holding the whole reference solution without its markers: a student who solved everything. */
    static Path solved(Path dir) throws IOException {
        Files.createDirectories(dir);
        for (Path f : javaFiles(SOLUTION)) {
            Files.writeString(dir.resolve(f.getFileName().toString()), unmark(Files.readString(f)));
        }
        return dir;
    }

    static Path write(Path dir, String name, String text) throws IOException {
        Files.createDirectories(dir);
        Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
        return dir;
    }

    static String q(String s) {
        return "\"" + s.replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
    }

    /** What a hostile student adds: tries each escape once and prints PROBE what BLOCKED|LEAKED. */
    static final String PROBE = """
            import java.io.*;
            import java.nio.file.*;

            public class Probe {
                static boolean done;

                static void report(String what, boolean leaked) {
                    System.out.println("PROBE " + what + " " + (leaked ? "LEAKED" : "BLOCKED"));
                }

                public static synchronized void run(String reference, String outside, int port) {
                    if (done) {
                        return;
                    }
                    done = true;
                    boolean leaked;
                    try { Files.readAllBytes(Path.of(reference)); leaked = true; } catch (Throwable e) { leaked = false; }
                    report("read-reference", leaked);
                    leaked = false;
                    for (String dir : new String[] {Path.of(reference).getParent().toString(), "/grade/lib", "/grade/in", "/"}) {
                        try (var s = Files.walk(Path.of(dir), 6)) {
                            leaked |= s.anyMatch(p -> p.getFileName() != null && p.getFileName().toString().equals("one-sided-shadows.png"));
                        } catch (Throwable e) {
                            // blocked or unreadable
                        }
                    }
                    report("list-references", leaked);
                    leaked = false;
                    for (String f : new String[] {outside, "/grade/in/x.txt", "/grade/lib/x.txt", "/usr/lib/x.txt"}) {
                        try { Files.writeString(Path.of(f), "escaped"); leaked = true; } catch (Throwable e) { }
                    }
                    report("write-outside", leaked);
                    try (java.net.Socket s = new java.net.Socket()) {
                        s.connect(new java.net.InetSocketAddress("127.0.0.1", port), 2000);
                        leaked = true;
                    } catch (Throwable e) { leaked = false; }
                    report("network", leaked);
                    try { new ProcessBuilder("/bin/sh", "-c", "sleep 600").start(); leaked = true; } catch (Throwable e) { leaked = false; }
                    report("process", leaked);
                    leaked = new File(outside).getParentFile().exists();
                    report("read-tmp-of-host", leaked);
                }
            }
            """;
}
