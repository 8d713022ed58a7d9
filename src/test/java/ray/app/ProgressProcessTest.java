package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.material.Material;

/**
 * Issue 10's terminal rules, on a real terminal: {@code script} (util-linux) runs {@code RayTracer}
 * on a pseudo-terminal. Progress goes to stderr when stderr is a terminal (even with stdout redirected),
 * never into a redirected stderr, never with --quiet; Ctrl+C leaves the line erased.
 */
@Tag("slow") // child JVMs; left out by gradle mutation -PmutationFast
class ProgressProcessTest {

    @TempDir
    Path dir;

    /** About 2 ms a pixel: a 40 x 40 image takes about 1.6 s of one core. */
    public static class Slow extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            try {
                Thread.sleep(2);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            return new Vector3d(0.5, 0.5, 0.5);
        }
    }

    /** A student's material that never returns (sleeping, so it does not burn the machine). */
    public static class Forever extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            while (true) {
                try {
                    Thread.sleep(50);
                } catch (InterruptedException e) {
                    return new Vector3d();
                }
            }
        }
    }

    private static final String SLOW_SCENE = "Width 40\nHeight 40\n\nCamera Camera\nVector3d eye [0 0 3]\nVector3d target [0 0 0]\n"
            + "double yFOV 90\n\nMaterial ray.app.ProgressProcessTest$Slow m\n\nSurface Sphere\nVector3d center [0 0 0]\n"
            + "double radius 10\nref material m\n";

    private static boolean haveScript() {
        try {
            return new ProcessBuilder("script", "--version").redirectErrorStream(true).start().waitFor() == 0;
        } catch (Exception e) {
            return false;
        }
    }

    private static String java(String args) {
        return Path.of(System.getProperty("java.home"), "bin", "java") + " -cp '" + System.getProperty("java.class.path")
                + "' -XX:TieredStopAtLevel=1 -Djava.awt.headless=true RayTracer " + args;
    }

    /** Runs {@code shellCommand} on a pseudo-terminal; returns what the terminal showed. */
    private String onTerminal(String shellCommand) throws Exception {
        Path typescript = dir.resolve("terminal.txt");
        Process p = new ProcessBuilder("script", "-qefc", shellCommand, typescript.toString()).directory(dir.toFile())
                .redirectInput(new File("/dev/null")).redirectOutput(dir.resolve("script.out").toFile()).redirectErrorStream(true).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "ended");
        return shown(typescript);
    }

    /** The typescript without the "Script started/done" lines script writes around it. */
    private static String shown(Path typescript) throws Exception {
        String t = Files.readString(typescript, StandardCharsets.UTF_8);
        if (t.startsWith("Script started")) {
            t = t.substring(t.indexOf('\n') + 1);
        }
        int done = t.lastIndexOf("\nScript done");
        return done >= 0 ? t.substring(0, done + 1) : t.startsWith("Script done") ? "" : t;
    }

    /** The distinct elapsed times the 0% bar showed. */
    private static java.util.Set<String> clockReadings(String shown) {
        java.util.Set<String> times = new java.util.TreeSet<>();
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("slow\\.txt   0% \\[>\\s+\\] ([0-9.]+) s").matcher(shown);
        while (m.find()) {
            times.add(m.group(1));
        }
        return times;
    }

    @Test
    void terminalShowsABarWithShareAndTimeLeftThenErasesIt() throws Exception {
        assumeTrue(haveScript(), "script (util-linux) is needed for a pseudo-terminal");
        Files.writeString(dir.resolve("slow.txt"), SLOW_SCENE);
        String shown = onTerminal(java("-j 1 slow.txt > out.log"));
        assertTrue(shown.contains("slow.txt ") && shown.contains("% [") && shown.contains("left"),
                "a progress bar on the terminal although stdout is redirected:\n" + shown);
        String afterLastReturn = shown.substring(shown.lastIndexOf('\r') + 1);
        assertFalse(afterLastReturn.contains("%"), "the line is erased at the end: " + afterLastReturn);
        String out = Files.readString(dir.resolve("out.log"));
        assertTrue(out.startsWith("slow.txt -> slow.png (40x40, 1x1 AA, ") && out.contains(" rays/s: 1,600 camera"), out);
        assertFalse(out.contains("%"), out);
    }

    @Test
    void redirectedStderrGetsNoProgressAndQuietGetsNothing() throws Exception {
        assumeTrue(haveScript(), "script (util-linux) is needed for a pseudo-terminal");
        Files.writeString(dir.resolve("slow.txt"), SLOW_SCENE);
        String shown = onTerminal(java("-j 1 slow.txt 2> err.log"));
        assertEquals("", Files.readString(dir.resolve("err.log")), "no carriage-return frames in a log");
        assertTrue(shown.contains("slow.txt -> slow.png"), shown);
        String quiet = onTerminal(java("-q -j 1 slow.txt"));
        assertEquals("", quiet.strip(), "--quiet prints nothing");
    }

    /**
     * A one-pixel image whose user material loops forever: the bar's clock keeps running (the render is
     * not silent although no tile ever finishes), and Ctrl+C erases the line and leaves no file.
     */
    @Test
    void aLoopingClassShowsTheClockAndCtrlCLeavesTheLineErased() throws Exception {
        assumeTrue(haveScript(), "script (util-linux) is needed for a pseudo-terminal");
        Files.writeString(dir.resolve("slow.txt"), SLOW_SCENE.replace("Width 40\nHeight 40", "Width 1\nHeight 1")
                .replace("ProgressProcessTest$Slow", "ProgressProcessTest$Forever"));
        Path typescript = dir.resolve("terminal.txt");
        Process p = new ProcessBuilder("script", "-qefc", java("-j 1 slow.txt"), typescript.toString()).directory(dir.toFile())
                .redirectInput(new File("/dev/null")).redirectOutput(dir.resolve("script.out").toFile()).redirectErrorStream(true).start();
        Optional<ProcessHandle> javaProcess = Optional.empty();
        for (int i = 0; i < 300 && (javaProcess.isEmpty() || clockReadings(Files.readString(typescript)).size() < 3); i++) {
            Thread.sleep(100);
            javaProcess = p.descendants().filter(h -> h.info().command().orElse("").endsWith("java")).findFirst();
        }
        assumeTrue(javaProcess.isPresent(), "the java process was not found under script");
        String before = Files.readString(typescript);
        assertTrue(clockReadings(before).size() >= 3, "the bar is redrawn as the clock runs, with no tile done: " + before);
        assertEquals(0, new ProcessBuilder("kill", "-INT", Long.toString(javaProcess.get().pid())).start().waitFor());
        assertTrue(p.waitFor(30, TimeUnit.SECONDS), "ended after Ctrl+C");
        String shown = shown(typescript);
        String afterLastReturn = shown.substring(shown.lastIndexOf('\r') + 1);
        assertFalse(afterLastReturn.contains("%"), "the line is erased after Ctrl+C: " + afterLastReturn);
        assertFalse(Files.exists(dir.resolve("slow.png")));
        try (var s = Files.list(dir)) {
            assertEquals(List.of(), s.map(x -> x.getFileName().toString()).filter(n -> n.endsWith(".tmp")).toList(), "no temporary file");
        }
    }
}
