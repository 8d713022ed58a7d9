package ray.spark;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.stream.Stream;
import org.apache.spark.SparkConf;
import ray.settings.RenderSettings;
import org.apache.spark.api.java.JavaSparkContext;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerJobStart;
import org.apache.spark.scheduler.SparkListenerTaskEnd;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * The render job on an embedded Spark (local[2], retries allowed as on a cluster: local[2,4]), one context
 * for the class, UI off: its PNGs are the files {@code raytracer} writes, byte for byte, for every
 * sampler, tile size and thread count; a bad scene fails alone before any task; a user's class that
 * throws fails its scene once, with its message, and no task is retried.
 */
class SparkRenderTest {

    /** Edges, a mirror, a soft shadow (area light), a hard one (point light): every sampler has work. */
    static final String SCENE = """
            Width 40
            Height 28
            AASamples 3
            MaxDepth 3
            BGColor [0.1 0.2 0.3]
            AmbientLight [0.2 0.2 0.2]

            Camera Camera
            Vector3d eye [0 1.5 6]
            double yFOV 50

            Material BlinnPhong shiny
            Vector3d diffuseColor [0.6 0.3 0.2]
            Vector3d specularColor [0.8 0.8 0.8]
            double exponent 40

            Material Diffuse matte
            Vector3d diffuseColor [0.3 0.6 0.3]

            Material Glazed chrome
            ref base matte
            double mirrorCoefficient 0.7

            Surface Sphere
            Vector3d center [-1.2 0 0]
            ref material shiny

            Surface Sphere
            Vector3d center [1.2 0 -0.5]
            ref material chrome

            Surface Triangle
            Vector3d v0 [-20 -1 -20]
            Vector3d v1 [-20 -1 20]
            Vector3d v2 [20 -1 20]
            ref material matte

            Surface Triangle
            Vector3d v0 [-20 -1 -20]
            Vector3d v1 [20 -1 20]
            Vector3d v2 [20 -1 -20]
            ref material matte

            Light PointLight
            Vector3d position [4 5 3]
            Vector3d intensity [0.6 0.6 0.6]

            Light AreaLight
            Vector3d position [-2 4 1]
            Vector3d intensity [0.5 0.5 0.5]
            int samples 2
            """;

    static JavaSparkContext jsc;
    static final AtomicInteger JOBS = new AtomicInteger(), FAILED_TASKS = new AtomicInteger();

    @BeforeAll
    static void start() {
        jsc = new JavaSparkContext(new SparkConf().setMaster("local[2,4]").setAppName("SparkRenderTest")
                .set("spark.ui.enabled", "false").set("spark.driver.host", "127.0.0.1").set("spark.driver.bindAddress", "127.0.0.1"));
        jsc.sc().addSparkListener(new SparkListener() {
            @Override
            public void onJobStart(SparkListenerJobStart e) {
                JOBS.incrementAndGet();
            }

            @Override
            public void onTaskEnd(SparkListenerTaskEnd e) {
                if (!e.taskInfo().successful()) {
                    FAILED_TASKS.incrementAndGet();
                }
            }
        });
    }

    @AfterAll
    static void stop() {
        if (jsc != null) {
            jsc.close();
        }
    }

    /** stdout and stderr of one run, and its status. */
    record Run(int status, String out, String err) {
    }

    static Run render(List<Path> scenes, RenderJob.Options o) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status;
        try (PrintStream po = new PrintStream(out, true, StandardCharsets.UTF_8); PrintStream pe = new PrintStream(err, true, StandardCharsets.UTF_8)) {
            status = new RenderJob(jsc, o, po, pe, false).run(scenes);
        }
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    static RenderJob.Options options(Path dir, int tile, int threads, String sampler) {
        return new RenderJob.Options(dir == null ? null : dir.toString(), tile, threads,
                new SceneBundle.Overrides(sampler.equals("adaptive") ? new RenderSettings().sampler(sampler).targetError(1)
                        : new RenderSettings().sampler(sampler), 0), false, false, false, false);
    }

    /** The PNG raytracer itself writes for {@code scene} (into {@code dir}). */
    static byte[] raytracer(Path scene, Path dir, int threads, String sampler) throws IOException {
        Files.createDirectories(dir);
        List<String> args = new ArrayList<>(List.of("-q", "-j", Integer.toString(threads), "--sampler", sampler, "-o", dir + "/"));
        if (sampler.equals("adaptive")) {
            args.addAll(List.of("--target-error", "1"));
        }
        args.add(scene.toString());
        assertEquals(0, ray.app.Main.run(new PrintStream(new ByteArrayOutputStream()), System.err, args.toArray(new String[0])));
        return Files.readAllBytes(dir.resolve(Output.pngName(scene)));
    }

