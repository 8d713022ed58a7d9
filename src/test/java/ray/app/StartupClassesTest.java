package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A plain render through the installed launcher spins no lambda: the first lambda a process calls loads
 * the method-handle machinery and its class spinner (about 90 classes, a tenth of what a render loads;
 * docs/performance.md, "Start-up"), which every short render would pay. The scene has meshes (an OBJ
 * file read), CSG, every built-in material kind and point lights, so the parser, the plan, the per-class
 * override checks (ray.Overrides), the render and its summary line all run. Nor does it load picocli.
 */
@Tag("slow")
class StartupClassesTest {

    @TempDir
    Path dir;

    @Test
    void aPlainRenderLoadsNoLambdaClass() throws Exception {
        String home = System.getProperty("ray.test.installHome");
        assumeTrue(home != null && !System.getProperty("os.name").toLowerCase().contains("windows"),
                "the build names the installed distribution (gradle test installs it first)");
        Path scenes = Path.of("scenes").toAbsolutePath();
        Path log = dir.resolve("classes.log");
        // not -q: the summary line is part of a plain render (its file names once went through a regex,
        // whose character class is a lambda)
        ProcessBuilder pb = new ProcessBuilder(Path.of(home, "bin", "raytracer").toString(),
                "-o", dir.resolve("mesh.png").toString(), scenes.resolve("mesh.txt").toString());
        pb.environment().remove("RAYTRACER_OPTS");
        pb.environment().put("JAVA_OPTS", "-Xlog:class+load:file=" + log);
        pb.environment().put("JAVA_HOME", System.getProperty("java.home"));
        pb.redirectInput(ProcessBuilder.Redirect.from(new File("/dev/null")));
        pb.redirectErrorStream(true);
        Process p = pb.start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the render ended");
        assertEquals(0, p.exitValue(), out);
        List<String> classes = Files.readAllLines(log, StandardCharsets.UTF_8);
        assertTrue(classes.size() > 300, "the class-load log lists the render's classes: " + classes.size());
        List<String> spun = classes.stream()
                .filter(l -> l.contains("$$Lambda") || l.contains("jdk.internal.org.objectweb.asm."))
                .collect(Collectors.toList());
        assertEquals(List.of(), spun, "classes of lambdas (or their spinner) loaded by a plain render");
        // the everyday command line is read without picocli, so nothing of it loads: its classes are Java 5
        // class files, which the class-data-sharing archive cannot hold (read and verified at every start)
        List<String> picocli = classes.stream().filter(l -> l.contains("picocli")).collect(Collectors.toList());
        assertEquals(List.of(), picocli, "picocli's classes loaded by a plain render");
    }
}
