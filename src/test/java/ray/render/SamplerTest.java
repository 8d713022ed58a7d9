package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import ray.PixelSample;
import ray.settings.RenderSettings;

/** Where each sampler puts its samples: inside the pixel, the promised number, stratified where claimed. */
class SamplerTest {

    private static final int[] SIDES = {1, 2, 3, 4, 5, 8};

    @ParameterizedTest
    @ValueSource(strings = {"grid", "jittered", "sobol", "adaptive"})
    void everyValueLiesInTheUnitIntervalAndDependsOnlyOnItsAddress(String name) {
        Random rnd = new Random(8);
        for (int n : SIDES) {
            Sampler s = Sampler.create(name, n);
            assertEquals(n * n, s.samplesPerPixel());
            for (int t = 0; t < 200; t++) {
                int x = rnd.nextInt(5000) - 100, y = rnd.nextInt(5000), i = rnd.nextInt(n * n), d = rnd.nextInt(12);
                double v = s.get(x, y, i, d);
                assertTrue(v >= 0 && v < 1, name + " n=" + n + " (" + x + "," + y + "," + i + "," + d + ") = " + v);
                assertEquals(v, Sampler.create(name, n).get(x, y, i, d), "a fresh sampler gives the same value");
            }
        }
    }

    /** Grid and jittered put exactly one sample in each of the n x n cells (any seed); jittered also in each pair of dimensions. */
    @ParameterizedTest
    @ValueSource(strings = {"grid", "jittered", "adaptive"})
    void oneSamplePerCell(String name) {
        for (int n : SIDES) {
            for (int seed : new int[] {0, 1, 2}) {
                Sampler s = Sampler.create(name, n, seed);
                int pairs = name.equals("jittered") ? 4 : 1;
                for (int pair = 0; pair < pairs; pair++) {
                    for (int px = 0; px < 5; px++) {
                        int[] hits = new int[n * n];
                        for (int i = 0; i < n * n; i++) {
                            double u = s.get(px, 3, i, 2 * pair), v = s.get(px, 3, i, 2 * pair + 1);
                            hits[(int) (v * n) * n + (int) (u * n)]++;
                        }
                        for (int c = 0; c < n * n; c++) {
                            assertEquals(1, hits[c], name + " n=" + n + " seed " + seed + " pair " + pair + " pixel " + px + ": cell " + c);
                        }
                    }
                }
            }
        }
    }

    @Test
    void gridIsTheCellCentresRowByRowAndHalfElsewhere() {
        Sampler g = Sampler.create("grid", 3);
        assertEquals(0.5 / 3, g.get(7, 9, 0, 0));
        assertEquals(2.5 / 3, g.get(7, 9, 5, 0));
        assertEquals(1.5 / 3, g.get(7, 9, 5, 1));
        assertEquals(0.5, g.get(7, 9, 5, 2));
        assertEquals(0.5, g.get(7, 9, 5, 7));
        // the positions the renderer's grid fast path uses: (i + 0.5) / n_s across, (j + 0.5) / n_s down
        for (int i = 0; i < 9; i++) {
            assertEquals((i % 3 + 0.5) / 3, g.get(1, 1, i, 0));
            assertEquals((i / 3 + 0.5) / 3, g.get(1, 1, i, 1));
            assertEquals(GridSampler.gridValue(3, i, 0), g.get(1, 1, i, 0));
        }
    }

    /**
     * Sobol points with 2^m samples per pixel form a (0, m, 2)-net: each box [a/2^k, (a+1)/2^k) x
     * [b/2^(m-k), (b+1)/2^(m-k)) holds exactly one point, in the pixel position and in later pairs.
     */
    @Test
    void sobolIsANetInEveryPairOfDimensions() {
        for (int n : new int[] {1, 2, 4, 8}) {
            for (int seed : new int[] {0, 7}) {
                assertNet(Sampler.create("sobol", n, seed), n * n, "n=" + n + " seed " + seed);
            }
        }
        // the error probes' sets: the first 2^m of a larger sequence, in every pair too
        for (int m : new int[] {16, 32, 128}) {
            assertNet(new SobolSampler(16, 0xe770be, m), m, "probe set of " + m);
        }
    }

