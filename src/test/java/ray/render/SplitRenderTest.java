package ray.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;
import ray.RayKind;
import ray.Scene;
import ray.settings.RenderSettings;
import ray.parse.Parser;

/**
 * A render cut into rectangles and assembled ({@link SplitRender}) is the whole render bit for bit:
 * pixels, rays by kind, samples per pixel and the adaptive sampler's error estimate, for every sampler,
 * any tiling (odd sizes, one-pixel slivers, pieces added in any order) and any thread count.
 */
class SplitRenderTest {

    /** SampledRenderTest's scene plus an area light: edges, mirror detail and soft shadows. */
    static Scene scene() throws Exception {
        String text = SampledRenderTest.SCENE + """

                Light AreaLight
                Vector3d position [0 3 0]
                Vector3d edge1 [2 0 0]
                Vector3d edge2 [0 0 2]
                Vector3d intensity [0.5 0.5 0.5]
                int samples 2
                """;
        return Parser.parse(text, "split.txt", new ArrayList<>());
    }

    private static RenderSettings settings(String sampler) {
        RenderSettings s = new RenderSettings().sampler(sampler);
        return sampler.equals("adaptive") ? s.targetError(1) : s;
    }

    /** Rectangles covering w x h: columns and rows cut at the given sizes, cycling. */
    static List<int[]> cut(int w, int h, int[] widths, int[] heights) {
        List<int[]> out = new ArrayList<>();
        for (int y = 0, j = 0; y < h; j++) {
            int rh = heights[j % heights.length];
            for (int x = 0, i = 0; x < w; i++) {
                int rw = widths[i % widths.length];
                out.add(new int[] {x, y, Math.min(w, x + rw), Math.min(h, y + rh)});
                x += rw;
            }
            y += rh;
        }
        return out;
    }

    @ParameterizedTest
    @ValueSource(strings = {"grid", "jittered", "sobol", "adaptive"})
    void piecesAssembleToTheWholeRender(String sampler) throws Exception {
        Scene whole = scene();
        Renderer r = new Renderer(whole).threads(2).settings(settings(sampler));
        Image expected = r.render();
        RenderSummary want = r.summary();

        int[][][] tilings = {{{40}, {28}}, {{7, 1, 13}, {5, 2}}, {{16}, {16}}, {{1}, {28}}};
        for (int t = 0; t < tilings.length; t++) {
            Scene scene = scene();
            SplitRender.Prepared prepared = SplitRender.prepare(scene, settings(sampler));
            List<int[]> rects = cut(40, 28, tilings[t][0], tilings[t][1]);
            Collections.shuffle(rects, new Random(t));
            SplitRender.Assembly a = new SplitRender.Assembly(40, 28);
            for (int[] q : rects) {
                a.add(SplitRender.render(prepared, 1 + t % 2, q[0], q[1], q[2], q[3]));
            }
            assertTrue(a.complete());
            List<SplitRender.ProbeTile> probes = a.probeTiles(8 + t);
            assertEquals(sampler.equals("adaptive"), !probes.isEmpty(), "probes only for the adaptive sampler");
            Collections.shuffle(probes, new Random(t));
            for (SplitRender.ProbeTile p : probes) {
                a.addProbes(SplitRender.probe(prepared, 2 - t % 2, p));
            }
            String what = sampler + ", tiling " + t;
            assertArrayEquals(expected.rgb, a.image().rgb, what);
            RenderSummary got = a.summary(want.seconds);
            for (RayKind k : RayKind.values()) {
                assertEquals(want.stats.get(k), got.stats.get(k), what + ": " + k + " rays");
            }
            assertEquals(want.line(), got.line(), what);
            assertEquals(want.meanSamplesPerPixel, got.meanSamplesPerPixel, 0.0, what);
            if (sampler.equals("adaptive")) {
                assertFalse(Double.isNaN(got.estimatedRmse), what);
                assertEquals(want.estimatedRmse, got.estimatedRmse, 0.0, what);
                assertEquals(want.estimatedRmseHigh, got.estimatedRmseHigh, 0.0, what);
            }
        }
    }

    @Test
    void overlapsGapsAndMissingProbesAreRefused() throws Exception {
        Scene scene = scene();
        SplitRender.Prepared prepared = SplitRender.prepare(scene, settings("adaptive"));
        SplitRender.Assembly a = new SplitRender.Assembly(40, 28);
        a.add(SplitRender.render(prepared, 1, 0, 0, 40, 20));
        assertThrows(IllegalStateException.class, a::image, "a gap");
        assertThrows(IllegalArgumentException.class, () -> a.add(SplitRender.render(prepared, 1, 30, 19, 40, 28)), "an overlap");
        a.add(SplitRender.render(prepared, 1, 0, 20, 40, 28));
        List<SplitRender.ProbeTile> probes = a.probeTiles(16);
        a.addProbes(SplitRender.probe(prepared, 1, probes.get(0)));
        assertThrows(IllegalStateException.class, () -> a.summary(1), "a probe tile missing");
        assertThrows(IllegalArgumentException.class, () -> new Renderer(scene).window(0, 0, 41, 28).render(), "outside the image");
    }
}
