package ray.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The study end to end on a tiny scene: its CSV, its report, and errors that shrink as n_s grows. */
class StudyTest {

    static final String TINY = """
            Width 24
            Height 16
            BGColor [0.05 0.05 0.1]
            AmbientLight [0.2 0.2 0.2]
            MaxDepth 2

            Camera Camera
            Vector3d eye [0 0 4]
            Vector3d target [0 0 0]
            Vector3d up [0 1 0]
            double yFOV 40

            Material Diffuse white
            Vector3d ambientColor [0.3 0.3 0.3]
            Vector3d diffuseColor [0.9 0.9 0.9]

            Material Glazed mirror
            ref base white
            double mirrorCoefficient 0.7

            Light PointLight
            Vector3d position [3 4 5]
            Vector3d intensity [30 30 30]

            Surface Sphere
            Vector3d center [-0.4 0 0]
            double radius 0.8
            ref material white

            Surface Sphere
            Vector3d center [0.7 0.2 -0.5]
            double radius 0.5
            ref material mirror
            """;

    @Test
    void csvHasTheColumnsAndGridErrorShrinksWithTheSetting(@TempDir Path dir) throws Exception {
        Path scene = dir.resolve("tiny.txt");
        Files.writeString(scene, TINY);
        Path report = dir.resolve("report");
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        StudySettings small = new StudySettings(4, new double[] {2, 1}, 8, 16, 2);
        int status = new Study(new RendererAdapter(2), small, 3, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), false).run(List.of(scene), report, "test");
        assertEquals(0, status, err.toString(StandardCharsets.UTF_8));

        List<String> lines = Files.readAllLines(report.resolve("tiny.csv"));
        assertTrue(lines.get(0).startsWith("sampler,setting,spp,seconds_median,seconds_min,seconds_max,rays,rmse,psnr_db,"
                + "max_error,share_off_by_more_than_one"), lines.get(0));
        List<Double> gridRmse = new ArrayList<>();
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",");
            double min = Double.parseDouble(f[4]), median = Double.parseDouble(f[3]), max = Double.parseDouble(f[5]);
            assertTrue(min <= median && median <= max, line);
            assertTrue(Long.parseLong(f[6]) > 0, line);
            if (f[0].equals("grid") && f[1].startsWith("n_s=")) {
                gridRmse.add(Double.parseDouble(f[7]));
            }
        }
        assertEquals(4, gridRmse.size(), lines.toString());
        // n_s = 1, 2, 4 against a 16 x 16 reference: each doubling of n_s must cut the error
        assertTrue(gridRmse.get(1) < gridRmse.get(0) && gridRmse.get(3) < gridRmse.get(1), gridRmse.toString());
        assertTrue(gridRmse.get(0) > 0, "a 1-sample render of edges cannot match the reference");
        // the mirror sphere makes the study try MaxDepth 0 and 1 as well
        assertTrue(lines.stream().anyMatch(l -> l.contains("MaxDepth=0")), lines.toString());
        for (String f : new String[] {"index.html", "tiny-error-vs-time.png", "tiny-crops.png"}) {
            assertTrue(Files.size(report.resolve(f)) > 0, f);
        }
        String html = Files.readString(report.resolve("index.html"));
        assertTrue(html.contains("To reach PSNR 40 dB"), html);
    }

    @Test
    void anUnreadableSceneIsReportedOnOneLineAndTheOthersStillRun(@TempDir Path dir) throws Exception {
        Path good = dir.resolve("tiny.txt"), bad = dir.resolve("bad.txt");
        Files.writeString(good, TINY);
        Files.writeString(bad, "Width -3\n");
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        StudySettings small = new StudySettings(2, new double[] {2}, 4, 4, 1);
        int status = new Study(new RendererAdapter(1), small, 1, new PrintStream(out, true, StandardCharsets.UTF_8),
                new PrintStream(err, true, StandardCharsets.UTF_8), false).run(List.of(bad, good), dir.resolve("r"), "test");
        assertEquals(1, status);
        String e = err.toString(StandardCharsets.UTF_8).trim();
        assertTrue(e.startsWith(bad.toString() + ":") && !e.contains("\n"), e);
        assertTrue(Files.exists(dir.resolve("r").resolve("tiny.csv")));
    }
}
