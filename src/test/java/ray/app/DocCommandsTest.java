package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The documentation's command outputs are the program's: every indented block in README.md and docs/*.md
 * that follows a line ending in {@code `raytracer ARGS`:} is the output of that command, run here (in
 * this JVM, from the project folder). In a block, a line {@code ...} stands for any number of lines and a
 * line ending in {@code (...)} for any line that starts with what comes before it. On a mismatch the
 * message holds the block as it should read, to paste in.
 */
class DocCommandsTest {

    record Block(Path file, int line, String args, List<String> expected) {
    }

    static List<Block> blocks() throws IOException {
        List<Path> files = new ArrayList<>(List.of(Path.of("README.md")));
        try (Stream<Path> docs = Files.list(Path.of("docs"))) {
            docs.filter(p -> p.toString().endsWith(".md")).sorted().forEach(files::add);
        }
        List<Block> out = new ArrayList<>();
        for (Path f : files) {
            List<String> lines = Files.readAllLines(f, StandardCharsets.UTF_8);
            for (int i = 0; i + 2 < lines.size(); i++) {
                String l = lines.get(i);
                int end = l.lastIndexOf("`:");
                int start = l.lastIndexOf("`raytracer ", end - 1);
                if (end < 0 || !l.endsWith("`:") || start < 0 || !lines.get(i + 1).isEmpty() || !lines.get(i + 2).startsWith("    ")) {
                    continue;
                }
                List<String> block = new ArrayList<>();
                int j = i + 2;
                for (; j < lines.size() && (lines.get(j).startsWith("    ") || lines.get(j).isEmpty() && j + 1 < lines.size()
                        && lines.get(j + 1).startsWith("    ")); j++) {
                    block.add(lines.get(j).isEmpty() ? "" : lines.get(j).substring(4).replaceAll("\\s+$", ""));
                }
                out.add(new Block(f, i + 1, l.substring(start + "`raytracer ".length(), end), block));
                i = j;
            }
        }
        return out;
    }

    static List<String> run(String args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        Main.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8),
                args.trim().split(" +"));
        String text = out.toString(StandardCharsets.UTF_8) + err.toString(StandardCharsets.UTF_8);
        List<String> lines = new ArrayList<>(text.lines().map(s -> s.replaceAll("\\s+$", "")).toList());
        while (!lines.isEmpty() && lines.get(lines.size() - 1).isEmpty()) {
            lines.remove(lines.size() - 1);
        }
        return lines;
    }

    /** Whether {@code actual} matches {@code expected} with its {@code ...} and {@code (...)} elisions. */
    static boolean matches(List<String> expected, int e, List<String> actual, int a) {
        if (e == expected.size()) {
            return a == actual.size();
        }
        String x = expected.get(e);
        if (x.equals("...")) {
            for (int k = a; k <= actual.size(); k++) {
                if (matches(expected, e + 1, actual, k)) {
                    return true;
                }
            }
            return false;
        }
        if (a == actual.size()) {
            return false;
        }
        String y = actual.get(a);
        boolean same = x.endsWith("(...)") ? y.startsWith(x.substring(0, x.length() - "(...)".length())) : x.equals(y);
        return same && matches(expected, e + 1, actual, a + 1);
    }

    @Test
    void everyDocumentedCommandPrintsWhatTheDocsShow() throws IOException {
        List<Block> blocks = blocks();
        assertTrue(blocks.stream().anyMatch(b -> b.args().equals("--help")), "the README shows --help: " + blocks);
        assertTrue(blocks.stream().anyMatch(b -> b.args().startsWith("--plan")), "the README shows a plan: " + blocks);
        StringBuilder wrong = new StringBuilder();
        for (Block b : blocks) {
            List<String> actual = run(b.args());
            if (!matches(b.expected(), 0, actual, 0)) {
                wrong.append('\n').append(b.file()).append(':').append(b.line()).append(": `raytracer ").append(b.args())
                        .append("` prints (paste this block, eliding with ... where it helps):\n\n");
                actual.forEach(l -> wrong.append(l.isEmpty() ? "" : "    " + l).append('\n'));
            }
        }
        assertEquals("", wrong.toString());
    }

    @Test
    void elisionsMatchWhatTheySay() {
        assertTrue(matches(List.of("a", "...", "d"), 0, List.of("a", "b", "c", "d"), 0));
        assertTrue(matches(List.of("a", "...", "d"), 0, List.of("a", "d"), 0));
        assertTrue(!matches(List.of("a", "...", "d"), 0, List.of("a", "b"), 0));
        assertTrue(matches(List.of("bound: 5 rays (...)"), 0, List.of("bound: 5 rays (camera 5)"), 0));
        assertTrue(!matches(List.of("bound: 5 rays (...)"), 0, List.of("bound: 6 rays (camera 6)"), 0));
        assertTrue(!matches(List.of("a"), 0, List.of("a", "b"), 0), "no line left over");
    }
}
