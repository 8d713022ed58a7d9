package ray.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A real standalone Spark cluster on 127.0.0.1: a master and a worker started from the installed
 * distribution's own jars (spark/build/install/raytracer-spark/lib) as child JVMs, jobs submitted with
 * the distribution's launcher, images compared with raytracer's. One job has its executor killed
 * (kill -9) mid-render: the worker starts another, Spark reruns the lost tiles, and the images are still
 * raytracer's, with no partial file in the output folder. spark-submit (its main class, from the same jars)
 * runs a render in local[2] and grades three hand-ins on the cluster, in bubblewrap on the executors, with
 * raytracer grade's results.
 */
class SparkClusterTest {

    static final Path HOME = Path.of(System.getProperty("raytracer.spark.home", "build/install/raytracer-spark"));
    static final List<String> JVM_ARGS = Arrays.asList(System.getProperty("raytracer.spark.jvmArgs", "").split(" "));
    @TempDir
    static Path dir;
    static Process master, worker;
    static String url;

    /** The environment every cluster process gets: Spark's home (its jars: the distribution's), Scala 2.13, loopback only. */
    static void environment(ProcessBuilder pb) {
        pb.environment().put("SPARK_HOME", dir.resolve("spark-home").toString());
        pb.environment().put("SPARK_SCALA_VERSION", "2.13");
        pb.environment().put("SPARK_LOCAL_IP", "127.0.0.1");
        pb.environment().put("SPARK_LOCAL_HOSTNAME", "localhost");
        pb.environment().put("RAYTRACER_TEST_SLOW_MICROS", "1500");   // SlowDiffuse, in the executors only
    }

    static Process daemon(String name, String mainClass, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(JVM_ARGS);
        // Spark's INFO log for the master and worker (the distribution's own config keeps warnings only): the test waits for their lines
        cmd.add("-Dlog4j2.configurationFile=" + dir.resolve("log4j2-daemon.properties"));
        cmd.addAll(List.of("-Xmx256m", "-cp", HOME.resolve("lib") + File.separator + "*", mainClass));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(dir.resolve(name + ".log").toFile());
        environment(pb);
        return pb.start();
    }

    static void awaitLog(String name, String line, Process p) throws Exception {
        Path log = dir.resolve(name + ".log");
        for (long end = System.nanoTime() + 120_000_000_000L; System.nanoTime() < end; Thread.sleep(100)) {
            if (Files.exists(log) && Files.readString(log).contains(line)) {
                return;
            }
            assertTrue(p.isAlive(), name + " died: " + Files.readString(log));
        }
        throw new AssertionError(name + " did not say '" + line + "' in 120 s: " + Files.readString(log));
    }

