package ray.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/** The driver's progress line: tasks done of total, scenes written, time left at the rate so far; only on a terminal. */
class ProgressTest {

    @Test
    void saysTasksScenesAndTimeLeft() {
        assertEquals("raytracer-spark: 0 of 80 tasks, 0 of 2 scenes", Progress.line(0, 80, 0, 2, 5_000_000_000L));
        // 20 of 80 in 10 s: 60 more at 2 a second
        assertEquals("raytracer-spark: 20 of 80 tasks, 1 of 2 scenes, about 30 s left", Progress.line(20, 80, 1, 2, 10_000_000_000L));
        assertEquals("raytracer-spark: 1 of 101 tasks, 0 of 1 scene, about 17 min left", Progress.line(1, 101, 0, 1, 10_000_000_000L));
    }

    @Test
    void drawsNothingWhenNotOnATerminalAndClearsWhatItDrew() {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        Progress off = new Progress(new PrintStream(b, true, StandardCharsets.UTF_8), false);
        off.start(10, 1);
        off.done(5, 0);
        off.clear();
        assertEquals("", b.toString(StandardCharsets.UTF_8));
        Progress on = new Progress(new PrintStream(b, true, StandardCharsets.UTF_8), true);
        on.start(10, 1);
        on.done(5, 0);
        on.clear();
        String s = b.toString(StandardCharsets.UTF_8);
        assertEquals(true, s.startsWith("\rraytracer-spark: 5 of 10 tasks, 0 of 1 scene"), s);
        assertEquals(true, s.endsWith("\r"), "cleared: " + s);
    }
}
