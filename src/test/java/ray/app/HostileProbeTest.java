package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.api.io.TempDir;
import ray.Failures;

/**
 * Issue 17's probes, each in every mode it applies to, against the installed distribution
 * ({@code bin/raytracer}, as a user runs it): render, {@code -o -}, {@code --stats --json},
 * {@code --plan}, {@code --plan --json}, {@code --study} and {@code --view} (on a throw-away Xvfb).
 * Every run is held to the same rules, whatever the probe: the expected exit status; no hang (each
 * run has a deadline); no stack trace; a failure is exactly one line on stderr that starts with a name
 * (file, file:line or {@code raytracer}) and says what the probe expects (a class.method, a cause);
 * no file that was there is changed (bytes, mode, link) and a failed run creates none (but the study's
 * report folder); no temporary file is left; standard output holds only a PNG or JSON Lines.
 * The table of every run (probe, mode, status, the line) is printed.
 */
class HostileProbeTest {

    @TempDir
    static Path work;

    private static Path launcher;
    private static Path classes;
    /** This test's own classes (SelfOperand, SharedOperands in the default package), for the probes that name them. */
    private static String testClasses;
    private static Process xvfb;
    private static String display;

    /** The modes a probe may run in, and the options each adds before the probe's own arguments. */
    enum Mode {
        RENDER(), STDOUT("-o", "-"), STATS_JSON("--stats", "--json", "-o", "out.png"), PLAN("--plan"), PLAN_JSON("--plan", "--json"),
        STUDY("--study", "--quick", "--report-dir", "rep"), VIEW("--view");

        final List<String> options;

        Mode(String... options) {
            this.options = List.of(options);
        }
    }

    /** A probe's "environment variable" naming where standard output goes instead (/dev/full). */
    static final String STDOUT_TO = ">";

    /** Status of a --view run whose window stays open showing the failure (the process is then ended by the test). */
    static final int OPEN = -1;
    /** Status 0, and the output says what the probe expects ("0!" in a probe's statuses; a plain 0 in a probe that fails elsewhere does not). */
    static final int SAYS = -3;

    interface Setup {
        void in(Path dir) throws IOException;
    }

    /**
     * One probe: files made by {@code setup} in a fresh folder per run, the arguments after the mode's
     * options, the status per mode, and a pattern the failure line (or, for a success, the output) must
     * contain. {@code stdin}: what standard input holds (null: nothing; "endless": 'Width 10' for ever).
     */
    record Probe(String id, String what, Setup setup, List<String> args, Map<Mode, Integer> status, Pattern says, String stdin,
            Map<String, String> env, Pattern creates) {
    }

    private static final List<Probe> PROBES = new ArrayList<>();

    static final String SCENE = """
            Width 8
            Height 6
            Camera Camera
            Vector3d eye [0 0 5]
            Vector3d target [0 0 0]
            Material %s m
            Surface %s
            ref material m
            Light PointLight
            Vector3d position [0 5 5]
            Vector3d intensity [10 10 10]
            """;

    static String scene(String material, String surface) {
        return SCENE.formatted(material, surface);
    }

    static String material(String m) {
        return scene(m, "Sphere");
    }

    static final String GOOD = material("Diffuse");

    private static Map<Mode, Integer> statuses(String spec) {
        Map<Mode, Integer> m = new LinkedHashMap<>();
        for (String s : spec.split(" ")) {
            String[] kv = s.split("=");
            m.put(Mode.valueOf(kv[0]), kv[1].equals("open") ? OPEN : kv[1].equals("0!") ? SAYS : Integer.parseInt(kv[1]));
        }
        return m;
    }

    private static void probe(String id, String what, Setup setup, String statuses, String says, String... args) {
        probe(id, what, setup, statuses, says, null, Map.of(), args);
    }

    private static void probe(String id, String what, Setup setup, String statuses, String says, String stdin, Map<String, String> env,
            String... args) {
        PROBES.add(new Probe(id, what, setup, List.of(args), statuses(statuses), Pattern.compile(says), stdin, env,
                Pattern.compile(id.equals("2.2") ? "rep/.*|later\\.png"     // the scene before the exit was rendered
                        : id.equals("6.1") ? "a\\.png|out\\.png"               // rendered; only the summary or JSON line was lost
                        : "rep/.*")));
    }

    private static Setup file(String name, String text) {
        return d -> write(d, name, text);
    }

    private static Path write(Path d, String name, String text) throws IOException {
        Path p = d.resolve(name);
        Files.createDirectories(p.getParent());
        return Files.writeString(p, text, StandardCharsets.UTF_8);
    }

