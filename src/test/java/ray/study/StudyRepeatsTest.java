package ray.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.Scene;
import ray.parse.Parser;
import ray.render.Renderer;

/**
 * The study's repeats for timing go through {@link StudyRenderer#renderAll} (so raytracer-spark gets
 * them too): all settings in one batch, then only the settings whose CPU times spread widely, in
 * further batches, up to three times the repeats; the report names the machines when times come from
 * more than one; and a render measures its CPU time when asked.
 */
class StudyRepeatsTest {

    /** The real renders, with scripted times: n_s=2 of the grid has CPU times all over the place, the rest steady. */
    static final class ScriptedTimes implements StudyRenderer {
        final StudyRenderer real = Study.localRenderer(1);
        final List<List<Setting>> batches = new ArrayList<>();
        final Map<String, Integer> count = new HashMap<>();
        int renders;

        @Override
        public List<String> samplers() {
            return real.samplers();
        }

        @Override
        public Result render(Scene scene, Setting s) {
            return real.render(scene, s);
        }

        @Override
        public List<Result> renderAll(Scene scene, List<Setting> settings) {
            if (settings.stream().anyMatch(s -> s.label().equals(Setting.REFERENCE))) {
                return real.renderAll(scene, settings);       // the reference's halves: images only, not timed
            }
            batches.add(List.copyOf(settings));
            List<Result> out = new ArrayList<>();
            for (Setting s : settings) {
                Result r = real.render(scene, s);
                int k = count.merge(s.sampler() + s.label(), 1, Integer::sum);
                boolean noisy = s.sampler().equals("grid") && s.label().equals("n_s=2");
                double cpu = noisy ? 0.1 * (1 + k % 3) : 0.1 + 0.001 * (k % 2);
                out.add(new Result(r.image(), cpu * 1.5, cpu, r.rays(), r.meanSpp(), r.estimate(), renders++ % 2 == 0 ? "node-a" : "node-b"));
            }
            return out;
        }
    }

    @Test
    void settingsWhoseTimesSpreadAreRenderedAgainInFurtherBatchesUpToThreeTimesTheRepeats(@TempDir Path dir) throws Exception {
        Path scene = Files.writeString(dir.resolve("tiny.txt"), StudyTest.TINY);
        ScriptedTimes renderer = new ScriptedTimes();
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = new Study(renderer, StudySettings.QUICK, 3, new PrintStream(out), new PrintStream(err), false)
                .run(List.of(scene), dir.resolve("r"), "test");
        assertEquals(0, status, err.toString());

        List<Setting> first = renderer.batches.get(0);
        assertEquals(3 * new java.util.HashSet<>(first).size(), first.size(), "the first batch: every setting, 3 times");
        assertEquals(3, renderer.batches.size(), "then two more batches for the noisy setting (3 + 3 + 3 = 9 = 3 x 3 repeats)");
        for (List<Setting> later : renderer.batches.subList(1, 3)) {
            assertEquals(3, later.size(), later.toString());
            assertTrue(later.stream().allMatch(s -> s.sampler().equals("grid") && s.label().equals("n_s=2")), later.toString());
        }

        List<String> lines = Files.readAllLines(dir.resolve("r/tiny.csv"));
        List<String> header = List.of(lines.get(0).split(","));
        int repeats = header.indexOf("repeats"), cpu = header.indexOf("cpu_seconds_median"), label = header.indexOf("setting");
        int q1 = header.indexOf("cpu_seconds_q1"), q3 = header.indexOf("cpu_seconds_q3");
        for (String line : lines.subList(1, lines.size())) {
            String[] f = line.split(",");
            boolean noisy = f[0].equals("grid") && f[label].equals("n_s=2");
            assertEquals(noisy ? "9" : "3", f[repeats], line);
            assertEquals(noisy ? 0.2 : 0.1, Double.parseDouble(f[cpu]), 0.0011, "the median of the CPU times the renderer measured: " + line);
            if (noisy) {
                assertEquals(0.1, Double.parseDouble(f[q1]), 1e-9, line);
                assertEquals(0.3, Double.parseDouble(f[q3]), 1e-9, line);
            }
        }
        String html = Files.readString(dir.resolve("r/index.html"));
        assertTrue(html.contains("Times from different machines") && html.contains("2 machines (node-a, node-b)"), "the report names the machines");
        assertTrue(html.contains("Why 40 dB") && html.contains("Recommendation.") && html.contains("CPU middle half"), "the report's sections");
    }

    @Test
    void oneMachineIsNotCalledDifferentMachines() {
        SceneStudy.Outcome o = ReportChoiceTest.outcome("a");
        assertEquals(List.of(""), Report.machines(List.of(o, o)));
    }

    @Test
    void aRenderMeasuresItsCpuTimeOnlyWhenAsked() throws Exception {
        Scene s = Parser.parse(StudyTest.TINY, "tiny.txt", new ArrayList<>());
        Renderer plain = new Renderer(s).threads(2);
        plain.render();
        assertTrue(Double.isNaN(plain.summary().cpuSeconds), "not measured unless asked");
        Renderer r = new Renderer(s).threads(2).measureCpu(true);
        r.render();
        double cpu = r.summary().cpuSeconds;
        assertFalse(Double.isNaN(cpu));
        assertTrue(cpu > 0 && cpu < 60, "CPU seconds of a tiny render: " + cpu);
    }
}