    private static void assertNet(Sampler s, int all, String what) {
        int m = Integer.numberOfTrailingZeros(all);
        for (int pair = 0; pair < 3; pair++) {
            for (int px = 0; px < 4; px++) {
                for (int k = 0; k <= m; k++) {
                    int[] hits = new int[all];
                    for (int i = 0; i < all; i++) {
                        int a = (int) (s.get(px, 11, i, 2 * pair) * (1 << k));
                        int b = (int) (s.get(px, 11, i, 2 * pair + 1) * (1 << (m - k)));
                        hits[b * (1 << k) + a]++;
                    }
                    for (int c = 0; c < all; c++) {
                        assertEquals(1, hits[c], what + " pair " + pair + " pixel " + px + " boxes 2^" + k + " x 2^" + (m - k));
                    }
                }
            }
        }
    }

    @Test
    void pixelsAndPairsAreScrambledDifferently() {
        for (String name : new String[] {"jittered", "sobol"}) {
            Sampler s = Sampler.create(name, 4);
            assertTrue(s.get(0, 0, 3, 0) != s.get(1, 0, 3, 0), name + ": neighbouring pixels share a position");
            assertTrue(s.get(0, 0, 3, 0) != s.get(0, 0, 3, 2), name + ": pair 1 repeats pair 0");
        }
    }

    @Test
    void adaptiveOrderVisitsEveryCellOnceAndSpreadsTheFirstFour() {
        for (int n : SIDES) {
            AdaptiveSampler a = new AdaptiveSampler(n);
            boolean[] seen = new boolean[n * n];
            for (int k = 0; k < n * n; k++) {
                assertTrue(!seen[a.order(k)], "n=" + n + ": cell " + a.order(k) + " twice");
                seen[a.order(k)] = true;
            }
            assertTrue(a.firstBatch() >= Math.min(4, n * n) && a.firstBatch() <= n * n);
        }
        AdaptiveSampler a = new AdaptiveSampler(4);
        boolean[] quadrant = new boolean[4];
        for (int k = 0; k < 4; k++) {
            int c = a.order(k);
            quadrant[(c / 4 / 2) * 2 + c % 4 / 2] = true;
        }
        assertTrue(quadrant[0] && quadrant[1] && quadrant[2] && quadrant[3], "the first four samples cover the four quadrants");
    }

    /**
     * The adaptive order as its comment describes it, checked choice by choice: the rotated-grid four
     * first, then each pick a cell farthest (squared distance to the nearest taken cell) from those taken,
     * the lowest such index, followed by its mirror image, so every even prefix is point-symmetric about
     * the centre; the centre cell of an odd grid last.
     */
    @Test
    void adaptiveOrderIsRotatedGridThenFarthestPointsWithMirrors() {
        for (int n = 2; n <= 9; n++) {
            int all = n * n, centre = n % 2 == 1 ? all / 2 : -1;
            int[] order = AdaptiveSampler.farthestPointOrder(n);
            int a = n / 8, b = 3 * n / 8;
            int[] seeds = {a * n + b, (n - 1 - a) * n + (n - 1 - b), b * n + (n - 1 - a), (n - 1 - b) * n + a};
            java.util.List<Integer> firsts = new java.util.ArrayList<>();
            for (int c : seeds) {
                if (!firsts.contains(c)) {
                    firsts.add(c);
                }
            }
            boolean[] taken = new boolean[all];
            for (int k = 0; k < firsts.size(); k++) {
                assertEquals((int) firsts.get(k), order[k], "n=" + n + ": rotated-grid cell " + k);
                taken[order[k]] = true;
            }
            for (int k = firsts.size(); k < all; ) {
                int pick = order[k];
                if (pick == centre) {
                    assertEquals(all - 1, k, "n=" + n + ": the centre comes last");
                    break;
                }
                double best = -1;
                int bestCell = -1;
                for (int c = 0; c < all; c++) {
                    if (!taken[c] && c != centre && nearest(n, c, taken) > best) {
                        best = nearest(n, c, taken);
                        bestCell = c;
                    }
                }
                assertEquals(bestCell, pick, "n=" + n + ": pick " + k + " is the lowest farthest cell");
                taken[pick] = true;
                k++;
                int mirror = all - 1 - pick;
                if (!taken[mirror]) {
                    assertEquals(mirror, order[k], "n=" + n + ": pick " + (k - 1) + " is followed by its mirror");
                    taken[mirror] = true;
                    k++;
                }
            }
            for (int k = 4; k <= all; k += 2) {   // even prefixes from 4 on: point-symmetric (the centre aside)
                java.util.Set<Integer> prefix = new java.util.HashSet<>();
                for (int q = 0; q < k; q++) {
                    prefix.add(order[q]);
                }
                for (int c : prefix) {
                    assertTrue(c == centre || prefix.contains(all - 1 - c), "n=" + n + ": prefix " + k + " holds " + c + " without its mirror");
                }
            }
        }
    }