    private static Setup both(Setup a, Setup b) {
        return d -> {
            a.in(d);
            b.in(d);
        };
    }

    private static void mkfifo(Path p) throws IOException {
        try {
            assumeTrue(new ProcessBuilder("mkfifo", p.toString()).start().waitFor() == 0, "mkfifo works here");
        } catch (InterruptedException e) {
            throw new IOException(e);
        }
    }

    /** A failure of a user's class at planning time: every mode. */
    static final String ALL_FAIL = "RENDER=1 STDOUT=1 STATS_JSON=1 PLAN=1 PLAN_JSON=1 STUDY=1 VIEW=open";
    /**
     * A failure while the scene is read: one code path (the parser) for every mode, so a render and a
     * plan for each; the study and the viewer read scenes the same way, and the FIFO and the class that
     * cannot be loaded run there too ({@link #EVERY_READ}).
     */
    static final String READ_FAIL = "RENDER=1 PLAN=1";
    static final String EVERY_READ = "RENDER=1 PLAN=1 STUDY=1 VIEW=open";
    /** A failure while rendering: every mode that renders; the plan, which does not, succeeds. */
    static final String RENDERS_FAIL = "RENDER=1 STDOUT=1 PLAN=0 STUDY=1 VIEW=open";
    static final String OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";

