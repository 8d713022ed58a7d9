package ray.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import ray.render.Image;

/**
 * The Java FLIP against NVIDIA's published implementation (flip-evaluator 1.7, LDR, sRGB inputs, 67.02
 * pixels per degree) on the pairs tools/flip_reference.py wrote: a render with noise and a warmer patch,
 * a render shifted by a pixel, a disc with and without anti-aliasing, a hue rotation, one grey step, a
 * blurred checkerboard, primaries against random colours. The reference runs in 32-bit floats, this in
 * doubles; the maps are stored to 5 decimals.
 */
class FlipTest {

    static final String DIR = "/ray/judge/flip/";

    record Pair(String name, int width, int height, double mean, double max, double[] percentiles) {
        @Override
        public String toString() {
            return name;
        }
    }

    static Stream<Pair> pairs() throws IOException {
        List<Pair> out = new ArrayList<>();
        for (String line : lines("summary.csv")) {
            if (line.startsWith("#") || line.startsWith("name,")) {
                continue;
            }
            String[] f = line.split(",");
            double[] q = new double[6];
            for (int i = 0; i < 6; i++) {
                q[i] = Double.parseDouble(f[5 + i]);
            }
            out.add(new Pair(f[0], Integer.parseInt(f[1]), Integer.parseInt(f[2]), Double.parseDouble(f[3]),
                    Double.parseDouble(f[4]), q));
        }
        assertEquals(7, out.size(), "summary.csv lists every pair");
        return out.stream();
    }

    static List<String> lines(String resource) throws IOException {
        try (InputStream in = FlipTest.class.getResourceAsStream(DIR + resource)) {
            assertTrue(in != null, "missing test resource " + DIR + resource);
            return new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8)).lines().toList();
        }
    }

    static Image png(String resource) throws IOException {
        try (InputStream in = FlipTest.class.getResourceAsStream(DIR + resource)) {
            return Images.fromBufferedImage(ImageIO.read(in));
        }
    }

    @ParameterizedTest
    @MethodSource("pairs")
    void agreesWithTheReferenceImplementation(Pair pair) throws IOException {
        Image ref = png(pair.name + "-reference.png"), test = png(pair.name + "-test.png");
        assertEquals(pair.width, ref.width);
        assertEquals(pair.height, ref.height);
        double[] map = Flip.errorMap(ref, test);
        List<String> rows = lines(pair.name + "-flip.csv");
        assertEquals(pair.height, rows.size());
        double worst = 0;
        for (int y = 0; y < pair.height; y++) {
            String[] f = rows.get(y).split(",");
            for (int x = 0; x < pair.width; x++) {
                double expected = Double.parseDouble(f[x]), got = map[y * pair.width + x];
                worst = Math.max(worst, Math.abs(expected - got));
                assertEquals(expected, got, 2e-4, pair.name + ": pixel (" + x + ", " + y + ")");
            }
        }
        assertEquals(pair.mean, Flip.mean(map), 2e-5, pair.name + ": mean");
        double[] sorted = map.clone();
        Arrays.sort(sorted);
        assertEquals(pair.max, sorted[sorted.length - 1], 2e-4, pair.name + ": max");
        int[] ps = {25, 50, 75, 90, 95, 99};
        for (int i = 0; i < ps.length; i++) {
            assertEquals(pair.percentiles[i], percentile(sorted, ps[i]), 2e-4, pair.name + ": percentile " + ps[i]);
        }
        System.out.printf("FLIP %-17s mean %.6f (reference %.6f), largest pixel difference %.2e%n", pair.name,
                Flip.mean(map), pair.mean, worst);
    }

    /** numpy's default ("linear") percentile of sorted values. */
    static double percentile(double[] sorted, double p) {
        double pos = p / 100 * (sorted.length - 1);
        int lo = (int) Math.floor(pos), hi = Math.min(lo + 1, sorted.length - 1);
        return sorted[lo] + (pos - lo) * (sorted[hi] - sorted[lo]);
    }

    @Test
    void identicalImagesHaveNoErrorAndTheErrorIsSymmetricInNothingButRange() {
        Image a = new Image(20, 10);
        for (int i = 0; i < a.rgb.length; i++) {
            a.rgb[i] = (i * 37 % 101) / 100.0;
        }
        for (double v : Flip.errorMap(a, a)) {
            assertEquals(0, v, 0);
        }
        Image b = new Image(20, 10);
        for (double v : Flip.errorMap(a, b)) {
            assertTrue(v >= 0 && v <= 1, "FLIP lies in [0, 1]: " + v);
        }
    }
}
