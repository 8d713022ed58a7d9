package ray.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;

/** {@code gradle buildTimes}'s measurement of one scene, and its table row. */
class BuildTimesTest {

    @Test
    void aSceneIsParsedAndBuiltAndItsRowPrinted() throws Exception {
        BuildTimes.Row r = BuildTimes.measure(Path.of("scenes/showcase.txt"), 2, 3);
        assertTrue(r.deterministic);
        assertEquals(1448, r.primitives);
        assertTrue(r.nodes > 100 && r.parseBest <= r.parseFirst && r.buildBest <= r.buildFirst, r.nodes + " nodes");
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        BuildTimes.print(List.of(r), new PrintStream(b, true, StandardCharsets.UTF_8));
        String[] lines = b.toString(StandardCharsets.UTF_8).split("\n");
        assertEquals(3, lines.length);
        // this JVM runs without -Dray.bvh.hash=true: no hash, and the row says how to get one
        assertTrue(lines[2].startsWith("| scenes/showcase.txt | ") && lines[2].contains("| 1,448 | - (run with -Dray.bvh.hash=true) |"),
                lines[2]);
    }
}
