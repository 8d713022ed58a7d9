package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The picocli-free reading of everyday command lines must agree with picocli where it answers, and
 * hand everything else (help, errors, unusual forms) to picocli.
 */
class SimpleCommandLineTest {

    @Test
    void everydayCommandLinesAreReadDirectly() {
        Main m = Main.simpleCommandLine(new String[] {"a.txt", "-o", "out.png", "-j", "3", "--stats", "-q"});
        assertNotNull(m);
        assertEquals(List.of(Path.of("a.txt")), m.scenes);
        assertEquals(Path.of("out.png"), m.output);
        assertEquals(3, m.threads);
        assertEquals(true, m.stats);
        assertEquals(true, m.quiet);
        Main two = Main.simpleCommandLine(new String[] {"--threads", "1", "a.txt", "b.txt"});
        assertEquals(List.of(Path.of("a.txt"), Path.of("b.txt")), two.scenes);
        assertEquals(1, two.threads);
        Main at = Main.simpleCommandLine(new String[] {"@scene.txt"});    // no argument files: a scene like any other
        assertEquals(List.of(Path.of("@scene.txt")), at.scenes);
        Main bench = Main.simpleCommandLine(new String[] {"-q", "--stats", "--json", "a.txt", "-o", "a.png"});   // gradle bench's
        assertNotNull(bench);
        assertEquals(true, bench.json);
        assertEquals(true, bench.stats);
    }

    /** Anything picocli might read differently, or must report, goes to picocli. */
    @Test
    void unusualFormsAreLeftToPicocli() {
        String[][] cases = {
            {}, {"--help"}, {"-h"}, {"--version"}, {"--bench"}, {"--output=x.png", "a.txt"}, {"-j4", "a.txt"},
            {"-j", "-1", "a.txt"}, {"-j", "x", "a.txt"}, {"-j", "1234567890", "a.txt"}, {"-o"}, {"a.txt", "-o", "-q"},
            {"-q", "-q", "a.txt"}, {"--stats", "--stats", "a.txt"}, {"--json", "--json", "--stats", "a.txt"}, {"-o", "a.png", "-o", "b.png", "a.txt"},
            {"-j", "1", "-j", "2", "a.txt"}, {"-"}, {"--", "a.txt"}, {""}, {"-qj", "2", "a.txt"},
        };
        for (String[] c : cases) {
            assertNull(Main.simpleCommandLine(c), () -> String.join(" ", c));
        }
    }

    /** Both readings of the same everyday command give the same exit status and the same error. */
    @Test
    void zeroThreadsIsRejectedTheSameWayOnBothPaths() {
        java.io.ByteArrayOutputStream err1 = new java.io.ByteArrayOutputStream(), err2 = new java.io.ByteArrayOutputStream();
        int direct = Main.run(new java.io.PrintStream(new java.io.ByteArrayOutputStream()), new java.io.PrintStream(err1), "-j", "0", "a.txt");
        int picocli = Main.run(new java.io.PrintStream(new java.io.ByteArrayOutputStream()), new java.io.PrintStream(err2), "--threads=0", "a.txt");
        assertEquals(2, direct);
        assertEquals(direct, picocli);
        assertEquals(err2.toString(), err1.toString());
    }

    /** --json without --stats (or --plan) is refused the same way whichever path reads it. */
    @Test
    void jsonWithoutStatsIsRejectedTheSameWayOnBothPaths() {
        java.io.ByteArrayOutputStream err1 = new java.io.ByteArrayOutputStream(), err2 = new java.io.ByteArrayOutputStream();
        int direct = Main.run(new java.io.PrintStream(new java.io.ByteArrayOutputStream()), new java.io.PrintStream(err1), "--json", "a.txt");
        int picocli = Main.run(new java.io.PrintStream(new java.io.ByteArrayOutputStream()), new java.io.PrintStream(err2), "--json", "--", "a.txt");
        assertNotNull(Main.simpleCommandLine(new String[] {"--json", "a.txt"}));
        assertEquals(2, direct);
        assertEquals(direct, picocli);
        assertEquals(err2.toString(), err1.toString());
    }
}
