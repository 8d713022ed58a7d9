package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The installed start script, bin/raytracer (src/launcher/raytracer.sh), installed under folder names a
 * shell would misread: a command substitution, quotes, a backslash, a semicolon, spaces. The script
 * must start the renderer from there, run none of those fragments, and split JAVA_OPTS as Gradle's own
 * script does (quotes honoured, nothing evaluated). The build installs the distribution before the tests
 * run and names it in the system property {@code ray.test.installHome}.
 */
@Tag("slow")
class LauncherTest {

    @TempDir
    Path dir;

    /** Every character a shell treats specially in one folder name, and a command substitution. */
    static final String HOSTILE = "x$(touch PWNED)y `touch PWNED2` a\"b'c;d\\e $HOME *";

    private static Path installHome() {
        String home = System.getProperty("ray.test.installHome");
        assumeTrue(home != null && !System.getProperty("os.name").toLowerCase().contains("windows"),
                "the build names the installed distribution (gradle test installs it first)");
        Path p = Path.of(home);
        assertTrue(Files.isExecutable(p.resolve("bin/raytracer")), "installed launcher at " + p);
        return p;
    }

    private static void copyTree(Path from, Path to) throws IOException {
        Files.walkFileTree(from, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path d, BasicFileAttributes a) throws IOException {
                Files.createDirectories(to.resolve(from.relativize(d).toString()));
                return FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path f, BasicFileAttributes a) throws IOException {
                Files.copy(f, to.resolve(from.relativize(f).toString()), StandardCopyOption.COPY_ATTRIBUTES);
                return FileVisitResult.CONTINUE;
            }
        });
    }

    private record Run(int status, String out, String err) {
    }

    private Run run(Path script, Path workDir, Map<String, String> env, String... args) throws Exception {
        List<String> cmd = new ArrayList<>();
        cmd.add(script.toString());
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(workDir.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("RAYTRACER_OPTS");
        pb.environment().put("JAVA_HOME", System.getProperty("java.home"));
        pb.environment().putAll(env);
        pb.redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        Path err = dir.resolve("stderr.log");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher ended");
        String e = Files.readString(err, StandardCharsets.UTF_8);
        Files.delete(err);
        return new Run(p.exitValue(), out, e);
    }

    private void assertNothingRan() throws IOException {
        try (Stream<Path> all = Files.walk(dir)) {
            assertFalse(all.anyMatch(p -> p.getFileName().toString().startsWith("PWNED")), "no shell fragment ran");
        }
    }

    @Test
    void startsFromAFolderWithShellCharactersAndRunsNoneOfThem() throws Exception {
        Path install = dir.resolve(HOSTILE).resolve("raytracer");
        copyTree(installHome(), install);
        Path work = Files.createDirectories(dir.resolve("work " + HOSTILE));
        Files.writeString(work.resolve("s.txt"), "Width 4\nHeight 3\nCamera Camera\nVector3d eye [0 0 5]\n"
                + "Material Diffuse d\nVector3d diffuseColor [1 0 0]\n"
                + "Surface Sphere\ndouble radius 1\nref material d\n"
                + "Light PointLight\nVector3d position [3 3 3]\n");

        // a render through the script in the hostile folder, class-data sharing archive present
        assertTrue(Files.exists(install.resolve("lib/raytracer.jsa")), "the archive is installed, so its option is used");
        Run r = run(install.resolve("bin/raytracer"), work, Map.of(), "-q", "s.txt");
        assertEquals(0, r.status, r.err);
        assertTrue(Files.size(work.resolve("s.png")) > 0, "the image was written");
        assertNothingRan();

        // started through a symbolic link (resolved to the installation, as Gradle's script does)
        Path link = Files.createSymbolicLink(work.resolve("rt link"), install.resolve("bin/raytracer"));
        Run v = run(link, work, Map.of(), "--version");
        assertEquals(0, v.status, v.err);
        assertTrue(v.out.toLowerCase().contains("raytracer"), v.out);
        assertNothingRan();
        assertTrue(Files.isSymbolicLink(link) && Files.exists(link, LinkOption.NOFOLLOW_LINKS));
    }

    @Test
    void javaOptsAreSplitWithQuotesAndNeverEvaluated() throws Exception {
        Path script = installHome().resolve("bin/raytracer");
        Run r = run(script, dir, Map.of(
                "JAVA_OPTS", "\"-Dray.test.spaced=a b\" -XshowSettings:properties",
                "RAYTRACER_OPTS", "-Dray.test.sub=$(touch${IFS}PWNED) -Dray.test.tick=`touch${IFS}PWNED2`"),
                "--version");
        assertEquals(0, r.status, r.err);
        assertTrue(r.err.contains("ray.test.spaced = a b"), "quoted option kept whole: " + r.err);
        assertTrue(r.err.contains("ray.test.sub = $(touch${IFS}PWNED)"), "passed literally: " + r.err);
        assertTrue(r.err.contains("ray.test.tick = `touch${IFS}PWNED2`"), "passed literally: " + r.err);
        assertNothingRan();
    }

    /**
     * A long render (RAYTRACER_JIT=long, as the JIT policy starts it) runs full tiered compilation with at
     * least four compiler threads (the JVM's own choice on 2 CPUs is two, one for C2: docs/performance.md,
     * "Long renders: the JIT's warm-up"), a user's -XX:CICompilerCount wins, and a short one keeps C1 only
     * and the JVM's own count.
     */
    @Test
    void aLongRenderGetsC2AndAtLeastFourCompilerThreads() throws Exception {
        Path script = installHome().resolve("bin/raytracer");
        Run longRun = run(script, dir, Map.of("RAYTRACER_JIT", "long", "JAVA_OPTS", "-XX:+PrintFlagsFinal"), "--version");
        assertEquals(0, longRun.status, longRun.err);
        // a long render's JVM writes its own output (this table) to stderr: stdout may carry an image
        assertEquals(4, flag(longRun.err, "TieredStopAtLevel"));
        assertTrue(flag(longRun.err, "CICompilerCount") >= 4, longRun.err);
        assertTrue(!longRun.out.contains("CICompilerCount"), "nothing of the JVM's on stdout: " + longRun.out);
        Run own = run(script, dir, Map.of("RAYTRACER_JIT", "long", "JAVA_OPTS", "-XX:+PrintFlagsFinal -XX:CICompilerCount=2"),
                "--version");
        assertEquals(2, flag(own.err, "CICompilerCount"), "the user's count wins");
        Run shortRun = run(script, dir, Map.of("RAYTRACER_JIT", "short", "JAVA_OPTS", "-XX:+PrintFlagsFinal"), "--version");
        assertEquals(1, flag(shortRun.out, "TieredStopAtLevel"));
        assertTrue(shortRun.out.matches("(?s).*\\bCICompilerCount\\s+=\\s+\\d+\\s+\\{product\\} \\{ergonomic\\}.*"),
                "a short render keeps the JVM's own count: " + shortRun.out);
    }

    /**
     * A long render with RAYTRACER_SIMD=1 gets the Vector API's module, the wide traversal and Wide4's
     * inlining (the JIT policy drops the JVM's notice of the module: JitPolicyNoticeTest), the exit status
     * is the JVM's, and RAYTRACER_STDERR_TTY (the JIT policy's own answer, its child's stderr being a pipe)
     * decides whether stderr counts as a terminal. Without RAYTRACER_SIMD, no module. Every long render,
     * and no short one, gets the render's warm-up pixels ({@code ray.render.warmUp}).
     */
    @Test
    void aLongRenderWithSimdGetsTheVectorModule() throws Exception {
        Path script = installHome().resolve("bin/raytracer");
        String show = "-XshowSettings:properties --show-module-resolution";
        Run ok = run(script, dir, Map.of("RAYTRACER_JIT", "long", "RAYTRACER_SIMD", "1", "RAYTRACER_STDERR_TTY", "true",
                "JAVA_OPTS", show), "--version");
        assertEquals(0, ok.status, ok.err);
        assertTrue(java.util.regex.Pattern.compile("(?m)^root jdk\\.incubator\\.vector ").matcher(ok.out).find(),
                "the module added: " + ok.out);
        assertTrue(ok.err.contains("ray.bvh.wide = true") && ok.err.contains("raytracer.stderrTty = true"), ok.err);
        assertTrue(!ok.out.contains("CompileCommand"), "the inlining command is quiet: " + ok.out);
        assertTrue(java.util.regex.Pattern.compile("(?m)^raytracer ").matcher(ok.out).find(), "the version: " + ok.out);
        Run missing = run(script, dir, Map.of("RAYTRACER_JIT", "long", "RAYTRACER_SIMD", "1"), "no-such-scene.txt");
        Run plain = run(script, dir, Map.of("RAYTRACER_JIT", "long"), "no-such-scene.txt");
        assertTrue(missing.status != 0, missing.err);
        assertEquals(plain.status, missing.status, "the JVM's exit status");
        Run off = run(script, dir, Map.of("RAYTRACER_JIT", "long", "JAVA_OPTS", show), "--version");
        assertTrue(!off.out.contains("jdk.incubator.vector") && !off.err.contains("ray.bvh.wide"), off.out + off.err);
        assertTrue(off.err.contains("raytracer.stderrTty = false"), "stderr is a file here: " + off.err);
        // every long render warms the JIT's profiles on pixels spread over the image; a short one does not
        assertTrue(off.err.contains("ray.render.warmUp = true") && ok.err.contains("ray.render.warmUp = true"), off.err);
        Run shortShow = run(script, dir, Map.of("RAYTRACER_JIT", "short", "JAVA_OPTS", show), "--version");
        assertTrue(!shortShow.err.contains("ray.render.warmUp"), shortShow.err);
        // the young generation capped for the vector code's warm-up garbage, unless the user sizes the heap
        Run young = run(script, dir, Map.of("RAYTRACER_JIT", "long", "RAYTRACER_SIMD", "1", "JAVA_OPTS", "-XX:+PrintFlagsFinal"),
                "--version");
        assertEquals(192L << 20, flag(young.err, "MaxNewSize"), "a SIMD render's young generation");
        assertTrue(young.err.matches("(?s).*\\bMaxNewSize\\s+=\\s+\\d+\\s+\\{product\\} \\{command line\\}.*"), young.err);
        Run sized = run(script, dir, Map.of("RAYTRACER_JIT", "long", "RAYTRACER_SIMD", "1", "JAVA_OPTS",
                "-XX:+PrintFlagsFinal -Xmx64m"), "--version");
        assertEquals(0, sized.status, sized.err);
        assertTrue(flag(sized.err, "MaxNewSize") < 64L << 20 && !sized.err.contains("VM warning"),
                "the user's heap size, no warning: " + sized.err);
        Run plainYoung = run(script, dir, Map.of("RAYTRACER_JIT", "long", "JAVA_OPTS", "-XX:+PrintFlagsFinal"), "--version");
        assertTrue(!plainYoung.err.matches("(?s).*\\bMaxNewSize\\s+=\\s+\\d+\\s+\\{product\\} \\{command line\\}.*"),
                "only a SIMD render's: " + plainYoung.err);
    }

    /**
     * A long render's BVH build is never compiled by C2 (the installation's lib/c2-directives.json): with
     * C2's thresholds lowered so that a build of 3,000 spheres would reach it, and every compilation done
     * before the code that asked for it goes on ({@code -Xbatch}: on a loaded machine a queued compile of
     * the builder could otherwise still be waiting when the build ends, which failed CI once), the builder is compiled by
     * C1 only (level 1: without profiling) while the render's own methods reach level 4; a user's own
     * directives file (here one that matches nothing) wins, and then the builder does reach C2, which
     * shows the check can fail. The JVM's line about the file goes to stderr: an image written to stdout
     * starts with PNG's signature.
     */
    @Test
    void aLongRendersBvhBuildIsNotCompiledByC2() throws Exception {
        Path script = installHome().resolve("bin/raytracer");
        assertTrue(Files.isRegularFile(installHome().resolve("lib/c2-directives.json")), "the directives are installed");
        StringBuilder scene = new StringBuilder("Width 16\nHeight 12\nCamera Camera\nVector3d eye [0 0 30]\n"
                + "Material Diffuse d\nVector3d diffuseColor [1 0 0]\nLight PointLight\nVector3d position [3 3 40]\n");
        java.util.Random random = new java.util.Random(36);
        for (int i = 0; i < 3000; i++) {
            scene.append(String.format(java.util.Locale.ROOT, "Surface Sphere%nVector3d center [%.4f %.4f %.4f]%n"
                    + "double radius 0.05%nref material d%n", random.nextDouble() * 20 - 10, random.nextDouble() * 20 - 10,
                    random.nextDouble() * 20 - 10));
        }
        Files.writeString(dir.resolve("many.txt"), scene.toString());
        String jit = "-Xbatch -XX:+PrintCompilation -XX:CompileThresholdScaling=0.02";   // -Xbatch: each compile done before the code goes on, whatever the load
        java.util.regex.Pattern builderC2 = java.util.regex.Pattern.compile("(?m)^\\s*\\d+\\s+\\d+\\s+[%sbn! ]*4\\s+ray\\.accel\\.BvhBuilder");
        java.util.regex.Pattern builderC1 = java.util.regex.Pattern.compile("(?m)^\\s*\\d+\\s+\\d+\\s+[%sbn! ]*1\\s+ray\\.accel\\.BvhBuilder::findSplit");
        java.util.regex.Pattern renderC2 = java.util.regex.Pattern.compile("(?m)^\\s*\\d+\\s+\\d+\\s+[%sbn! ]*4\\s+ray\\.");

        Run ours = run(script, dir, Map.of("RAYTRACER_JIT", "long", "JAVA_OPTS", jit), "-q", "-o", "-", "many.txt");
        assertEquals(0, ours.status, ours.err);
        assertTrue(ours.out.startsWith("\uFFFDPNG\r\n"), "the image alone on stdout");
        assertTrue(ours.err.contains("1 compiler directives added"), "the JVM read the installed file: " + ours.err);
        assertTrue(renderC2.matcher(ours.err).find(), "C2 compiles the render's methods");
        assertFalse(builderC2.matcher(ours.err).find(), "no C2 compile of the builder");
        assertTrue(builderC1.matcher(ours.err).find(), "the builder's split search compiled by C1 without profiling");

        Path none = Files.writeString(dir.resolve("none.json"), "[ { match: \"none/None.none\", c2: { Exclude: true } } ]");
        Run theirs = run(script, dir, Map.of("RAYTRACER_JIT", "long", "JAVA_OPTS", jit + " -XX:CompilerDirectivesFile=" + none),
                "-q", "-o", "-", "many.txt");
        assertEquals(0, theirs.status, theirs.err);
        assertTrue(builderC2.matcher(theirs.err).find(), "the user's directives win, and the builder reaches C2: " + theirs.err);
    }

    /** The value of JVM flag {@code name} in -XX:+PrintFlagsFinal's table. */
    private static long flag(String table, String name) {
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("\\b" + name + "\\s+=\\s+(\\d+)").matcher(table);
        assertTrue(m.find(), name + " in " + table);
        return Long.parseLong(m.group(1));
    }

    /**
     * Under LC_ALL=C (cron, containers) a scene named café.txt renders: the launcher gives the JVM a UTF-8
     * locale where the user's is not, so the name is not decoded as 'caf??.txt'. The name's bytes are made
     * by the shell, whatever this test JVM's own encoding.
     */
    @Test
    void aNonAsciiSceneNameRendersUnderTheCLocale() throws Exception {
        Path script = installHome().resolve("bin/raytracer");
        Path work = Files.createDirectories(dir.resolve("c-locale"));
        String out = shell(script, work, "name=$(printf 'caf\\303\\251.txt'); printf 'Width 4\\nHeight 3\\n\\n"
                + "Camera Camera\\n' > \"$name\"; LC_ALL=C LANG=C \"$0\" -q \"$name\"; echo \"status $?\"");
        assertEquals("status 0\n", out);
        try (Stream<Path> s = Files.list(work)) {
            assertEquals(1, s.filter(f -> f.getFileName().toString().endsWith(".png")).count(), "café.png written");
        }
    }

    /**
     * A name whose bytes are not UTF-8 (café in Latin-1) cannot be opened by the JVM (it decodes the byte
     * to U+FFFD): the launcher says so in one line with the way round it, status 2, before Java starts;
     * and the way round it works. The name's bytes are made by the shell.
     */
    @Test
    void aNameThatIsNotUtf8IsNamedWithTheWayRoundIt() throws Exception {
        Path script = installHome().resolve("bin/raytracer");
        Path work = Files.createDirectories(dir.resolve("latin1"));
        String out = shell(script, work, "name=$(printf 'caf\\351.txt'); printf 'Width 4\\nHeight 3\\n\\n"
                + "Camera Camera\\n' > \"$name\"; \"$0\" -q \"$name\"; echo \"status $?\"; \"$0\" -q - < \"$name\" > out.png; "
                + "echo \"status $?\"");
        assertEquals("raytracer: the name 'caf?.txt' is not valid UTF-8 (a name in another encoding, e.g. Latin-1), and Java cannot "
                + "open a file by such a name: rename the file (e.g. convmv -f latin1 -t utf8), or give it by redirection: "
                + "raytracer - < NAME reads a scene, raytracer -o - scene.txt > NAME writes an image\nstatus 2\nstatus 0\n", out);
        assertTrue(Files.size(work.resolve("out.png")) > 0, "read from standard input, the scene renders");
    }

    /**
     * Runs {@code script} in {@code sh -c} (names made from bytes by the shell, whatever this JVM's
     * encoding), with the launcher as $0; returns stdout and stderr together.
     */
    private static String shell(Path launcher, Path work, String script) throws Exception {
        ProcessBuilder pb = new ProcessBuilder("sh", "-c", script, launcher.toString()).directory(work.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("RAYTRACER_OPTS");
        pb.environment().put("JAVA_HOME", System.getProperty("java.home"));
        pb.redirectErrorStream(true);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the shell ended");
        return out;
    }
}