    static {
        // ---- 1. files: never replace what the user did not ask to replace ----
        probe("1.1", "a.png is a link to notes.txt", both(file("a.txt", GOOD), d -> {
            write(d, "notes.txt", "my notes\n");
            Files.createSymbolicLink(d.resolve("a.png"), Path.of("notes.txt"));
        }), "RENDER=1", "a\\.png: cannot write the image: .*notes\\.txt \\(where a\\.png leads\\) is not a PNG image", "a.txt");
        probe("1.1", "a.png is a link to another scene", both(file("a.txt", GOOD), d -> {
            write(d, "b.txt", GOOD);
            Files.createSymbolicLink(d.resolve("a.png"), Path.of("b.txt"));
        }), "RENDER=1", "is not a PNG image", "a.txt");
        probe("1.2", "-o model.obj where the scene reads model.obj", both(file("model.obj", OBJ),
                file("m.txt", scene("Diffuse", "Mesh\nString file model.obj"))), "RENDER=1", "model\\.obj: cannot write the image",
                "-o", "model.obj", "m.txt");
        probe("1.2", "-o ./x/../model.obj, the same input spelled otherwise", both(file("model.obj", "\u0089PNG\r\n\u001a\n"),
                file("m.txt", scene("Diffuse", "Mesh\nString file model.obj"))), "RENDER=1", "model\\.obj: cannot write the image",
                "-o", "./model.obj", "m.txt");
        probe("1.3", "--study: site/index.html not the study's", both(file("a.txt", GOOD), file("rep/index.html", "mine\n")),
                "STUDY=1", "rep/index\\.html: it exists and was not written by a study", "a.txt");
        probe("1.3", "--study: rep/a.csv a link to ../precious.txt", both(file("a.txt", GOOD), d -> {
            write(d, "precious.txt", "precious\n");
            Files.createDirectories(d.resolve("rep"));
            Files.createSymbolicLink(d.resolve("rep/a.csv"), Path.of("../precious.txt"));
        }), "STUDY=1", "rep/a\\.csv: it is a symbolic link \\(to \\.\\./precious\\.txt\\)", "a.txt");
        probe("1.3", "--study: x/s.txt and y/s.txt", both(file("x/s.txt", GOOD), file("y/s.txt", GOOD)), "STUDY=0!",
                "study of 2 scene", "x/s.txt", "y/s.txt");
        probe("1.4", "a read-only (444) image", both(file("a.txt", GOOD), d -> {
            Files.write(d.resolve("a.png"), "\u0089PNG\r\n\u001a\nold".getBytes(StandardCharsets.ISO_8859_1));
            Files.setPosixFilePermissions(d.resolve("a.png"), PosixFilePermissions.fromString("r--r--r--"));
        }), "RENDER=1", "a\\.png: cannot write the image: it is read-only \\(mode 444\\)", "a.txt");

        // ---- 2. user code: contained in every mode, never in the output streams ----
        probe("2.1", "System.out.println in a constructor and shade()", file("p.txt", material("Printer")),
                "RENDER=0 STDOUT=0 STATS_JSON=0 PLAN=0 PLAN_JSON=0", "", "p.txt");
        probe("2.2", "System.exit(0) in shade()", file("q.txt", material("Quit")),
                "RENDER=1 STDOUT=1 STATS_JSON=1 PLAN=0 PLAN_JSON=0 STUDY=1 VIEW=1",
                "^q\\.txt: Quit\\.shade called System\\.exit while the scene was being (rendered|studied)|^raytracer: Quit\\.shade called System\\.exit "
                + "while the viewer was open", "q.txt");
        probe("2.2", "System.exit(0) in terms()", file("q.txt", material("QuitTerms")),
                "RENDER=1 PLAN=1 PLAN_JSON=1 STUDY=1",
                "^q\\.txt: QuitTerms\\.terms called System\\.exit while the scene was being (rendered|planned|studied)", "q.txt");
        probe("2.2", "a user thread calls System.exit between two scenes", both(file("later.txt", material("Later")),
                file("slow.txt", material("Slow"))), "RENDER=1 VIEW=1", "Later\\.lambda.*called System\\.exit", "-j", "1", "later.txt", "slow.txt");
        probe("2.3", "an Error in terms()", file("t.txt", material("ErrTerms")), ALL_FAIL, "ErrTerms\\.terms", "t.txt");
        probe("2.3", "an Error in init()", file("i.txt", material("ErrInit")), READ_FAIL, "ErrInit\\.init", "i.txt");
        probe("2.3", "an AssertionError in shade()", file("a.txt", material("Asrt")), RENDERS_FAIL, "Asrt\\.shade", "a.txt");
        probe("2.3", "getMessage() throws", file("b.txt", material("BadMsg")), RENDERS_FAIL, "its getMessage\\(\\) threw", "b.txt");
        StringBuilder glazed = new StringBuilder("Width 8\nHeight 6\nCamera Camera\nMaterial Diffuse g0\n");
        for (int k = 1; k <= 5000; k++) {
            glazed.append("Material Glazed g").append(k).append("\nref base g").append(k - 1).append('\n');
        }
        probe("2.3", "a 5,000-level Glazed chain", file("g.txt", glazed.toString()), READ_FAIL,
                "g\\.txt:\\d+: Material GlazedMaterial: a chain of more than 100 Glazed", "g.txt");
        probe("2.4", "a FIFO as the scene", d -> mkfifo(d.resolve("pipe.txt")), EVERY_READ, "pipe\\.txt: cannot read the scene: not a regular "
                + "file \\(a FIFO\\)", "pipe.txt");
        probe("2.5", "a class whose superclass is missing", file("n.txt", material("NeedsBase")), EVERY_READ,
                "n\\.txt:6: class 'NeedsBase' cannot be loaded: it needs the class Base", "n.txt");
        probe("2.5", "a class compiled for a newer Java", file("n.txt", material("NewJava")), READ_FAIL,
                "n\\.txt:6: class 'NewJava' cannot be loaded: it was compiled for a newer Java", "n.txt");
        probe("2.6", "endless recursion in shade() at -j 4", file("r.txt", material("Recurse")), RENDERS_FAIL,
                "Recurse\\.shade.*StackOverflowError|StackOverflowError.*Recurse\\.shade", "-j", "4", "r.txt");

        // ---- 3. resources: bounded before the work ----
        StringBuilder dag = new StringBuilder(GOOD.replace("Surface Sphere\nref material m\n", "Surface Sphere c0\nref material m\n"));
        for (int k = 1; k <= 40; k++) {
            dag.append("Surface CSG c").append(k).append("\nString operation union\nref left c").append(k - 1)
                    .append("\nref right c").append(k - 1).append('\n');
        }
        probe("3.1", "CSGs sharing operands 40 levels deep", file("c.txt", dag.toString()), READ_FAIL,
                "c\\.txt:\\d+: Surface CSG: .*one surface is both operands of a CSG", "c.txt");
        StringBuilder chain = new StringBuilder(GOOD.replace("Surface Sphere\nref material m\n", "Surface Sphere c0\nref material m\n"));
        for (int k = 1; k <= 10_000; k++) {
            chain.append("Surface Sphere s").append(k).append("\nref material m\nSurface CSG c").append(k)
                    .append("\nString operation union\nref left c").append(k - 1).append("\nref right s").append(k).append('\n');
        }
        probe("3.1", "a chain of 10,000 unions", file("c.txt", chain.toString()), "RENDER=1 PLAN=1",
                "c\\.txt:\\d+: Surface CSG: .*a ray tests every operand below each level of a chain", "c.txt");
        probe("3.1", "a surface whose operands() return itself", file("o.txt", scene("Diffuse", "SelfOperand")), "RENDER=1 PLAN=1 STUDY=1",
                "o\\.txt:7: SelfOperand's operands lead back to itself", "o.txt");
        probe("3.1", "a surface sharing operands 60 levels deep (2^60 paths)", file("o.txt", scene("Diffuse", "SharedOperands")),
                "RENDER=0 PLAN=0 PLAN_JSON=0", "", "o.txt");
        String glass = "Width %d\nHeight %d\nAASamples 64\nMaxDepth 1000\nCamera Camera\nMaterial DielectricMaterial g\nSurface Sphere\n"
                + "ref material g\n";
        probe("3.2", "glass at MaxDepth 1000, 4000x4000, AASamples 64", file("g.txt", glass.formatted(4000, 4000)),
                "RENDER=1 STDOUT=1 STATS_JSON=1 PLAN=0!", "refused: .*more than a million years|a render would be refused", "g.txt");
        probe("3.2", "the same at 8x6", file("g.txt", glass.formatted(8, 6)), "RENDER=1 PLAN=0!",
                "refused: .*more than a million years|a render would be refused", "g.txt");
        probe("3.3", "yes 'Width 10' | raytracer -", d -> { }, "RENDER=1 PLAN=1 STUDY=1",
                "<stdin>:2: Width is set twice", "endless", Map.of(), "-");
        probe("3.4", "-j 40000", file("a.txt", GOOD), "RENDER=2 STATS_JSON=2", "raytracer: --threads must be 1 to 1024, got 40000",
                "-j", "40000", "a.txt");
        for (String[] f : new String[][] {{"pipe.obj", "not a regular file \\(a FIFO"}, {"/dev/zero", "outside the scene file's folder"},
            {"/proc/self/environ", "outside the scene file's folder"}, {"../x.obj", "outside the scene file's folder"}}) {
            probe("3.5", "a Mesh file " + f[0], both(file("in/m.txt", scene("Diffuse", "Mesh\nString file " + f[0])), d -> {
                if (f[0].equals("pipe.obj")) {
                    mkfifo(d.resolve("in/pipe.obj"));
                } else {
                    write(d, "x.obj", OBJ);
                }
            }), "RENDER=1 PLAN=1 STUDY=1", "in/m\\.txt:7: Surface Mesh: .*" + f[1], "in/m.txt");
        }
        probe("3.6", "2730x2730 jittered in a 512 MB heap", file("big.txt", "Width 2730\nHeight 2730\nSampler jittered\nCamera Camera\n"),
                "RENDER=1 PLAN=1", "big\\.txt:1: Width 2730 x Height 2730 = 7,452,900 pixels would need about", null,
                Map.of("JAVA_OPTS", "-Xmx512m"), "big.txt");
        probe("3.6", "--sampler adaptive on 1600x1600 in a 512 MB heap", file("big.txt", "Width 1600\nHeight 1600\nCamera Camera\n"),
                "RENDER=1", "big\\.txt: Width 1600 x Height 1600 = 2,560,000 pixels would need about .* adaptive", null,
                Map.of("JAVA_OPTS", "-Xmx512m"), "--sampler", "adaptive", "big.txt");

        // ---- 4. input read exactly ----
        probe("4.1", "an OBJ file with a byte-order mark", both(file("m.obj", "\uFEFF" + OBJ),
                file("m.txt", scene("Diffuse", "Mesh\nString file m.obj"))), "RENDER=0 PLAN=0", "", "m.txt");
        probe("4.2", "OBJ: f 1 2 99999999999", both(file("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n"),
                file("m.txt", scene("Diffuse", "Mesh\nString file m.obj"))), "RENDER=1 PLAN=1",
                "m\\.obj:4: 'f 1 2 99999999999' has the index 99999999999", "m.txt");
        probe("4.2", "OBJ: v 0x1p0 0 0", both(file("m.obj", "v 0x1p0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"),
                file("m.txt", scene("Diffuse", "Mesh\nString file m.obj"))), "RENDER=1 PLAN=1", "m\\.obj:1: cannot read 'v 0x1p0 0 0'", "m.txt");
        probe("4.2", "OBJ: tab-separated f", both(file("m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf\t1\t2\t3\n"),
                file("m.txt", scene("Diffuse", "Mesh\nString file m.obj"))), "RENDER=0 PLAN=0", "", "m.txt");
        probe("4.4", "'-' is standard input, ./- is not read", file("-", "Width 2\nHeight 2\nCamera Camera\n"),
                "RENDER=1 PLAN=1 STUDY=1", "<stdin>:2: Width is set twice", "endless", Map.of(), "-");

        // ---- 6. statuses and streams ----
        probe("6.1", "standard output is /dev/full", file("a.txt", GOOD), "RENDER=1 STDOUT=1 STATS_JSON=1 PLAN=1 PLAN_JSON=1",
                "^(raytracer: cannot write to standard output|a\\.txt: cannot write the image to standard output)", null,
                Map.of(STDOUT_TO, "/dev/full"), "a.txt");
        probe("6.2", "--plan --view", file("a.txt", GOOD), "PLAN=2", "raytracer: --view does nothing with --plan", "--view", "a.txt");
        probe("6.2", "--quick without --study", file("a.txt", GOOD), "RENDER=2 PLAN=2", "raytracer: --quick goes with --study", "--quick", "a.txt");
        probe("6.2", "--stats with --plan", file("a.txt", GOOD), "PLAN=2 STUDY=2", "raytracer: --stats reports a render", "--stats", "a.txt");
        probe("6.2", "-q with a zero-area triangle and a negative colour", file("w.txt", GOOD.replace("Material Diffuse m",
                "Material Diffuse m\nVector3d diffuseColor [-1 0 0]") + "Surface Triangle\nref material m\n"), "RENDER=0 PLAN=0 STUDY=0", "",
                "-q", "w.txt");
        probe("6.2", "-o ''", file("a.txt", GOOD), "RENDER=2", "raytracer: --output is empty", "-o", "", "a.txt");
        probe("6.2", "s.txt s.txt", file("s.txt", GOOD), "RENDER=2 PLAN=2 STUDY=2", "raytracer: the scene s\\.txt is given twice", "s.txt", "s.txt");
        probe("6.2", "s.txt ./s.txt", file("s.txt", GOOD), "RENDER=2", "raytracer: the scene \\./s\\.txt is given twice", "s.txt", "./s.txt");
        probe("6.3", "an escape sequence in the file name", file("a\u001b[31mred.txt", GOOD), "RENDER=0 PLAN=0", "", "a\u001b[31mred.txt");
        probe("6.3", "an eye at [1e308 1e308 1e308]", file("e.txt", GOOD.replace("[0 0 5]", "[1e308 1e308 1e308]")), "RENDER=0 PLAN=0", "",
                "e.txt");
        probe("6.3", "an empty scene name", file("a.txt", GOOD), "RENDER=2 PLAN=2", "raytracer: an empty scene name", "");
        probe("6.3", "a Cylinder's derived field 'height'", file("c.txt", scene("Diffuse", "Cylinder\ndouble height 2")), READ_FAIL,
                "c\\.txt:8: field 'height' of Cylinder is private", "c.txt");
        probe("6.3", "a user bounds() returning null", file("n.txt", scene("Diffuse", "NullBox")), "RENDER=1 STDOUT=1 STUDY=1 VIEW=open",
                "NullBox\\.bounds\\(\\) returned null", "n.txt");
    }

