package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The {@code raytracer} process itself (a child JVM running {@code RayTracer}), for what only a whole
 * process shows: a user's class calling System.exit, a class missing from the class path, standard
 * input and output as scene and image, and a display that does not answer. The student classes are
 * compiled here, as a student would, into a folder of their own.
 */
@Tag("slow") // child JVMs; left out by gradle mutation -PmutationFast
class CommandLineProcessTest {

    @TempDir
    Path dir;

    record Result(int status, byte[] out, String err) {
        List<String> errLines() {
            return err.lines().toList();
        }
    }

    private Result raytracer(Path classes, Map<String, String> env, File stdin, String... args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-cp");
        cmd.add(System.getProperty("java.class.path") + (classes == null ? "" : File.pathSeparator + classes));
        cmd.add("-XX:TieredStopAtLevel=1");
        if (env == null) {
            cmd.add("-Djava.awt.headless=true");
        }
        cmd.add("RayTracer");
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        if (env != null) {
            pb.environment().putAll(env);
        }
        pb.redirectInput(stdin != null ? ProcessBuilder.Redirect.from(stdin) : ProcessBuilder.Redirect.from(new File("/dev/null")));
        Path err = dir.resolve("stderr.log");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the process ended");
        String e = Files.readString(err, StandardCharsets.UTF_8);
        Files.delete(err);
        return new Result(p.exitValue(), out, e);
    }