    private static double nearest(int n, int c, boolean[] taken) {
        double m = Double.POSITIVE_INFINITY;
        for (int t = 0; t < taken.length; t++) {
            if (taken[t]) {
                double dx = c % n - t % n, dy = c / n - t / n;
                m = Math.min(m, dx * dx + dy * dy);
            }
        }
        return m;
    }

    /** Vigna's splitmix64 finaliser, as published (splitmix64.c), for the known-answer test below. */
    private static long splitmixFinaliser(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /**
     * The samplers' hash is splitmix64's finaliser over the combined key, as its comment says: the
     * finaliser restated here gives splitmix64's published first outputs from seed 0, and the hash is that
     * finaliser applied in the documented order (so the jittered and Sobol pixels do not change silently).
     */
    @Test
    void hashIsSplitmix64sFinaliserOverTheKey() {
        long state = 0;
        long[] published = {0xe220a8397b1dcdafL, 0x6e789e6aa1b965f4L, 0x06c45d188009454fL, 0xf88bb8a8724c81ecL};
        for (long want : published) {
            state += 0x9E3779B97F4A7C15L;
            assertEquals(want, splitmixFinaliser(state), "splitmix64 from seed 0");
        }
        Random rnd = new Random(11);
        for (int k = 0; k < 200; k++) {
            int a = rnd.nextInt(), b = rnd.nextInt(), c = rnd.nextInt(), d = rnd.nextInt();
            long h = splitmixFinaliser(0x9E3779B97F4A7C15L ^ a);
            h = splitmixFinaliser(h ^ (b & 0xFFFFFFFFL) * 0xBF58476D1CE4E5B9L);
            h = splitmixFinaliser(h ^ (c & 0xFFFFFFFFL) * 0x94D049BB133111EBL);
            h = splitmixFinaliser(h ^ (d & 0xFFFFFFFFL) * 0x9E3779B97F4A7C15L);
            assertEquals(h, Sampler.hash(a, b, c, d), "hash(" + a + ", " + b + ", " + c + ", " + d + ")");
        }
        assertEquals(0xe220a8397b1dcdafL, splitmixFinaliser(0x9E3779B97F4A7C15L ^ 0), "hash's first step for a = 0");
        assertEquals(0.5, Sampler.unit(1L << 63), 0);
        assertEquals(Math.nextDown(1.0), Sampler.unit(-1L), 0);
        assertEquals(0, Sampler.unit(0x7FFL), 0, "only the top 53 bits count");
    }

    @Test
    void permuteIsABijection() {
        Random rnd = new Random(3);
        for (int l = 1; l < 300; l++) {
            int p = rnd.nextInt();
            boolean[] seen = new boolean[l];
            for (int i = 0; i < l; i++) {
                int j = Sampler.permute(i, l, p);
                assertTrue(j >= 0 && j < l && !seen[j], "l=" + l + " p=" + p + ": " + i + " -> " + j);
                seen[j] = true;
            }
        }
    }

    @Test
    void pixelSampleHandsOutAlignedPairsInOrder() {
        PixelSample ps = new PixelSample();
        ps.next2D();
        assertEquals(0.5, ps.u);
        assertEquals(0.5, ps.v, "outside a render every draw is 0.5");
        Sampler s = Sampler.create("sobol", 4);
        ps.start(s, 3, 4, 5);
        double one = ps.next1D();
        assertEquals(s.get(3, 4, 5, 2), one);
        ps.next2D();   // dimension 3 is skipped: pairs start even
        assertEquals(s.get(3, 4, 5, 4), ps.u);
        assertEquals(s.get(3, 4, 5, 5), ps.v);
        assertEquals(6, ps.dimension());
        ps.start(s, 3, 4, 5);
        assertEquals(one, ps.next1D(), "a restarted sample draws the same numbers");
    }

    @Test
    void unknownNamesAndSizesAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> Sampler.create("halton", 2));
        assertThrows(IllegalArgumentException.class, () -> Sampler.create("grid", 0));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings().sampler("Grid"));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings().targetError(-1));
        assertThrows(IllegalArgumentException.class, () -> new RenderSettings().samples(65));
    }
}
