package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.parse.Parser;

/**
 * The film's numbers by hand: per-pixel counts, sums and means, the variance of the clamped mean
 * (Welford's running M2, s^2 / n averaged over the channels, in 8-bit steps squared), the image writes;
 * the adaptive sampler's 3 x 3 maximum, and which pixels it nudges: exactly the pixels next to an edge.
 */
class FilmTest {

    @Test
    void countsSumsMeansAndTheVarianceOfTheClampedMean() {
        Film f = new Film(3, 2);
        double[][] samples = {{0.2, 0.5, 0.9}, {0.4, 0.1, 1.7}, {0.9, 0.3, -0.5}};   // blue clamps to 1 and 0
        for (double[] s : samples) {
            f.add(2, 1, s[0], s[1], s[2]);
        }
        assertEquals(3, f.count(2, 1));
        assertEquals(0, f.count(1, 1));
        assertEquals(1.5, f.sum(2, 1, 0), 1e-15);
        assertEquals(0.9, f.sum(2, 1, 1), 1e-15);
        assertEquals(2.1, f.sum(2, 1, 2), 1e-15);
        Vector3d m = new Vector3d();
        f.mean(2, 1, m);
        assertTrue(new Vector3d(0.5, 0.3, 0.7).epsilonEquals(m, 1e-15), "mean " + m);
        f.mean(0, 0, m);
        assertEquals(new Vector3d(), m, "a pixel without samples is black");
        // sample variances of the clamped values, divided by n, averaged over channels, times 255^2
        double vr = var(0.2, 0.4, 0.9), vg = var(0.5, 0.1, 0.3), vb = var(0.9, 1, 0);
        assertEquals((vr + vg + vb) / 3 / 3 * 255 * 255, f.varianceOfMean(2, 1), 1e-9);
        f.add(0, 0, 0.5, 0.5, 0.5);
        assertTrue(Double.isNaN(f.varianceOfMean(0, 0)), "one sample: no estimate");
        f.add(0, 0, 0.5, 0.5, 0.5);
        assertEquals(0, f.varianceOfMean(0, 0), 0, "two equal samples");
        assertEquals(5, f.totalSamples());
    }

    private static double var(double... x) {
        double mean = 0;
        for (double v : x) {
            mean += v / x.length;
        }
        double s = 0;
        for (double v : x) {
            s += (v - mean) * (v - mean);
        }
        return s / (x.length - 1);
    }

    @Test
    void setReplacesAPixelAndWritesGoIntoTheImage() {
        Film f = new Film(2, 2);
        f.add(0, 0, 1, 2, 3);
        f.set(1, 1, 4, new double[] {4, 8, 12}, new double[] {0.5, 0.5, 0.5}, new double[] {0.3, 0.3, 0.3});
        assertEquals(4, f.count(1, 1));
        assertEquals(0.3 * 3 / (3.0 * 3 * 4) * 255 * 255, f.varianceOfMean(1, 1), 1e-9);
        Image all = new Image(2, 2);
        all.set(1, 0, 7, 7, 7);   // no samples there: left as it was
        f.writeTo(all);
        assertArrayEquals(new double[] {1, 2, 3, 7, 7, 7, 0, 0, 0, 1, 2, 3}, all.rgb, 1e-15);
        Image part = new Image(2, 2);
        f.writeTo(part, 1, 1, 2, 2);
        assertArrayEquals(new double[] {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3}, part.rgb, 1e-15, "only the region");
        f.writeTo(part, 0, 0, 1, 1);
        assertArrayEquals(new double[] {1, 2, 3, 0, 0, 0, 0, 0, 0, 1, 2, 3}, part.rgb, 1e-15);
        assertEquals(0, Film.clamp(-0.0), 0);
        assertEquals(1, Film.clamp(1e300), 0);
        assertEquals(0, Film.clamp(Double.NaN), 0);
        assertEquals(0.25, Film.clamp(0.25), 0);
    }

    @Test
    void neighbourhoodMaxIsTheLargestOverEach3x3Block() {
        Random r = new Random(7);
        for (int[] size : new int[][] {{1, 1}, {1, 5}, {5, 1}, {4, 3}, {7, 6}}) {
            int w = size[0], h = size[1];
            double[] v = new double[w * h];
            for (int i = 0; i < v.length; i++) {
                v[i] = r.nextInt(10) - 3;
            }
            double[] got = SampledRender.neighbourhoodMax(v, w, h);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    double m = Double.NEGATIVE_INFINITY;
                    for (int j = y - 1; j <= y + 1; j++) {
                        for (int i = x - 1; i <= x + 1; i++) {
                            if (i >= 0 && i < w && j >= 0 && j < h) {
                                m = Math.max(m, v[j * w + i]);
                            }
                        }
                    }
                    assertEquals(m, got[y * w + x], 0, "(" + x + ", " + y + ") of " + w + " x " + h);
                }
            }
        }
    }

    /**
     * A 5 x 5 image, black but for pixel (2, 2), which a white square fills exactly: no pixel's samples
     * disagree (the square's edges lie between the samples), so only the means tell the edge: the pixel
     * and its eight neighbours are nudged to 16 samples, the other sixteen stop after their first four.
     */
    @Test
    void adaptiveNudgesExactlyThePixelsNextToAnEdge() throws Exception {
        String scene = """
                Width 5
                Height 5
                AASamples 4
                Sampler adaptive
                TargetError 1
                AmbientLight [1 1 1]
                Camera Camera
                Vector3d eye [0 0 5]
                double yFOV 90
                Material Diffuse white
                Vector3d ambientColor [1 1 1]
                Surface Triangle
                Vector3d v0 [-1 -1 0]
                Vector3d v1 [1 -1 0]
                Vector3d v2 [1 1 0]
                ref material white
                Surface Triangle
                Vector3d v0 [-1 -1 0]
                Vector3d v1 [1 1 0]
                Vector3d v2 [-1 1 0]
                ref material white
                """;
        Renderer r = new Renderer(Parser.parse(scene, "edge.txt", new ArrayList<>())).threads(2);
        Image img = r.render();
        Film film = r.summary().film;
        StringBuilder counts = new StringBuilder();
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 5; x++) {
                counts.append(film.count(x, y)).append(x < 4 ? " " : "\n");
            }
        }
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 5; x++) {
                boolean centre = x == 2 && y == 2, near = Math.abs(x - 2) <= 1 && Math.abs(y - 2) <= 1;
                assertEquals(centre ? 1 : 0, img.rgb[3 * (5 * y + x)], 0, "pixel (" + x + ", " + y + ")");
                assertEquals(near ? 16 : 4, film.count(x, y), "samples of pixel (" + x + ", " + y + "):\n" + counts);
            }
        }
    }
}