    /** Compiles student sources (name -> text) into a new folder, as javac would for a student. */
    private Path compile(Map<String, String> sources) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assumeTrue(javac != null, "a JDK with javac is needed");
        Path src = Files.createDirectories(dir.resolve("student-src")), out = Files.createDirectories(dir.resolve("student-classes"));
        List<String> args = new ArrayList<>(List.of("-d", out.toString(), "-cp", System.getProperty("java.class.path")));
        for (Map.Entry<String, String> s : sources.entrySet()) {
            Path f = src.resolve(s.getKey() + ".java");
            Files.writeString(f, s.getValue());
            args.add(f.toString());
        }
        assertEquals(0, javac.run(null, null, null, args.toArray(new String[0])), "student classes compile");
        return out;
    }

    private static final String GOOD = MainBadInputTest.GOOD;

    private static String sceneWith(String material) {
        return GOOD + "\nMaterial " + material + " m\n\nSurface Sphere\nVector3d center [0 0 0]\nref material m\n";
    }


    /**
     * A class that calls System.exit(0) mid-render ends the program, but not with success: status 1 and
     * one line naming the scene and the calling method. A class whose helper is missing from the class
     * path (deleted after compiling) fails alone with NoClassDefFoundError; scenes before the exit render.
     */
    @Test
    void systemExitFromAUserClassIsNotASuccess() throws Exception {
        Path classes = compile(Map.of(
                "Quitter", CLASS.formatted("Quitter", "", "System.exit(0);\n        return null;"),
                "UsesHelper", CLASS.formatted("UsesHelper", "", "return Helper.color();"),
                "Helper", "public class Helper { static javax.vecmath.Vector3d color() { return new javax.vecmath.Vector3d(1, 0, 0); } }"));
        Files.delete(classes.resolve("Helper.class"));
        Files.writeString(dir.resolve("helper.txt"), sceneWith("UsesHelper"));
        Files.writeString(dir.resolve("good.txt"), GOOD);
        Files.writeString(dir.resolve("quit.txt"), sceneWith("Quitter"));
        Files.writeString(dir.resolve("after.txt"), GOOD);
        Files.write(dir.resolve("quit.png"), MainBadInputTest.oldPng());
        Result r = raytracer(classes, null, null, "-q", "helper.txt", "good.txt", "quit.txt", "after.txt");
        assertEquals(1, r.status(), r.err());
        List<String> lines = r.errLines();
        assertEquals(2, lines.size(), r.err());
        assertTrue(lines.get(0).startsWith("helper.txt: rendering failed: NoClassDefFoundError (Helper) at UsesHelper.shade("), lines.get(0));
        assertEquals("quit.txt: Quitter.shade called System.exit while the scene was being rendered; the program stopped there "
                + "and no image was written", lines.get(1));
        assertTrue(Files.size(dir.resolve("good.png")) > 0);
        assertArrayEquals(MainBadInputTest.oldPng(), Files.readAllBytes(dir.resolve("quit.png")), "the old image stays");
        assertFalse(Files.exists(dir.resolve("helper.png")));
        try (var s = Files.list(dir)) {
            assertEquals(List.of(), s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".tmp")).toList(), "no temporary file left");
        }
    }

    /** '-' reads the scene from standard input and writes the PNG to standard output; the summary goes to stderr. */
    @Test
    void dashReadsStdinAndWritesStdout() throws Exception {
        Path scene = dir.resolve("a.txt");
        Files.writeString(scene, GOOD);
        Result r = raytracer(null, null, scene.toFile(), "-");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().length > 8 && r.out()[0] == (byte) 0x89 && r.out()[1] == 'P', "a PNG on stdout");
        assertTrue(r.err().startsWith("<stdin> -> <stdout> (4x3, "), r.err());
    }

    /** A scene named @x.txt (as typed, relative) renders like any other: picocli's argument files are off. */
    @Test
    void sceneNamedLikeAnArgumentFileRenders() throws Exception {
        Files.writeString(dir.resolve("@x.txt"), GOOD);
        Result r = raytracer(null, null, null, "-q", "--threads=1", "@x.txt");     // read by picocli, not the everyday fast path
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        assertTrue(Files.size(dir.resolve("@x.png")) > 0);
        Result fast = raytracer(null, null, null, "@x.txt", "-o", "y.png");
        assertEquals(0, fast.status(), fast.err());
        assertTrue(Files.size(dir.resolve("y.png")) > 0);
    }

    /** /dev/stdin redirected from a file is read, but no PNG is written into /dev. */
    @Test
    void devStdinAsTheSceneWritesNothingIntoDev() throws Exception {
        Path scene = dir.resolve("a.txt");
        Files.writeString(scene, GOOD);
        Path devPng = Path.of("/dev/stdin.png");
        Object before = Files.exists(devPng) ? Files.getLastModifiedTime(devPng) : null;
        Result r = raytracer(null, null, scene.toFile(), "-q", "/dev/stdin");
        assertEquals(1, r.status());
        assertEquals(List.of("/dev/stdin: a PNG beside it would go into /dev; name the image with -o FILE.png, or read the scene "
                + "from standard input with '-'"), r.errLines());
        assertEquals(before, Files.exists(devPng) ? Files.getLastModifiedTime(devPng) : null, "nothing written into /dev");
        Result ok = raytracer(null, null, scene.toFile(), "-q", "/dev/stdin", "-o", "out.png");
        assertEquals(0, ok.status(), ok.err());
        assertTrue(Files.size(dir.resolve("out.png")) > 0);
    }

    /** A DISPLAY nobody answers on: the same one line and status as no display at all, no AWTError trace. */
    @Test
    void unreachableDisplayIsOneLine() throws Exception {
        Result r = raytracer(null, Map.of("DISPLAY", "nohost.invalid:37"), null);
        assertEquals(2, r.status(), r.err());
        assertEquals(List.of("raytracer: no display for the viewer (DISPLAY=nohost.invalid:37 does not answer); "
                + "give scene files to render (see --help)"), r.errLines());
    }

    /**
     * The JIT policy (JitPolicy): a long first scene starts the launcher named by RAYTRACER_RELAUNCH again
     * with RAYTRACER_JIT=long on the same command line, renders nothing itself and ends with that
     * process's status; a short one renders here and leaves the launcher alone. A scene of a few primitives
     * does not get the SIMD traversal's module (RAYTRACER_SIMD); a large one does (below).
     */
    @Test
    void longRenderStartsTheLauncherAgainUnderC2() throws Exception {
        Path fake = dir.resolve("fake-launcher");
        Files.writeString(fake, "#!/bin/sh\necho \"$RAYTRACER_JIT|${RAYTRACER_RELAUNCH-unset}|${RAYTRACER_SIMD-unset}|$*\" > " + dir.resolve("relaunched.txt") + "\nexit 7\n");
        assertTrue(fake.toFile().setExecutable(true));
        Files.writeString(dir.resolve("long.txt"), "Width 4000\nHeight 3000\nAASamples 3\n\nCamera Camera\n"
                + "Light PointLight\nVector3d position [0 5 0]\n");   // 108 M camera rays, as many shadow rays
        Files.writeString(dir.resolve("short.txt"), GOOD);
        Map<String, String> env = Map.of("RAYTRACER_RELAUNCH", fake.toString());
        Result r = raytracer(null, env, null, "-q", "long.txt", "short.txt");
        assertEquals(7, r.status(), r.err());
        assertEquals("long|unset|unset|-q long.txt short.txt", Files.readString(dir.resolve("relaunched.txt")).trim());
        assertFalse(Files.exists(dir.resolve("long.png")) || Files.exists(dir.resolve("short.png")), "nothing rendered here");
        Files.delete(dir.resolve("relaunched.txt"));
        Result s = raytracer(null, env, null, "-q", "short.txt");
        assertEquals(0, s.status(), s.err());
        assertFalse(Files.exists(dir.resolve("relaunched.txt")), "a short first scene renders here");
        assertTrue(Files.size(dir.resolve("short.png")) > 0);
    }

    /**
     * A scene with large OBJ files is judged before they are read (JitPolicy.isLongBeforeFiles): the launcher
     * starts again before the parser reads the mesh (here a 17 MB file of zeros that no parse could accept),
     * and a short render of the same mesh is not sent away. A large mesh gets the SIMD traversal
     * (RAYTRACER_SIMD=1, on JDK 17-25 with the Vector API's module); the render's stderr then comes through a
     * pipe that drops the JVM's notice of the module, and the launcher is told that this stderr is not a
     * terminal (RAYTRACER_STDERR_TTY).
     */
    @Test
    void longMeshRenderStartsTheLauncherAgainBeforeReadingTheObjFile() throws Exception {
        Path fake = dir.resolve("fake-launcher");
        Files.writeString(fake, "#!/bin/sh\necho \"$RAYTRACER_JIT|${RAYTRACER_SIMD-unset}|${RAYTRACER_STDERR_TTY-unset}|$*\" > "
                + dir.resolve("relaunched.txt") + "\nprintf 'WARNING: Using incubator modules: jdk.incubator.vector\\nfrom the render\\n' >&2\nexit 7\n");
        assertTrue(fake.toFile().setExecutable(true));
        try (java.io.RandomAccessFile f = new java.io.RandomAccessFile(dir.resolve("big.obj").toFile(), "rw")) {
            f.setLength(17L << 20);   // sparse: never written, never read
        }
        String scene = "Camera Camera\nLight AreaLight\nVector3d position [0 5 0]\nint samples 4\n\n"
                + "Material Diffuse m\n\nSurface Mesh\nString file big.obj\nref material m\n";
        Files.writeString(dir.resolve("mesh-long.txt"), "Width 1920\nHeight 1080\n" + scene);   // 35 M rays
        Files.writeString(dir.resolve("mesh-short.txt"), "Width 64\nHeight 48\n" + scene);
        Map<String, String> env = Map.of("RAYTRACER_RELAUNCH", fake.toString());
        Result r = raytracer(null, env, null, "-q", "mesh-long.txt");
        assertEquals(7, r.status(), r.err());
        if (JitPolicy.simdPays()) {   // JDK 17-25 with the module (CI's 17)
            assertEquals("from the render\n", r.err(), "the OBJ file was not read; the JVM's notice of the module dropped");
            assertEquals("long|1|false|-q mesh-long.txt", Files.readString(dir.resolve("relaunched.txt")).trim());
        } else {
            assertTrue(r.err().endsWith("from the render\n") && !r.err().contains("big.obj"), r.err());
            assertEquals("long|unset|unset|-q mesh-long.txt", Files.readString(dir.resolve("relaunched.txt")).trim());
        }
        Files.delete(dir.resolve("relaunched.txt"));
        Result s = raytracer(null, env, null, "-q", "mesh-short.txt");
        assertTrue(s.err().contains("big.obj"), s.err());   // read here, and refused
        assertFalse(Files.exists(dir.resolve("relaunched.txt")), "a short render of the mesh is not sent away");
    }

    private static final String CLASS = """
            import java.util.Set;
            import javax.vecmath.Vector3d;
            import ray.IntersectionRecord;
            import ray.Ray;
            import ray.Scene;
            import ray.material.Material;
            import ray.material.Term;

            public class %s extends Material {
                %s
                @Override
                public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
                    %s
                }
            }
            """;

    /**
     * Standard output carries only the image or the JSON: a student's System.out.println (in a
     * constructor, in shade()) goes to stderr, in every mode that writes to stdout.
     */
    @Test
    void userPrintlnNeverReachesStandardOutput() throws Exception {
        Path classes = compile(Map.of("Printer", CLASS.formatted("Printer", "public Printer() { System.out.println(\"made\"); }",
                "System.out.println(\"debug\"); System.out.print('x'); return new Vector3d(1, 0, 0);")));
        Files.writeString(dir.resolve("p.txt"), sceneWith("Printer"));
        Result png = raytracer(classes, null, null, "-q", "-o", "-", "p.txt");
        assertEquals(0, png.status(), png.err());
        javax.imageio.ImageIO.setUseCache(false);
        java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(new java.io.ByteArrayInputStream(png.out()));
        assertTrue(img != null && img.getWidth() == 4, "stdout is exactly a PNG");
        assertTrue(png.err().contains("debug") && png.err().contains("made"), "the debug lines went to stderr: " + png.err());
        for (String[] args : new String[][] {{"--plan", "--json", "p.txt"}, {"--stats", "--json", "-o", "p.png", "p.txt"}}) {
            Result r = raytracer(classes, null, null, args);
            assertEquals(0, r.status(), r.err());
            String out = new String(r.out(), java.nio.charset.StandardCharsets.UTF_8);
            assertEquals(1, out.lines().count(), out);
            assertTrue(out.startsWith("{") && out.endsWith("}\n"), "one JSON line only: " + out);
        }
    }

    /**
     * System.exit from user code is never a success in any mode: under --plan (in terms()), under
     * --study (in shade()), and from a thread a user's class started, which exits between two scenes.
     */
    @Test
    void systemExitIsNotASuccessInAnyMode() throws Exception {
        Path classes = compile(Map.of(
                "QuitTerms", CLASS.formatted("QuitTerms", "@Override public Set<Term> terms() { System.exit(0); return null; }",
                        "return new Vector3d();"),
                "QuitShade", CLASS.formatted("QuitShade", "", "System.exit(0); return null;"),
                "QuitLater", CLASS.formatted("QuitLater", "public QuitLater() { new Thread(() -> { try { Thread.sleep(300); } "
                        + "catch (InterruptedException e) { } System.exit(0); }).start(); }", "return new Vector3d(0, 1, 0);"),
                "Slow", CLASS.formatted("Slow", "static volatile boolean slept;",
                        "if (!slept) { slept = true; try { Thread.sleep(4000); } catch (InterruptedException e) { } } return new Vector3d();")));
        Files.writeString(dir.resolve("terms.txt"), sceneWith("QuitTerms"));
        Files.writeString(dir.resolve("shade.txt"), sceneWith("QuitShade"));
        Files.writeString(dir.resolve("later.txt"), sceneWith("QuitLater"));
        Files.writeString(dir.resolve("slow.txt"), sceneWith("Slow"));
        Result plan = raytracer(classes, null, null, "--plan", "terms.txt");
        assertEquals(1, plan.status(), plan.err());
        assertTrue(plan.err().contains("QuitTerms.terms called System.exit"), plan.err());
        Result study = raytracer(classes, null, null, "--study", "--quick", "--report-dir", "r", "shade.txt");
        assertEquals(1, study.status(), study.err());
        assertTrue(study.err().contains("QuitShade.shade called System.exit"), study.err());
        Result later = raytracer(classes, null, null, "-q", "-j", "1", "later.txt", "slow.txt");
        assertEquals(1, later.status(), later.err());
        assertTrue(later.err().contains("called System.exit"), later.err());
        assertFalse(Files.exists(dir.resolve("slow.png")), "the second scene was not finished");
    }
}
