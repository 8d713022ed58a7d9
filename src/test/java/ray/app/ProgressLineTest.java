package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The progress bar's arithmetic and text (the terminal rules themselves: ProgressProcessTest). */
class ProgressLineTest {

    @Test
    void shareCountsPixelsNotTiles() {
        ProgressLine p = new ProgressLine(new PrintStream(new ByteArrayOutputStream()), "s.txt", 100 * 10);
        p.tileDone(null, 0, 0, 16, 10, 1, 7);        // 160 pixels of 1,000
        assertEquals(0.16, p.share(), 1e-12);
        p.tileDone(null, 96, 0, 100, 10, 2, 7);      // an edge tile: 40 more
        assertEquals(0.20, p.share(), 1e-12);
    }

    @Test
    void progressivePassesShareTheWork() {
        ProgressLine p = new ProgressLine(new PrintStream(new ByteArrayOutputStream()), "s.txt", 100);
        p.tileDone(null, 0, 0, 10, 5, 1, 2);          // half of pass 0 of 2
        p.passDone(null, 0, 2);
        assertEquals(0.5, p.share(), 1e-12);
        p.tileDone(null, 0, 0, 10, 5, 1, 2);          // half of pass 1
        assertEquals(0.75, p.share(), 1e-12);
        p.passDone(null, 1, 2);
        assertEquals(1.0, p.share(), 1e-12);
    }

    @Test
    void lineShowsShareBarElapsedAndTimeLeft() {
        assertEquals("s.txt  50% [==========>         ] 10.0 s, about 10.0 s left", ProgressLine.line("s.txt", 0.5, 10_000_000_000L));
        assertEquals("s.txt   0% [>                   ] 0.3 s", ProgressLine.line("s.txt", 0, 300_000_000L));
        assertEquals("s.txt   1% [>                   ] 0.3 s", ProgressLine.line("s.txt", 0.01, 300_000_000L), "too early to say");
        assertEquals("s.txt 100% [====================] 2.0 s, about 0.0 s left", ProgressLine.line("s.txt", 1, 2_000_000_000L));
        assertEquals("s.txt  25% [=====>              ] 1 min 00 s, about 3 min 00 s left", ProgressLine.line("s.txt", 0.25, 60_000_000_000L));
        assertEquals("2 h 00 min", ProgressLine.duration(7200));
    }

    @Test
    void longNamesAreCutToTheTerminalWidth() {
        String name = "/very/long/path/" + "x".repeat(200) + "/scene.txt";
        String s = ProgressLine.line(name, 0.5, 10_000_000_000L);
        assertEquals(ProgressLine.WIDTH, s.length(), s);
        assertTrue(s.startsWith("...") && s.contains("scene.txt  50%"), s);
    }

    @Test
    void clearErasesWhatWasDrawnAndStopsDrawing() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ProgressLine p = new ProgressLine(new PrintStream(bytes, true, StandardCharsets.UTF_8), "s.txt", 100);
        assertTrue(p.redraw());
        String drawn = bytes.toString(StandardCharsets.UTF_8);
        p.clear();
        String all = bytes.toString(StandardCharsets.UTF_8);
        assertEquals(drawn + "\r" + " ".repeat(drawn.length() - 1) + "\r", all);
        assertFalse(p.redraw(), "nothing is drawn after clear()");
        assertEquals(all, bytes.toString(StandardCharsets.UTF_8));
    }

    @Test
    void theLineFitsNarrowTerminalsAndNeverWraps() {
        String[] labels = {"s.txt", "scenes/showcase-extensions.txt", "a/very/long/path/to/some/student/scene-file-name.txt"};
        double[] shares = {0, 0.01, 0.42, 0.999, 1};
        long[] times = {300_000_000L, 12_000_000_000L, 3_700_000_000_000L};
        for (int width = 1; width <= 120; width++) {
            for (String label : labels) {
                for (double share : shares) {
                    for (long t : times) {
                        String s = ProgressLine.line(label, share, t, width);
                        assertTrue(s.length() <= width, width + " columns: " + s);
                        if (width >= 4) {
                            assertTrue(s.contains((int) Math.floor(100 * share) + "%"), width + " columns keeps the percentage: " + s);
                        }
                    }
                }
            }
        }
        String sixty = ProgressLine.line("scenes/showcase.txt", 0.42, 12_000_000_000L, 59);
        assertTrue(sixty.startsWith("...") && sixty.endsWith("] 12.0 s, about 16.6 s left") && sixty.length() == 59, sixty);
        String forty = ProgressLine.line("scenes/showcase.txt", 0.42, 12_000_000_000L, 39);
        assertTrue(forty.endsWith("] 12.0 s") && forty.contains(".txt  42% [") && forty.length() == 39, "40 columns: the time left goes: " + forty);
    }

    @Test
    void redrawAndClearStayWithinTheTerminalsWidth() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        int[] columns = {80};
        ProgressLine p = new ProgressLine(new PrintStream(bytes, true, StandardCharsets.UTF_8), "scenes/showcase-extensions.txt", 100,
                () -> columns[0]);
        p.tileDone(null, 0, 0, 10, 5, 1, 2);
        assertTrue(p.redraw());
        columns[0] = 40;                                   // the window made narrower mid-render
        assertTrue(p.redraw());
        p.clear();
        String all = bytes.toString(StandardCharsets.UTF_8);
        String[] pieces = all.split("\r", -1);
        for (int i = 1; i < pieces.length; i++) {
            assertTrue(pieces[i].length() <= (i == 1 ? 79 : 39), "piece " + i + " is " + pieces[i].length() + " columns: '" + pieces[i] + "'");
        }
        assertTrue(all.endsWith("\r"), "the cursor is back at the start of an erased line");
        assertTrue(pieces[pieces.length - 2].isBlank());
    }
}
