package ray.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.app.Main;

/** The command line of `raytracer grade`: usage mistakes get one line and status 2, before any child JVM starts. */
class GradeCommandTest {

    @TempDir
    Path dir;

    String[] run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new String[] {Integer.toString(status), out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8)};
    }

    @Test
    void usageMistakes() throws Exception {
        String[] r = run("grade");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("give -o DIR and submissions, or --gradescope ROOT alone"), r[2]);
        r = run("grade", "--gradescope", dir.toString(), "-o", dir.toString());
        assertEquals("2", r[0], r[2]);
        r = run("grade", "-o", dir.resolve("out").toString(), "--tests", dir.toString(), "x.zip");
        assertEquals("2", r[0]);
        assertTrue(r[2].startsWith("raytracer grade: ") && r[2].contains("no rubric.txt"), r[2]);
        assertEquals(1, r[2].trim().split("\n").length, "one line: " + r[2]);
        r = run("grade", "--jobs", "0", "-o", "x", "y");
        assertEquals("2", r[0]);
        r = run("grade", "--sandbox", "sometimes", "-o", dir.resolve("o").toString(), "--tests", rubric().toString(), "y");
        assertEquals("2", r[0]);
        assertTrue(r[2].contains("--sandbox sometimes: expected auto, bwrap or none"), r[2]);
        assertTrue(!Files.exists(dir.resolve("o")), "nothing written on a usage mistake");
    }

    @Test
    void helpNamesTheOutputs() {
        String[] r = run("grade", "--help");
        assertEquals("0", r[0]);
        assertTrue(r[1].contains("grades.csv") && r[1].contains("--gradescope") && r[1].contains("--tests"), r[1]);
    }

    Path rubric() throws Exception {
        Path t = Files.createDirectories(dir.resolve("t"));
        for (String d : new String[] {"fw", "checks", "scenes", "refs"}) {
            Files.createDirectories(t.resolve(d));
        }
        Files.writeString(t.resolve("rubric.txt"), "framework fw\nchecks checks\nscenes scenes\nreferences refs\ngroup G\ncheck 1 C.m T\n");
        return t;
    }
}