    @BeforeAll
    static void startCluster() throws Exception {
        assertTrue(Files.isDirectory(HOME.resolve("lib")), "the distribution (gradle :spark:installDist) at " + HOME);
        Files.createDirectories(dir.resolve("spark-home"));
        Files.writeString(dir.resolve("log4j2-daemon.properties"), String.join("\n", "rootLogger.level = info",
                "rootLogger.appenderRef.out.ref = out", "appender.console.type = Console", "appender.console.name = out",
                "appender.console.layout.type = PatternLayout", "appender.console.layout.pattern = %p %c{1}: %m%n", ""));
        Files.createSymbolicLink(dir.resolve("spark-home/jars"), HOME.resolve("lib").toAbsolutePath());
        int port;
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            port = s.getLocalPort();
        }
        url = "spark://127.0.0.1:" + port;
        master = daemon("master", "org.apache.spark.deploy.master.Master", "--host", "127.0.0.1", "--port", Integer.toString(port),
                "--webui-port", "0");
        awaitLog("master", "I have been elected leader", master);
        worker = daemon("worker", "org.apache.spark.deploy.worker.Worker", "--host", "127.0.0.1", "--cores", "2", "--memory", "1g",
                "--webui-port", "0", "--work-dir", dir.resolve("work").toString(), url);
        awaitLog("worker", "Successfully registered with master", worker);
    }

    @AfterAll
    static void stopCluster() {
        for (Process p : new Process[] {worker, master}) {
            if (p != null) {
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            }
        }
    }

    /**
     * Starts a job on the cluster: with the distribution's launcher, or (with a user's class in the scenes)
     * its main class on the distribution's jars plus this test's classes, as spark-submit would run it.
     */
    static Process submit(boolean userClasses, Path out, Path log, Path... scenes) throws IOException {
        List<String> cmd = new ArrayList<>();
        if (userClasses) {
            cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
            cmd.addAll(JVM_ARGS);
            cmd.addAll(List.of("-cp", HOME.resolve("lib") + File.separator + "*" + File.pathSeparator + testClasses(), "ray.spark.SparkMain"));
        } else {
            cmd.add(HOME.resolve("bin/raytracer-spark").toString());
        }
        cmd.addAll(List.of("--master", url, "--allow-long", "--tile", "16", "--conf", "spark.ui.enabled=false",
                "--conf", "spark.executor.memory=512m", "--conf", "spark.executor.extraClassPath=" + testClasses(), "-o", out.toString()));
        for (Path s : scenes) {
            cmd.add(s.toString());
        }
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile());
        environment(pb);
        pb.environment().remove("RAYTRACER_TEST_SLOW_MICROS");   // the driver renders nothing; the executors inherit the worker's
        return pb.start();
    }

    /**
     * Starts {@code org.apache.spark.deploy.SparkSubmit}, the class the spark-submit script runs, from the
     * distribution's jars: raytracer-spark's jar as the application, the ray tracer's own jars in --jars,
     * the Spark options before the application's arguments (README "Scale out").
     */
    static Process sparkSubmit(Path log, String master, String... appArgs) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(JVM_ARGS);
        cmd.addAll(List.of("-cp", HOME.resolve("lib") + File.separator + "*", "org.apache.spark.deploy.SparkSubmit",
                "--master", master, "--class", "ray.spark.SparkMain", "--conf", "spark.ui.enabled=false",
                "--conf", "spark.executor.memory=512m", "--conf", "spark.driver.host=127.0.0.1",
                "--jars", String.join(",", jar("raytracer-\\d.*"), jar("vecmath-.*"), jar("picocli-.*"), jar("obj-.*")),
                jar("raytracer-spark-.*")));
        cmd.addAll(List.of(appArgs));
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile());
        environment(pb);
        pb.environment().remove("RAYTRACER_TEST_SLOW_MICROS");
        return pb.start();
    }

    /** The distribution's jar whose name matches {@code regex} (without .jar). */
    static String jar(String regex) throws IOException {
        List<String> found = files(HOME.resolve("lib")).stream().filter(n -> n.matches(regex + "\\.jar")).toList();
        assertEquals(1, found.size(), regex + " in " + HOME.resolve("lib"));
        return HOME.resolve("lib").resolve(found.get(0)).toAbsolutePath().toString();
    }

    /** Where this test's classes are (SlowDiffuse, for the executors). */
    static String testClasses() {
        return Path.of(SlowDiffuse.class.getProtectionDomain().getCodeSource().getLocation().getPath()).toString();
    }

    /** The job tests' scene at w x h, one sample a pixel; {@code slow}: its floor's material waits in the executors (SlowDiffuse). */
    static Path scene(String name, int width, int height, boolean slow) throws IOException {
        String text = SparkRenderTest.SCENE.replace("Width 40", "Width " + width).replace("Height 28", "Height " + height)
                .replace("AASamples 3", "AASamples 1");
        return Files.writeString(dir.resolve(name + ".txt"), slow ? text.replace("Material Diffuse matte", "Material ray.spark.SlowDiffuse matte") : text);
    }

    /** raytracer's own PNG of the scene. */
    static byte[] raytracer(Path scene) throws IOException {
        Path ref = dir.resolve("ref");
        Files.createDirectories(ref);
        assertEquals(0, ray.app.Main.run(new java.io.PrintStream(new java.io.ByteArrayOutputStream()), System.err, "-q", "--allow-long",
                "-o", ref + "/", scene.toString()));
        return Files.readAllBytes(ref.resolve(Output.pngName(scene)));
    }

    static List<ProcessHandle> executors() {
        return worker.descendants().filter(h -> h.info().commandLine().orElse("").contains("CoarseGrainedExecutorBackend")).toList();
    }

    static List<String> files(Path folder) throws IOException {
        try (Stream<Path> s = Files.list(folder)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void aJobOnTheClusterWritesRaytracersImages() throws Exception {
        Path a = scene("plain", 40, 28, false);
        Path out = dir.resolve("out-plain");
        Process job = submit(false, out, dir.resolve("plain.log"), a);
        assertEquals(0, job.waitFor(), Files.readString(dir.resolve("plain.log")));
        assertArrayEquals(raytracer(a), Files.readAllBytes(out.resolve("plain.png")));
        String log = Files.readString(dir.resolve("plain.log"));
        assertTrue(log.lines().anyMatch(l -> l.startsWith(a + " -> " + out.resolve("plain.png") + " (40x28, 1x1 AA, ")), "the summary line: " + log);
    }

    @Test
    void sparkSubmitRendersInLocalMode() throws Exception {
        Path a = scene("submitted", 24, 16, false);
        Path out = dir.resolve("out-submit-local");
        Process job = sparkSubmit(dir.resolve("submit-local.log"), "local[2]", "-o", out.toString(), a.toString());
        assertEquals(0, job.waitFor(), Files.readString(dir.resolve("submit-local.log")));
        assertArrayEquals(raytracer(a), Files.readAllBytes(out.resolve("submitted.png")));
    }

    @Test
    void sparkSubmitGradesOnTheClusterAsRaytracerGradeDoes() throws Exception {
        GradeFixture.prepare();
        Path out = dir.resolve("out-grade");
        List<String> args = new ArrayList<>(List.of("grade", "--tests", GradeFixture.tests.toString(), "-o", out.toString()));
        GradeFixture.handIns.forEach(p -> args.add(p.toString()));
        Process job = sparkSubmit(dir.resolve("grade.log"), url, args.toArray(new String[0]));
        assertEquals(0, job.waitFor(), Files.readString(dir.resolve("grade.log")));
        GradeFixture.assertSameReports(out);
        assertTrue(Files.readString(dir.resolve("grade.log")).contains("at a time; bubblewrap)"), "graded in bubblewrap on the executors");
    }

    @Test
    void anExecutorKilledMidRenderIsReplacedAndTheImagesAreStillRaytracers() throws Exception {
        Path small = scene("small", 16, 16, true), big = scene("big", 96, 64, true);
        Path out = dir.resolve("out-fault");
        Process job = submit(true, out, dir.resolve("fault.log"), small, big);
        // the small scene's tiles come first: once its PNG is there, the big one is being rendered
        Set<Long> seen = new HashSet<>();
        ProcessHandle killed = null;
        for (long end = System.nanoTime() + 180_000_000_000L; System.nanoTime() < end && job.isAlive() && killed == null; Thread.sleep(50)) {
            executors().forEach(h -> seen.add(h.pid()));
            if (Files.exists(out.resolve("small.png"))) {
                Optional<ProcessHandle> e = executors().stream().findFirst();
                assertTrue(e.isPresent(), "an executor runs the big scene");
                assertFalse(Files.exists(out.resolve("big.png")), "the big scene is still being rendered");
                killed = e.get();
                killed.destroyForcibly();   // SIGKILL: the executor dies without a word to the driver
            }
        }
        assertNotNull(killed, "the small scene came out before the job ended: " + Files.readString(dir.resolve("fault.log")));
        assertEquals(0, job.waitFor(), Files.readString(dir.resolve("fault.log")));
        executors().forEach(h -> seen.add(h.pid()));
        assertArrayEquals(raytracer(small), Files.readAllBytes(out.resolve("small.png")));
        assertArrayEquals(raytracer(big), Files.readAllBytes(out.resolve("big.png")));
        assertEquals(List.of("big.png", "small.png"), files(out), "only whole images in the output folder");
        assertTrue(mostExecutorsOfOneApplication() >= 2, "the worker started a second executor after the kill");
    }

    /** The most executor folders (work/app-ID/N) the worker made for one application. */
    static long mostExecutorsOfOneApplication() throws IOException {
        long most = 0;
        for (String app : files(dir.resolve("work"))) {
            most = Math.max(most, files(dir.resolve("work").resolve(app)).stream().filter(n -> n.matches("\\d+")).count());
        }
        return most;
    }
}
