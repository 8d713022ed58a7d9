package ray.parse;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Junk scene lines raise only {@link SceneFormatException}: seeded random mutations (lines deleted,
 * duplicated, swapped, blanked; characters flipped; junk numbers, bytes and words inserted; the file
 * cut short) of every seed scene of the fuzz corpus (which includes {@code scenes/*.txt}), without
 * Jazzer, deterministic and quick enough for every {@code gradle test}. The seed and input number
 * are in any failure message; {@code ParserFuzzTest} explores further with coverage guidance.
 */
class ParserMutationTest {

    /** Inputs over all seeds (so more scenes in scenes/ do not make the test slower), and at least this many per seed. */
    static final int INPUTS_TOTAL = 3000, INPUTS_MIN = 100;
    /** Larger seeds are cut to their first lines up to this size: mutating a huge scene costs time, not coverage. */
    static final int SEED_MAX_BYTES = 16 * 1024;
    static final String[] JUNK = {"NaN", "-NaN", "Infinity", "-inf", "1e999", "-1e400", "1e-400", "-0", "+0", "0", "-1",
        "2147483647", "2147483648", "-2147483649", "9223372036854775808", "99999999999999999999999", "0x10", "1_0", "1.", ".5",
        "1e", "--1", "[", "]", "[]", "[1 2]", "[1 2 3 4]", "[NaN 0 0]", "#", " # c", "ref", "int", "double", "String",
        "Vector3d", "Surface", "Camera", "Material", "Light", "Sphere", "Glazed", "jaz.Zer", "java.lang.Runtime",
        "EvilNotASurface", "FieldZooSurface", "Width", "Height", "AASamples", "MaxDepth", "BGColor", "\t", "\r", "\u00a0",
        "\ufeff", "\u2028", "\u0000", "\u001b", "\uffff", "\ud800", "é", "65536", "65537", "1000", "1001", "64", "65"};

    static Stream<String> seeds() throws IOException, URISyntaxException {
        URL dir = ParserMutationTest.class.getResource("ParserFuzzTestInputs/parseOnlyThrowsSceneFormatException");
        if (dir == null) {
            throw new IllegalStateException("seed corpus not on the test class path");
        }
        Path root = Paths.get(dir.toURI());
        try (Stream<Path> files = Files.walk(root)) {
            return files.filter(Files::isRegularFile).map(p -> root.relativize(p).toString()).sorted()
                    .collect(Collectors.toList()).stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("seeds")
    void mutationsOfASeedRaiseOnlySceneFormatException(String seedFile) throws Exception {
        URL url = ParserMutationTest.class.getResource("ParserFuzzTestInputs/parseOnlyThrowsSceneFormatException/" + seedFile);
        byte[] seed = Files.readAllBytes(Paths.get(url.toURI()));
        if (seed.length > SEED_MAX_BYTES) {
            int cut = SEED_MAX_BYTES;
            while (cut > 0 && seed[cut - 1] != '\n') {
                cut--;
            }
            seed = Arrays.copyOf(seed, cut);
        }
        int inputs = Math.max(INPUTS_MIN, INPUTS_TOTAL / (int) seeds().count());
        byte[] base = seed;
        long seedValue = seedFile.hashCode() * 0x9E3779B97F4A7C15L + 20261121;
        // a hang guard, not a speed test: ~1 ms of work per input is allowed 30 s per seed
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            Random random = new Random(seedValue);
            for (int i = 0; i < inputs; i++) {
                byte[] input = mutate(base, random);
                try {
                    ParserInvariant.check(input);
                } catch (Throwable t) {
                    fail("seed " + seedValue + ", input " + i + " of " + seedFile + ": " + t + "\n--- input ---\n"
                            + new String(input, 0, Math.min(input.length, 3000), StandardCharsets.UTF_8), t);
                }
            }
        });
    }

    /** One to four random edits of {@code seed}. */
    static byte[] mutate(byte[] seed, Random r) {
        List<String> lines = new ArrayList<>(Arrays.asList(new String(seed, StandardCharsets.UTF_8).split("\n", -1)));
        int edits = 1 + r.nextInt(4);
        for (int e = 0; e < edits && !lines.isEmpty(); e++) {
            int i = r.nextInt(lines.size());
            String l = lines.get(i);
            switch (r.nextInt(10)) {
                case 0 -> lines.remove(i);
                case 1 -> lines.add(i, l);
                case 2 -> {
                    int j = r.nextInt(lines.size());
                    lines.set(i, lines.get(j));
                    lines.set(j, l);
                }
                case 3 -> lines.set(i, "");
                case 4 -> lines.set(i, replaceWord(l, JUNK[r.nextInt(JUNK.length)], r));
                case 5 -> lines.set(i, insertAt(l, " " + JUNK[r.nextInt(JUNK.length)], r));
                case 6 -> lines.set(i, flipChar(l, r));
                case 7 -> lines.set(i, l.toLowerCase());
                case 8 -> lines.subList(1 + r.nextInt(lines.size()), lines.size()).clear();
                default -> lines.add(i, JUNK[r.nextInt(JUNK.length)] + " " + JUNK[r.nextInt(JUNK.length)] + " " + JUNK[r.nextInt(JUNK.length)]);
            }
        }
        byte[] out = String.join("\n", lines).getBytes(StandardCharsets.UTF_8);
        if (r.nextInt(20) == 0 && out.length > 0) {
            out[r.nextInt(out.length)] = (byte) r.nextInt(256);    // now and then a raw byte, maybe invalid UTF-8
        }
        return out;
    }

    private static String replaceWord(String line, String junk, Random r) {
        String[] w = line.split(" ", -1);
        w[r.nextInt(w.length)] = junk;
        return String.join(" ", w);
    }

    private static String insertAt(String line, String s, Random r) {
        int at = r.nextInt(line.length() + 1);
        return line.substring(0, at) + s + line.substring(at);
    }

    private static String flipChar(String line, Random r) {
        if (line.isEmpty()) {
            return String.valueOf((char) (32 + r.nextInt(95)));
        }
        char[] c = line.toCharArray();
        c[r.nextInt(c.length)] = "[]#.-+e0 9aZ\t,x".charAt(r.nextInt(15));
        return new String(c);
    }

    /** The mutator itself must produce variety, or the test above proves little. */
    @org.junit.jupiter.api.Test
    void mutatorChangesTheInput() {
        byte[] seed = "Width 4\nHeight 3\n\nCamera Camera\n".getBytes(StandardCharsets.UTF_8);
        Random r = new Random(1);
        long changed = Stream.generate(() -> mutate(seed, r)).limit(100).filter(m -> !Arrays.equals(m, seed)).count();
        assertFalse(changed < 80, changed + " of 100 mutations changed the input");
    }
}
