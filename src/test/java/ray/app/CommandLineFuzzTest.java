package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Timeout;

/**
 * Jazzer fuzz test of the command line: arguments (options, values, paths, '-', '--', '@' names, links,
 * folders, over-long and odd names) over a folder of scenes. Whatever the arguments: the exit status is
 * 0, 1 or 2, nothing is thrown, stderr holds no stack trace and only whole lines, the scene files are
 * never changed, and no temporary file is left. Every path stays inside the fuzz folder (".." is taken
 * out), so nothing outside it is ever written. {@code gradle test} runs the seeds in
 * {@code src/test/resources/ray/app/CommandLineFuzzTestInputs/}; {@code gradle fuzz} fuzzes.
 */
class CommandLineFuzzTest {

    private static final String GOOD = "Width 4\nHeight 3\nBGColor [1 0 0]\n\nCamera Camera\n";
    private static final String BAD = "Width 4\nHeight 3\n\nCamera Camera\nSurface Sphre\n";
    private static final String[] OPTIONS = {"-o", "--output", "-j", "--threads", "-q", "--quiet", "--stats", "--json",
        "--plan", "--cut-faint", "--allow-long", "--sampler", "--samples", "--target-error", "--", "-", "-h", "-V", "-qj",
        "--output=", "--threads=", "-o-", "--no-such", "jittered", "adaptive", "0", "1", "2", "-1", "99999999999"};
    private static final String[] NAMES = {"good.txt", "bad.txt", "sub", "sub/", "link.txt", "dirlink", "dirlink/good.txt",
        "@good.txt", "-dash.txt", "missing.txt", "missing/", "good.png", "out", "sub/x.png", "x".repeat(250) + ".txt",
        "y".repeat(300), "", ".", "sub/../good.txt", "good.txt/x.png"};

    private static Path dir;

    private static synchronized Path folder() throws IOException {
        if (dir == null) {
            dir = Files.createTempDirectory("raytracer-cli-fuzz");
            Files.writeString(dir.resolve("good.txt"), GOOD);
            Files.writeString(dir.resolve("bad.txt"), BAD);
            Files.writeString(dir.resolve("@good.txt"), GOOD);
            Files.writeString(dir.resolve("-dash.txt"), GOOD);
            Files.createDirectories(dir.resolve("sub"));
            Files.createSymbolicLink(dir.resolve("link.txt"), dir.resolve("good.txt"));
            Files.createSymbolicLink(dir.resolve("dirlink"), dir);
        }
        return dir;
    }

    /** A path inside the fuzz folder: the text with every ".." and leading '/' taken out. */
    private static String inside(Path root, String s) {
        String clean = s.replace("..", "").replace('\0', '_');
        while (clean.startsWith("/")) {
            clean = clean.substring(1);
        }
        return root + "/" + clean;
    }

    @Timeout(value = 20, unit = TimeUnit.SECONDS)
    @FuzzTest(maxDuration = "60s")
    void commandLineNeverMisbehaves(FuzzedDataProvider data) throws IOException {
        Path root = folder();
        List<String> args = new ArrayList<>();
        int n = data.consumeInt(0, 8);
        for (int i = 0; i < n; i++) {
            switch (data.consumeInt(0, 3)) {
                case 0 -> args.add(data.pickValue(OPTIONS));
                case 1 -> args.add(inside(root, data.pickValue(NAMES)));
                case 2 -> args.add(inside(root, data.consumeString(40)));
                default -> args.add(data.consumeString(20).replace("..", "").replace("/", "_"));   // stays relative: no path
            }
        }
        if (args.stream().anyMatch(a -> !a.startsWith("-") && !a.startsWith(root.toString()) && !isValue(a))) {
            args.add(0, "--plan");        // a bare relative word would name a file in the working folder: only plan
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(new ByteArrayInputStream(GOOD.getBytes(StandardCharsets.UTF_8)),
                new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8),
                args.toArray(new String[0]));
        String e = err.toString(StandardCharsets.UTF_8);
        assertTrue(status == 0 || status == 1 || status == 2, "status " + status + " for " + args);
        // (messages are one line each, control characters shown as spaces, so a tab starts no line of ours;
        // a name may itself contain "Exception in thread", so only a line starting with it counts)
        assertFalse(e.lines().anyMatch(l -> l.startsWith("\tat ") || l.startsWith("Exception in thread") || l.startsWith("Caused by: ")),
                "stack trace for " + args + ":\n" + e);
        assertTrue(e.isEmpty() || e.endsWith("\n"), "whole lines on stderr for " + args);
        assertArrayEquals(GOOD.getBytes(StandardCharsets.UTF_8), Files.readAllBytes(root.resolve("good.txt")), "good.txt intact: " + args);
        assertArrayEquals(BAD.getBytes(StandardCharsets.UTF_8), Files.readAllBytes(root.resolve("bad.txt")), "bad.txt intact: " + args);
        assertEquals(GOOD, Files.readString(root.resolve("@good.txt")), "@good.txt intact: " + args);
        assertTrue(Files.isSymbolicLink(root.resolve("link.txt")), "link.txt still a link: " + args);
        try (Stream<Path> s = Files.walk(root, 2)) {
            assertEquals(List.of(), s.filter(p -> p.getFileName().toString().endsWith(".tmp")).toList(), "temporary files left: " + args);
        }
    }

    /** Words the options take as values (numbers, sampler names), never used as file names. */
    private static boolean isValue(String a) {
        return a.matches("-?[0-9]+") || a.equals("jittered") || a.equals("adaptive");
    }
}