    @ParameterizedTest(name = "{0}, tiles of {1}, {2} thread(s)")
    @CsvSource({"grid, 7, 1", "jittered, 64, 2", "sobol, 9, 1", "adaptive, 7, 2", "adaptive, 64, 1"})
    void imagesAreRaytracersByteForByte(String sampler, int tile, int threads, @TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("scene.txt"), SCENE);
        byte[] expected = raytracer(scene, dir.resolve("ref"), 2, sampler);
        Run r = render(List.of(scene), options(dir.resolve("out"), tile, threads, sampler));
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(expected, Files.readAllBytes(dir.resolve("out/scene.png")), sampler + ": not raytracer's PNG");
        assertTrue(r.out().startsWith(scene + " -> " + dir.resolve("out/scene.png") + " (40x28, 3x3 AA, "), r.out());
        if (!sampler.equals("grid")) {
            assertTrue(r.out().contains("\n  " + sampler + ": "), "the sampler's line: " + r.out());
        }
        try (Stream<Path> files = Files.list(dir.resolve("out"))) {
            assertEquals(List.of("scene.png"), files.map(p -> p.getFileName().toString()).toList(), "no temporary file left");
        }
    }

    @Test
    void manyScenesAreOneJobAndABadOneFailsAloneBeforeAnyTask(@TempDir Path dir) throws IOException {
        String fresh = "# " + System.nanoTime() + "\n";   // content not cached by an earlier test in this JVM
        Path a = Files.writeString(dir.resolve("a.txt"), fresh + SCENE);
        Path bad = Files.writeString(dir.resolve("bad.txt"), SCENE.replace("double yFOV 50", "double yFOV fifty"));
        Path b = Files.writeString(dir.resolve("b.txt"), fresh + SCENE.replace("Width 40", "Width 30"));
        int jobs = JOBS.get(), parses = SceneBundle.PARSES.get();
        Run r = render(List.of(a, bad, b), options(null, 16, 1, "grid"));
        assertEquals(1, r.status());
        assertEquals(1, JOBS.get() - jobs, "all scenes' tiles in one job");
        assertEquals(2, SceneBundle.PARSES.get() - parses, "each scene parsed once in this JVM, not once per task");
        String[] errLines = r.err().strip().split("\n");
        assertEquals(1, errLines.length, r.err());
        assertTrue(errLines[0].startsWith(bad + ":10: "), "file:line: message, got " + errLines[0]);
        assertFalse(Files.exists(dir.resolve("bad.png")));
        assertArrayEquals(raytracer(a, dir.resolve("ref"), 1, "grid"), Files.readAllBytes(dir.resolve("a.png")));
        assertArrayEquals(raytracer(b, dir.resolve("ref"), 1, "grid"), Files.readAllBytes(dir.resolve("b.png")));

        jobs = JOBS.get();
        assertEquals(1, render(List.of(bad), options(null, 16, 1, "grid")).status());
        assertEquals(jobs, JOBS.get(), "no job for scenes that all fail to read");
    }

    @Test
    void aUsersClassThatThrowsFailsItsSceneOnceWithoutRetries(@TempDir Path dir) throws IOException {
        Path broken = Files.writeString(dir.resolve("broken.txt"), SCENE.replace("Material Diffuse matte", "Material ray.spark.BrokenMaterial matte")
                .replace("Vector3d diffuseColor [0.3 0.6 0.3]\n", ""));
        Path good = Files.writeString(dir.resolve("good.txt"), SCENE);
        int failedTasks = FAILED_TASKS.get();
        Run r = render(List.of(broken, good), options(null, 8, 1, "grid"));
        assertEquals(1, r.status());
        assertEquals(failedTasks, FAILED_TASKS.get(), "no task failed (and so none was retried)");
        String[] errLines = r.err().strip().split("\n");
        assertEquals(1, errLines.length, r.err());
        ByteArrayOutputStream raytracerErr = new ByteArrayOutputStream();
        Files.createDirectories(dir.resolve("ref"));
        assertEquals(1, ray.app.Main.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(raytracerErr, true, StandardCharsets.UTF_8),
                "-o", dir.resolve("ref") + "/", broken.toString()));
        assertEquals(raytracerErr.toString(StandardCharsets.UTF_8).strip(), errLines[0], "raytracer's own line");
        assertFalse(Files.exists(dir.resolve("broken.png")));
        assertTrue(Files.exists(dir.resolve("good.png")));
        assertTrue(errLines[0].startsWith(broken + ": rendering failed: student code not finished at ray.spark.BrokenMaterial.shade"), errLines[0]);
    }

    @Test
    void statsJsonHasRaytracersKeysAndAHadoopPathTakesTheImage(@TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("scene.txt"), SCENE);
        RenderJob.Options o = new RenderJob.Options("file:" + dir.resolve("hadoop"), 64, 1, SceneBundle.Overrides.NONE, false, true, true, false);
        Run r = render(List.of(scene), o);
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(raytracer(scene, dir.resolve("ref"), 1, "grid"), Files.readAllBytes(dir.resolve("hadoop/scene.png")));
        String json = r.out().strip();
        for (String key : List.of("\"scene\":", "\"output\":", "\"width\":40", "\"height\":28", "\"samplesPerPixel\":9", "\"seconds\":{\"parse\":",
                "\"build\":", "\"render\":", "\"write\":", "\"total\":", "\"cpuSeconds\":", "\"peakRssBytes\":", "\"bvhBytesPerPrimitive\":",
                "\"rays\":{\"camera\":10080,", "\"invalidSamples\":0")) {
            assertTrue(json.contains(key), key + " in " + json);
        }
        try (Stream<Path> files = Files.list(dir.resolve("hadoop"))) {
            assertTrue(files.allMatch(p -> p.getFileName().toString().matches("scene\\.png|\\.scene\\.png\\.crc")), "only the image (and Hadoop's checksum)");
        }
    }

    @Test
    void theStudysRendersAsTasksGiveRaytracersReportButTheTimes(@TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("tiny.txt"), SCENE.replace("Width 40", "Width 16").replace("Height 28", "Height 12"));
        ByteArrayOutputStream ignored = new ByteArrayOutputStream();
        assertEquals(0, ray.app.Main.run(new PrintStream(ignored), System.err, "--study", "--quick", "--report-dir",
                dir.resolve("local").toString(), scene.toString()));
        int jobs = JOBS.get();
        // the file, and the same scene from standard input; the reference renders in tiles of 5 x 5
        assertEquals(0, StudyJob.run(jsc, List.of(scene, Path.of("-")), true, false, dir.resolve("spark"), 1, 5, Files.readAllBytes(scene),
                new PrintStream(ignored), System.err, false));
        assertTrue(JOBS.get() - jobs >= 6, "the renders ran as Spark jobs");
        assertEquals(withoutTimes(dir.resolve("local/tiny.csv")), withoutTimes(dir.resolve("spark/tiny.csv")),
                "the same settings, errors, estimates and rays; only the times differ");
        assertEquals(withoutTimes(dir.resolve("local/tiny.csv")), withoutTimes(dir.resolve("spark/stdin.csv")), "the scene read from stdin");
        for (String f : List.of("index.html", "tiny-error-vs-time.png", "tiny-crops.png", "adaptive-honesty.png")) {
            assertTrue(Files.size(dir.resolve("spark").resolve(f)) > 0, f);
        }
        assertTrue(Files.readString(dir.resolve("spark/index.html")).contains("different machines"), "the report says where the times come from");
        // each render's CPU time was measured inside its task (the render threads' clocks), for every setting
        List<String> csv = Files.readAllLines(dir.resolve("spark/tiny.csv"));
        int cpu = List.of(csv.get(0).split(",")).indexOf("cpu_seconds_median");
        for (String line : csv.subList(1, csv.size())) {
            assertTrue(Double.parseDouble(line.split(",", -1)[cpu]) > 0, line);
        }
    }

    @Test
    void standardInputIsReadByTheStudyOnly() {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        assertEquals(2, SparkMain.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8), "-"));
        assertEquals("raytracer-spark: a scene from standard input ('-') is read by --study only; to render it, give its file "
                + "(the PNG is named after it)", err.toString(StandardCharsets.UTF_8).strip());
        err.reset();
        assertEquals(2, SparkMain.run(new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8),
                "--study", "-", "-"));
        assertEquals("raytracer-spark: standard input ('-') can be read only once", err.toString(StandardCharsets.UTF_8).strip());
    }

    /** A study CSV without its time columns (any whose header names seconds or a speed, and the repeats, which follow the times). */
    static List<String> withoutTimes(Path csv) throws IOException {
        List<String> lines = Files.readAllLines(csv);
        String[] header = lines.get(0).split(",");
        List<String> out = new ArrayList<>();
        for (String line : lines) {
            String[] f = line.split(",", -1);
            StringBuilder b = new StringBuilder();
            for (int i = 0; i < header.length; i++) {
                if (!header[i].contains("second") && !header[i].contains("time") && !header[i].contains("speed")
                        && !header[i].equals("repeats")) {   // how many renders were timed follows the times' spread
                    b.append(f[i]).append(',');
                }
            }
            out.add(b.toString());
        }
        return out;
    }
}
