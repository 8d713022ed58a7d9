package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A student's own class reaches the installed launcher: compiled into a folder of its own (as a student
 * does with javac), it is found by the scene parser through {@code --class-path DIR}, {@code -cp DIR}
 * (anywhere among the arguments) or {@code CLASSPATH}, and not without them; the other arguments keep
 * their order and {@code --} still protects a scene named like the option.
 */
@Tag("slow")
class LauncherClassPathTest {

    @TempDir
    Path dir;

    static final String SCENE = "Width 4\nHeight 3\nCamera Camera\nVector3d eye [0 0 5]\n"
            + "Material StudentRed d\n"
            + "Surface Sphere\ndouble radius 1\nref material d\n"
            + "Light PointLight\nVector3d position [3 3 3]\n";

    private record Run(int status, String out, String err) {
    }

    private Run run(Map<String, String> env, String... args) throws Exception {
        String home = System.getProperty("ray.test.installHome");
        assumeTrue(home != null && !System.getProperty("os.name").toLowerCase().contains("windows"),
                "the build names the installed distribution (gradle test installs it first)");
        List<String> cmd = new ArrayList<>(List.of(Path.of(home, "bin", "raytracer").toString()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(dir.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("RAYTRACER_OPTS");
        pb.environment().remove("CLASSPATH");
        pb.environment().put("JAVA_HOME", System.getProperty("java.home"));
        pb.environment().putAll(env);
        pb.redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        Path err = dir.resolve("stderr.log");
        pb.redirectError(err.toFile());
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the launcher ended");
        return new Run(p.exitValue(), out, Files.readString(err));
    }

    @Test
    void aStudentsClassesAreFoundThroughTheOptionOrClasspath() throws Exception {
        Path classes = Files.createDirectories(dir.resolve("my classes"));
        Path src = Files.writeString(dir.resolve("StudentRed.java"),
                "public class StudentRed extends ray.material.Diffuse {\n"
                + "    public StudentRed() { diffuseColor.set(0.9, 0.1, 0.1); }\n}\n");
        var javac = ToolProvider.getSystemJavaCompiler();
        assumeTrue(javac != null, "a JDK compiler");
        assertEquals(0, javac.run(null, null, null, "-d", classes.toString(), "-cp", System.getProperty("java.class.path"), src.toString()));
        Files.writeString(dir.resolve("s.txt"), SCENE);

        Run without = run(Map.of(), "-q", "s.txt");
        assertEquals(1, without.status, "without the class path the class is unknown: " + without.err);
        assertTrue(without.err.contains("StudentRed"), without.err);

        Run option = run(Map.of(), "-q", "--class-path", classes.toString(), "s.txt");
        assertEquals(0, option.status, option.err);
        assertTrue(Files.size(dir.resolve("s.png")) > 0);
        Files.delete(dir.resolve("s.png"));

        Run late = run(Map.of(), "s.txt", "-cp", "my classes", "-q");      // after the scene, relative, with a space
        assertEquals(0, late.status, late.err);
        assertEquals("", late.err, "-q still reached the renderer");
        Files.delete(dir.resolve("s.png"));

        Run env = run(Map.of("CLASSPATH", classes.toString()), "-q", "s.txt");
        assertEquals(0, env.status, env.err);
        assertTrue(Files.exists(dir.resolve("s.png")));

        Run missing = run(Map.of(), "s.txt", "--class-path");
        assertEquals(2, missing.status);
        assertTrue(missing.err.startsWith("raytracer: --class-path needs a class path"), missing.err);

        // after --, "-cp" is a scene's name like any other
        Run dashes = run(Map.of(), "-q", "--", "-cp");
        assertEquals(1, dashes.status);
        assertTrue(dashes.err.contains("-cp"), dashes.err);
    }

    @Test
    void startedWithoutTheLauncherTheOptionSaysWhatToDo() {
        var err = new java.io.ByteArrayOutputStream();
        int status = Main.run(new java.io.PrintStream(new java.io.ByteArrayOutputStream()), new java.io.PrintStream(err),
                "--class-path", "classes", "s.txt");
        assertEquals(2, status);
        assertTrue(err.toString().startsWith("raytracer: --class-path is read by the raytracer launcher"), err.toString());
        assertTrue(err.toString().contains("java -cp \"classes" + File.pathSeparator), err.toString());
    }
}
