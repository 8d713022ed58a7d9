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
        "--output=", "--threads=", "-o-", "--no-such", "jittered", "adaptive", "0", "1", "2", "-1", "99999999999",
        "--study", "--quick", "--full-size", "--report-dir", "--view", "--max-depth", "40000"};
    private static final String[] NAMES = {"good.txt", "bad.txt", "sub", "sub/", "link.txt", "dirlink", "dirlink/good.txt",
        "@good.txt", "-dash.txt", "missing.txt", "missing/", "good.png", "out", "sub/x.png", "x".repeat(250) + ".txt",
        "y".repeat(300), "", ".", "sub/../good.txt", "good.txt/x.png",
        "mesh.txt", "model.obj", "notes.txt", "notes-link.png", "ro.png", "mesh.png", "site", "site/", "dag.txt",
        "caf\uFFFD.txt"};   // as a Latin-1 name reaches Java (no such file: refused as not UTF-8, never written)
    private static final String OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    private static final String MESH = GOOD + "\nMaterial Diffuse d\n\nSurface Mesh\nString file model.obj\nref material d\n";
    private static final byte[] RO_PNG = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 4, 2};

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
            // the files issue 17 protects: a scene's OBJ input, a note behind a .png link, a read-only image
            Files.writeString(dir.resolve("model.obj"), OBJ);
            Files.writeString(dir.resolve("mesh.txt"), MESH);
            Files.writeString(dir.resolve("notes.txt"), "notes\n");
            Files.createSymbolicLink(dir.resolve("notes-link.png"), dir.resolve("notes.txt"));
            Files.write(dir.resolve("ro.png"), RO_PNG);
            dir.resolve("ro.png").toFile().setReadOnly();
            StringBuilder dag = new StringBuilder(GOOD).append("\nMaterial Diffuse d\n\nSurface Sphere c0\nref material d\n\n");
            for (int k = 1; k <= 30; k++) {
                dag.append("Surface CSG c").append(k).append("\nref left c").append(k - 1).append("\nref right c").append(k - 1).append("\n\n");
            }
            Files.writeString(dir.resolve("dag.txt"), dag);
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

    /** Where the arguments come from: the fuzzer's bytes, or a seeded random source (the normal test task). */
    interface Choices {
        int pick(int min, int max);

        String pick(String[] values);

        String text(int max);
    }

    @Timeout(value = 20, unit = TimeUnit.SECONDS)
    @FuzzTest(maxDuration = "60s")
    void commandLineNeverMisbehaves(FuzzedDataProvider data) throws IOException {
        check(new Choices() {
            @Override
            public int pick(int min, int max) {
                return data.consumeInt(min, max);
            }

            @Override
            public String pick(String[] values) {
                return data.pickValue(values);
            }

            @Override
            public String text(int max) {
                return data.consumeString(max);
            }
        });
    }

    /**
     * The same checks on 40 seeded random command lines in every `gradle test` (the fuzzer's seeds alone
     * seldom reach --study, --plan with a Mesh, or the protected files): render, --plan, --study, -o -.
     */
    @org.junit.jupiter.api.Test
    void seededCommandLinesNeverMisbehave() throws IOException {
        java.util.Random r = new java.util.Random(17);
        Choices c = new Choices() {
            @Override
            public int pick(int min, int max) {
                return min + r.nextInt(max - min + 1);
            }

            @Override
            public String pick(String[] values) {
                return values[r.nextInt(values.length)];
            }

            @Override
            public String text(int max) {
                StringBuilder b = new StringBuilder();
                for (int i = r.nextInt(max + 1); i > 0; i--) {
                    b.append((char) (r.nextInt(8) == 0 ? r.nextInt(0x3000) : ' ' + r.nextInt(95)));
                }
                return b.toString();
            }
        };
        for (int i = 0; i < 40; i++) {
            check(c);
        }
    }

    private void check(Choices data) throws IOException {
        Path root = folder();
        List<String> args = new ArrayList<>();
        int n = data.pick(0, 8);
        for (int i = 0; i < n; i++) {
            switch (data.pick(0, 3)) {
                case 0 -> args.add(data.pick(OPTIONS));
                case 1 -> args.add(inside(root, data.pick(NAMES)));
                case 2 -> args.add(inside(root, data.text(40)));
                default -> args.add(data.text(20).replace("..", "").replace("/", "_"));   // stays relative: no path
            }
        }
        if (args.stream().anyMatch(a -> !a.startsWith("-") && !a.startsWith(root.toString()) && !isValue(a))) {
            args.add(0, "--plan");        // a bare relative word would name a file in the working folder: only plan
        }
        if (args.contains("--study") && !args.contains("--report-dir")) {
            args.add(0, root.resolve("site").toString());   // never the default build/reports/accuracy of the working folder
            args.add(0, "--report-dir");
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
        assertFalse(e.chars().anyMatch(ch -> ch == 0x1B), "no raw escape on stderr for " + args);
        assertArrayEquals(GOOD.getBytes(StandardCharsets.UTF_8), Files.readAllBytes(root.resolve("good.txt")), "good.txt intact: " + args);
        assertArrayEquals(BAD.getBytes(StandardCharsets.UTF_8), Files.readAllBytes(root.resolve("bad.txt")), "bad.txt intact: " + args);
        assertEquals(GOOD, Files.readString(root.resolve("@good.txt")), "@good.txt intact: " + args);
        assertEquals(OBJ, Files.readString(root.resolve("model.obj")), "a scene's OBJ input intact: " + args);
        assertEquals(MESH, Files.readString(root.resolve("mesh.txt")), "mesh.txt intact: " + args);
        assertEquals("notes\n", Files.readString(root.resolve("notes.txt")), "notes.txt intact (behind notes-link.png): " + args);
        assertArrayEquals(RO_PNG, Files.readAllBytes(root.resolve("ro.png")), "the read-only image intact: " + args);
        assertTrue(Files.isSymbolicLink(root.resolve("link.txt")), "link.txt still a link: " + args);
        assertTrue(Files.isSymbolicLink(root.resolve("notes-link.png")), "notes-link.png still a link: " + args);
        try (Stream<Path> s = Files.walk(root, 2)) {
            assertEquals(List.of(), s.filter(p -> p.getFileName().toString().endsWith(".tmp")).toList(), "temporary files left: " + args);
        }
    }

    /** Words the options take as values (numbers, sampler names), never used as file names. */
    private static boolean isValue(String a) {
        return a.matches("-?[0-9]+") || a.equals("jittered") || a.equals("adaptive");
    }
}