    /** The student classes the probes name, compiled against the installed jars as a student would. */
    static final Map<String, String> CLASSES = new TreeMap<>();

    static {
        String material = """
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
        CLASSES.put("Printer", material.formatted("Printer", "public Printer() { System.out.println(\"made\"); }",
                "System.out.println(\"debug\"); return new Vector3d(1, 0, 0);"));
        CLASSES.put("Quit", material.formatted("Quit", "", "System.exit(0); return null;"));
        CLASSES.put("QuitTerms", material.formatted("QuitTerms", "@Override public Set<Term> terms() { System.exit(0); return null; }",
                "return new Vector3d();"));
        CLASSES.put("Later", material.formatted("Later", "public Later() { new Thread(() -> { try { Thread.sleep(300); } "
                + "catch (InterruptedException e) { } System.exit(0); }).start(); }", "return new Vector3d(0, 1, 0);"));
        CLASSES.put("Slow", material.formatted("Slow", "static volatile boolean slept;",
                "if (!slept) { slept = true; try { Thread.sleep(4000); } catch (InterruptedException e) { } } return new Vector3d();"));
        CLASSES.put("ErrTerms", material.formatted("ErrTerms", "@Override public Set<Term> terms() { throw new AssertionError(\"terms\"); }",
                "return new Vector3d();"));
        CLASSES.put("ErrInit", material.formatted("ErrInit", "@Override public void init() { throw new AssertionError(\"init\"); }",
                "return new Vector3d();"));
        CLASSES.put("Asrt", material.formatted("Asrt", "", "throw new AssertionError(\"shade not written\");"));
        CLASSES.put("BadMsg", material.formatted("BadMsg", "",
                "throw new RuntimeException() { @Override public String getMessage() { throw new IllegalStateException(); } };"));
        CLASSES.put("Recurse", material.formatted("Recurse", "", "return shade(ray, record, scene);"));
        CLASSES.put("NeedsBase", "public class NeedsBase extends Base { }");
        CLASSES.put("Base", material.formatted("Base", "", "return new Vector3d();"));
        CLASSES.put("NewJava", material.formatted("NewJava", "", "return new Vector3d();"));
        CLASSES.put("NullBox", """
                public class NullBox extends ray.surface.Surface {
                    @Override public boolean intersects(ray.Ray r, ray.IntersectionRecord h, ray.Scene s) { return false; }
                    @Override public ray.accel.Aabb bounds() { return null; }
                }
                """);
    }

    @BeforeAll
    static void install() throws Exception {
        String home = System.getProperty("ray.test.installHome");
        assumeTrue(home != null, "the build names the installed distribution (gradle test installs it first)");
        launcher = Path.of(home, "bin", "raytracer");
        assumeTrue(Files.isExecutable(launcher), "installed launcher at " + launcher);
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assumeTrue(javac != null, "a JDK with javac is needed");
        Path src = Files.createDirectories(work.resolve("student-src"));
        classes = Files.createDirectories(work.resolve("student-classes"));
        String jars;
        try (Stream<Path> lib = Files.list(Path.of(home, "lib"))) {
            jars = lib.filter(j -> j.toString().endsWith(".jar")).map(Path::toString).collect(Collectors.joining(File.pathSeparator));
        }
        List<String> args = new ArrayList<>(List.of("-d", classes.toString(), "-cp", jars));
        for (Map.Entry<String, String> c : CLASSES.entrySet()) {
            args.add(Files.writeString(src.resolve(c.getKey() + ".java"), c.getValue()).toString());
        }
        assertEquals(0, javac.run(null, null, null, args.toArray(new String[0])), "the student classes compile");
        Files.delete(classes.resolve("Base.class"));          // NeedsBase's superclass is missing
        Path newer = classes.resolve("NewJava.class");
        byte[] bytes = Files.readAllBytes(newer);
        bytes[6] = 0;
        bytes[7] = 99;                                         // class file version 99: a Java from the future
        Files.write(newer, bytes);
        testClasses = Stream.of(System.getProperty("java.class.path").split(File.pathSeparator))
                .filter(e -> Files.exists(Path.of(e, "SharedOperands.class"))).findFirst().orElseThrow();
        display = startXvfb();
    }

    /** A throw-away X server for the --view runs, or null (those runs are skipped) where Xvfb is missing. */
    private static String startXvfb() throws IOException {
        boolean found = Stream.of(System.getenv().getOrDefault("PATH", "").split(":")).anyMatch(d -> !d.isEmpty()
                && Files.isExecutable(Path.of(d, "Xvfb")));
        if (!found) {
            return null;
        }
        xvfb = new ProcessBuilder("Xvfb", "-displayfd", "1", "-screen", "0", "800x600x24", "-nolisten", "tcp")
                .redirectError(work.resolve("xvfb.log").toFile()).start();
        String n = new BufferedReader(new InputStreamReader(xvfb.getInputStream(), StandardCharsets.US_ASCII)).readLine();
        return n != null && n.trim().matches("\\d+") ? ":" + n.trim() : null;
    }

    @AfterAll
    static void stopXvfb() throws InterruptedException {
        if (xvfb != null) {
            xvfb.destroy();
            xvfb.waitFor(10, TimeUnit.SECONDS);
        }
    }

    /** What one run did. */
    record Result(Probe probe, Mode mode, int status, byte[] out, String err, List<String> problems, double seconds) {
    }

    @TestFactory
    List<DynamicTest> everyProbeInEveryMode() throws Exception {
        List<Object[]> runs = new ArrayList<>();
        for (Probe p : PROBES) {
            for (Map.Entry<Mode, Integer> m : p.status().entrySet()) {
                runs.add(new Object[] {p, m.getKey()});
            }
        }
        // two runs at a time: most of a run is a JVM starting
        ExecutorService pool = Executors.newFixedThreadPool(2);
        List<Future<Result>> results = new ArrayList<>();
        int i = 0;
        for (Object[] r : runs) {
            Path dir = work.resolve("run-" + i++);
            results.add(pool.submit(() -> run((Probe) r[0], (Mode) r[1], dir)));
        }
        pool.shutdown();
        List<DynamicTest> tests = new ArrayList<>();
        StringBuilder table = new StringBuilder("issue 17 probes against the installed raytracer:\n");
        for (Future<Result> f : results) {
            Result r = f.get();
            String name = r.probe().id() + " " + r.probe().what() + " [" + r.mode().name().toLowerCase().replace('_', ' ') + "]";
            String line = r.err().lines().filter(l -> !userLine(l)).findFirst().orElse("");
            table.append(String.format("  %-4s %-58s %-10s %4s %5.1f s  %s%n", r.probe().id(), r.probe().what(), r.mode(),
                    r.status() == OPEN ? "open" : Integer.toString(r.status()), r.seconds(),
                    Failures.oneLine(r.problems().isEmpty() ? line : "FAILS: " + String.join("; ", r.problems()))));
            tests.add(DynamicTest.dynamicTest(name, () -> {
                assumeTrue(!r.problems().contains("skipped"), "no Xvfb for the --view run");
                if (!r.problems().isEmpty()) {
                    fail(String.join("; ", r.problems()) + "\nstatus " + r.status() + "\nstderr:\n" + r.err());
                }
            }));
        }
        System.out.print(table);
        return tests;
    }

    /** A line a student's class printed (the probes' Printer), not the tool's. */
    private static boolean userLine(String l) {
        return l.equals("made") || l.equals("debug");
    }

    private static final Pattern NAMED = Pattern.compile("^(raytracer|[^ ]+?(:\\d+)?): .+");

    private Result run(Probe p, Mode mode, Path dir) throws Exception {
        List<String> problems = new ArrayList<>();
        if (mode == Mode.VIEW && display == null) {
            return new Result(p, mode, 0, new byte[0], "", List.of("skipped"), 0);
        }
        Files.createDirectories(dir);
        p.setup().in(dir);
        Map<String, String> before = snapshot(dir);
        List<String> cmd = new ArrayList<>();
        cmd.add(launcher.toString());
        cmd.addAll(mode.options);
        cmd.addAll(p.args());
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("RAYTRACER_OPTS");
        pb.environment().put("JAVA_HOME", System.getProperty("java.home"));
        pb.environment().put("CLASSPATH", classes + File.pathSeparator + testClasses);
        pb.environment().remove("DISPLAY");
        if (mode == Mode.VIEW) {
            pb.environment().put("DISPLAY", display);
            // The viewer keeps recent files in Preferences: a probe's own prefs root, never the user's, so
            // concurrent runs do not see each other's prefs file vanish ("Prefs file removed in background").
            pb.environment().put("JAVA_OPTS", "-Djava.util.prefs.userRoot=" + dir.resolveSibling(dir.getFileName() + ".prefs"));
        }
        p.env().forEach((k, v) -> {
            if (!k.equals(STDOUT_TO)) {
                pb.environment().put(k, v);
            }
        });
        Path errFile = dir.resolveSibling(dir.getFileName() + ".err"), outFile = dir.resolveSibling(dir.getFileName() + ".out");
        pb.redirectError(errFile.toFile()).redirectOutput(p.env().containsKey(STDOUT_TO) ? new File(p.env().get(STDOUT_TO)) : outFile.toFile());
        pb.redirectInput(p.stdin() == null ? ProcessBuilder.Redirect.from(new File("/dev/null")) : ProcessBuilder.Redirect.PIPE);
        long t0 = System.nanoTime();
        Process proc = pb.start();
        if (p.stdin() != null) {
            Thread feeder = new Thread(() -> {
                byte[] line = "Width 10\n".getBytes(StandardCharsets.US_ASCII);
                try (OutputStream o = proc.getOutputStream()) {
                    while (true) {
                        o.write(line);      // 'yes Width 10': until the process stops reading
                    }
                } catch (IOException e) {
                    // the process closed its end: it stopped reading, as it should
                }
            });
            feeder.setDaemon(true);
            feeder.start();
        }
        int status;
        if (mode == Mode.VIEW && p.status().get(mode) == OPEN) {
            // the window stays open on the failure: wait for its line on stderr, then for a moment more
            long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
            while (proc.isAlive() && System.nanoTime() < end && Files.readString(errFile).lines().noneMatch(l -> !userLine(l))) {
                Thread.sleep(100);
            }
            Thread.sleep(300);
            status = proc.isAlive() ? OPEN : proc.exitValue();
            proc.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        } else if (!proc.waitFor(60, TimeUnit.SECONDS)) {
            proc.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
            problems.add("still running after 60 s (a hang)");
            status = -2;
        } else {
            status = proc.exitValue();
        }
        double seconds = (System.nanoTime() - t0) / 1e9;
        String err = Files.readString(errFile, StandardCharsets.UTF_8);
        byte[] out = Files.exists(outFile) ? Files.readAllBytes(outFile) : new byte[0];
        int spec = p.status().get(mode), expected = spec == SAYS ? 0 : spec;
        if (status != expected && status != -2) {
            problems.add("status " + status + ", expected " + expected);
        }
        List<String> lines = err.lines().filter(l -> !userLine(l)).collect(Collectors.toList());
        if (lines.stream().anyMatch(l -> l.startsWith("\tat ") || l.contains("Exception in thread") || l.startsWith("Caused by"))) {
            problems.add("a stack trace on stderr");
        }
        if (err.indexOf('\u001b') >= 0 || new String(out, StandardCharsets.ISO_8859_1).contains("\u001b[31m")) {
            problems.add("a raw escape sequence reached the terminal");
        }
        boolean failed = expected != 0;
        if (failed) {
            if (lines.size() != 1) {
                problems.add(lines.size() + " lines on stderr, expected one");
            }
            if (lines.isEmpty() || !NAMED.matcher(lines.get(0)).matches()) {
                problems.add("the line does not start with a name");
            }
            if (lines.stream().noneMatch(l -> p.says().matcher(l).find())) {
                problems.add("no line says /" + p.says() + "/");
            }
        } else if (p.args().contains("-q") && !lines.isEmpty()) {
            problems.add("-q printed " + lines.size() + " lines");
        } else if ((spec == SAYS || !p.says().pattern().isEmpty() && p.status().values().stream().allMatch(v -> v == 0))
                && !p.says().matcher(err + new String(out, StandardCharsets.UTF_8)).find()) {   // a probe that succeeds says so
            problems.add("the output does not say /" + p.says() + "/");
        }
        checkStdout(mode, failed, out, problems);
        checkFiles(before, snapshot(dir), failed, p.creates(), problems);
        return new Result(p, mode, status, out, err, problems, seconds);
    }

    private static void checkStdout(Mode mode, boolean failed, byte[] out, List<String> problems) {
        String text = new String(out, StandardCharsets.UTF_8);
        if (mode == Mode.STDOUT) {
            boolean png = out.length > 8 && Arrays.equals(Arrays.copyOf(out, 8), new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'});
            if (failed ? out.length > 0 : !png) {
                problems.add(failed ? "standard output is not empty" : "standard output is not a PNG");
            }
        } else if (mode == Mode.PLAN_JSON || mode == Mode.STATS_JSON) {
            if (text.lines().anyMatch(l -> !(l.startsWith("{") && l.endsWith("}")))) {
                problems.add("standard output is not JSON Lines only: " + Failures.oneLine(text));
            }
        }
    }

    /**
     * Every file that was there is as it was (content, permissions, link target); a failed run creates
     * nothing but the study's report folder (and a scene's image rendered before the failure); no
     * temporary file is left anywhere.
     */
    private static void checkFiles(Map<String, String> before, Map<String, String> after, boolean failed, Pattern creates,
            List<String> problems) {
        for (Map.Entry<String, String> e : before.entrySet()) {
            String now = after.get(e.getKey());
            boolean output = e.getKey().equals("out.png") || e.getKey().startsWith("rep/") && !e.getValue().startsWith("link")
                    && !e.getKey().equals("rep/index.html");
            if (!e.getValue().equals(now) && !(output && !failed)) {
                problems.add(e.getKey() + " changed: " + e.getValue() + " -> " + now);
            }
        }
        for (String name : after.keySet()) {
            if (name.contains(".raytracer-") && name.endsWith(".tmp")) {
                problems.add("temporary file left: " + name);
            } else if (failed && !before.containsKey(name) && !creates.matcher(name).matches()) {
                problems.add("a failed run created " + name);
            }
        }
    }

    /** Each file under {@code dir}: its kind, permissions, and content hash or link target. */
    private static Map<String, String> snapshot(Path dir) throws IOException {
        Map<String, String> m = new TreeMap<>();
        try (Stream<Path> all = Files.walk(dir)) {
            for (Path f : (Iterable<Path>) all::iterator) {
                String key = dir.relativize(f).toString();
                if (Files.isSymbolicLink(f)) {
                    m.put(key, "link to " + Files.readSymbolicLink(f));
                } else if (Files.isRegularFile(f, LinkOption.NOFOLLOW_LINKS)) {
                    Set<PosixFilePermission> perms = Files.getPosixFilePermissions(f, LinkOption.NOFOLLOW_LINKS);
                    m.put(key, PosixFilePermissions.toString(perms) + " " + Arrays.hashCode(Files.readAllBytes(f)));
                } else if (!Files.isDirectory(f, LinkOption.NOFOLLOW_LINKS)) {
                    m.put(key, "special");
                }
            }
        }
        return m;
    }
}
