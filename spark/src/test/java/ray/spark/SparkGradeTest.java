package ray.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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

/**
 * {@code raytracer-spark grade} in local[2]: three hand-ins (GradeFixture), one task each, graded in
 * sandboxed child JVMs on the executors: the same grades.csv, pictures and reports as {@code raytracer
 * grade}; usage mistakes refused in one line before Spark starts.
 */
class SparkGradeTest {

    @TempDir
    Path dir;

    record Run(int status, String out, String err) {
    }

    static Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = SparkMain.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    @Test
    void gradesAsRaytracerGradeDoes() throws Exception {
        GradeFixture.prepare();
        Path out = dir.resolve("spark");
        List<String> args = new ArrayList<>(List.of("grade", "--master", "local[2]", "--conf", "spark.ui.enabled=false",
                "--conf", "spark.driver.host=127.0.0.1", "--conf", "spark.driver.bindAddress=127.0.0.1",
                "--tests", GradeFixture.tests.toString(), "-o", out.toString()));
        GradeFixture.handIns.forEach(p -> args.add(p.toString()));
        Run r = run(args.toArray(new String[0]));
        assertEquals(0, r.status(), r.err() + r.out());
        GradeFixture.assertSameReports(out);
        String csv = Files.readString(out.resolve("grades.csv"));
        assertTrue(csv.contains("\nsolved,") && csv.contains("\ninverse-r,") && csv.contains("\nstub,"), csv);
        for (String name : List.of("solved", "inverse-r", "stub")) {
            assertTrue(r.out().lines().anyMatch(l -> l.startsWith(name + ": ")), "a score line for " + name + ": " + r.out());
        }
        assertTrue(r.out().contains(" graded in ") && r.out().contains("2 at a time; bubblewrap"), r.out());
    }

    @Test
    void usageMistakesAreOneLineBeforeSparkStarts() throws Exception {
        Run r = run("grade");
        assertEquals(2, r.status());
        assertEquals("raytracer-spark grade: give -o DIR and submissions (see raytracer-spark grade --help)", r.err().strip());
        r = run("grade", "--sandbox", "sometimes", "-o", dir.resolve("o").toString(), "x.zip");
        assertEquals(2, r.status());
        assertEquals("raytracer-spark grade: --sandbox sometimes: expected auto, bwrap or none", r.err().strip());
        r = run("grade", "--tests", dir.toString(), "-o", dir.resolve("o").toString(), "x.zip");
        assertEquals(2, r.status());
        assertTrue(r.err().startsWith("raytracer-spark grade: ") && r.err().contains("no rubric.txt") && r.err().strip().lines().count() == 1,
                r.err());
        assertFalse(Files.exists(dir.resolve("o")), "nothing written on a usage mistake");
        r = run("grade", "--jobs", "2", "-o", dir.resolve("o").toString(), "x.zip");
        assertEquals(2, r.status());
        assertEquals("raytracer-spark grade: Unknown option: '--jobs' (see raytracer-spark grade --help)", r.err().strip());
        r = run("grade", "--help");
        assertEquals(0, r.status());
        assertTrue(r.out().contains("--master") && r.out().contains("--sandbox") && r.out().contains("grades.csv"), r.out());
    }
}
