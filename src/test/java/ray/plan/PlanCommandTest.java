package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.app.Main;

/** {@code --plan}, {@code --json} and the refusal, through the command line. */
class PlanCommandTest {

    @TempDir
    Path dir;

    private final ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();

    private int run(String... args) {
        out.reset();
        err.reset();
        return Main.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8), args);
    }

    private String out() {
        return out.toString(StandardCharsets.UTF_8);
    }

    private String err() {
        return err.toString(StandardCharsets.UTF_8);
    }

    private static final String[] KINDS = {"camera", "shadow", "mirror", "refraction", "user"};

    /** The numbers under {@code "key":{...}} of a JSON line, by kind; a null bound reads as infinity. */
    static Map<String, Double> kinds(String json, String key) {
        Matcher m = Pattern.compile("\"" + key + "\":\\{\"camera\":([0-9.E]+|null),\"shadow\":([0-9.E]+|null),\"mirror\":([0-9.E]+|null),"
                + "\"refraction\":([0-9.E]+|null),\"user\":([0-9.E]+|null)\\}").matcher(json);
        assertTrue(m.find(), key + " in " + json);
        Map<String, Double> r = new HashMap<>();
        for (int i = 0; i < KINDS.length; i++) {
            r.put(KINDS[i], m.group(i + 1).equals("null") ? Double.POSITIVE_INFINITY : Double.parseDouble(m.group(i + 1)));
        }
        return r;
    }

    /** Done when: --plan and --stats --json tell the truth for every scene in scenes/. */
    @Tag("slow") // every scene; left out by gradle mutation -PmutationFast
    @Test
    void planAndStatsTellTheTruthForEveryScene() throws IOException {
        List<String> scenes = new ArrayList<>();
        try (Stream<Path> s = Files.list(Path.of("scenes"))) {
            for (Path p : (Iterable<Path>) s.sorted()::iterator) {
                Files.copy(p, dir.resolve(p.getFileName()));     // the OBJ files the scenes read too
                if (p.toString().endsWith(".txt")) {
                    scenes.add(dir.resolve(p.getFileName()).toString());
                }
            }
        }
        assertEquals(0, run(Stream.concat(Stream.of("--plan", "--json"), scenes.stream()).toArray(String[]::new)), err());
        String[] plans = out().split("\n");
        assertEquals(0, run(Stream.concat(Stream.of("--stats", "--json"), scenes.stream()).toArray(String[]::new)), err());
        String[] stats = out().split("\n");
        assertEquals(scenes.size(), plans.length);
        assertEquals(scenes.size(), stats.length);
        for (int i = 0; i < scenes.size(); i++) {
            String scene = scenes.get(i);
            assertTrue(plans[i].startsWith("{\"scene\":\"" + scene + "\""), plans[i]);
            assertTrue(stats[i].startsWith("{\"scene\":\"" + scene + "\""), stats[i]);
            Map<String, Double> bound = kinds(plans[i], "bound"), without = kinds(plans[i], "boundWithoutPlan"), rays = kinds(stats[i], "rays");
            for (String k : KINDS) {
                assertTrue(rays.get(k) <= bound.get(k), scene + ": " + rays.get(k) + " " + k + " rays counted, the plan's bound is " + bound.get(k));
                assertTrue(bound.get(k) <= without.get(k), scene + ": " + k + " bound above the bound without skips");
            }
            assertEquals(bound.get("camera"), rays.get("camera"), scene + ": one camera ray per sample");
            // an effect the plan says is off casts nothing
            for (String[] e : new String[][] {{"directLight", "shadow"}, {"mirrorReflection", "mirror"}, {"refraction", "refraction"},
                    {"userRays", "user"}}) {
                if (plans[i].contains("\"" + e[0] + "\":{\"on\":false")) {
                    assertEquals(0, rays.get(e[1]), scene + ": " + e[0] + " off but " + e[1] + " rays were cast");
                    assertEquals(0, bound.get(e[1]), scene + ": " + e[0] + " off but its bound is not 0");
                }
            }
        }
    }

    /** The keys docs/json.md promises are the keys printed (and in that order at the top level). */
    @Test
    void jsonKeysAreTheDocumentedOnes() throws IOException {
        Path scene = dir.resolve("k.txt");
        Files.copy(Path.of("scenes/material-glazed.txt"), scene);
        assertEquals(0, run("--stats", "--json", scene.toString()));
        assertEquals(List.of("scene", "output", "width", "height", "samplesPerPixel", "maxDepth", "seconds", "cpuSeconds",
                "peakRssBytes", "bvhBytesPerPrimitive", "rays", "invalidSamples"), topLevelKeys(out().strip()));
        assertTrue(out().contains("\"seconds\":{\"parse\":"), out());
        assertEquals(0, run("--plan", "--json", scene.toString()));
        assertEquals(List.of("scene", "width", "height", "samplesPerPixel", "maxDepth", "effects", "bound", "boundWithoutPlan",
                "totalBound", "totalBoundWithoutPlan", "cutFaint", "lights", "saved", "skipped", "estimate"), topLevelKeys(out().strip()));
        String doc = Files.readString(Path.of("docs/json.md"));
        for (String key : List.of("cpuSeconds", "peakRssBytes", "bvhBytesPerPrimitive", "invalidSamples", "boundWithoutPlan",
                "totalBoundWithoutPlan", "cutFaint", "cameraRays", "directLight", "mirrorReflection", "areaLightSamples", "userRays")) {
            assertTrue(doc.contains("`" + key + "`") || doc.contains("\"" + key + "\""), key + " is not documented in docs/json.md");
        }
    }

    /** The keys of a one-line JSON object's top level, in order (strings hold no braces in these objects). */
    static List<String> topLevelKeys(String json) {
        List<String> keys = new ArrayList<>();
        int depth = 0;
        Matcher m = Pattern.compile("[{}\\[\\]]|\"((?:[^\"\\\\]|\\\\.)*)\"(:?)").matcher(json);
        while (m.find()) {
            String t = m.group();
            if (t.equals("{") || t.equals("[")) {
                depth++;
            } else if (t.equals("}") || t.equals("]")) {
                depth--;
            } else if (depth == 1 && !m.group(2).isEmpty()) {
                keys.add(m.group(1));
            }
        }
        return keys;
    }

    /** Over 1e11 rays: refused before rendering, one line naming the cause and the option, no PNG. */
    @Test
    void anAbsurdSceneIsRefusedBeforeRendering() throws IOException {
        Path scene = dir.resolve("absurd.txt");
        Files.writeString(scene, "Width 100\nHeight 100\nAASamples 64\nMaxDepth 1000\n\nCamera Camera\n\n"
                + "Material Diffuse d\n\nMaterial Glazed m\nref base d\ndouble mirrorCoefficient 0.5\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 0]\nVector3d v1 [100 -100 0]\nVector3d v2 [0 100 0]\nref material m\n\n"
                + "Surface Triangle\nVector3d v0 [-100 -100 10]\nVector3d v1 [0 100 10]\nVector3d v2 [100 -100 10]\nref material m\n\n"
                + "Light PointLight\nVector3d position [0 0 3]\n\nLight PointLight\nVector3d position [1 1 3]\n\n");
        assertEquals(1, run(scene.toString()));
        String e = err().strip();
        assertFalse(e.contains("\n"), e);
        // 4096 samples x 10,000 pixels x (1 camera + 1000 mirror + 2 x 1001 shadow rays)
        assertTrue(e.startsWith(scene + ": refused: this render may cast up to 123,002,880,000 rays (limit 1e11; "), e);
        assertTrue(e.contains("100x100 pixels x 64x64 samples") && e.contains("MaxDepth") && e.contains("--allow-long"), e);
        assertFalse(Files.exists(dir.resolve("absurd.png")));
        assertEquals("", out());
        // the plan says so too, without rendering
        assertEquals(0, run("--plan", scene.toString()));
        assertTrue(out().contains("a render would be refused (bound over 1e11 rays; --allow-long allows it)"), out());
    }

    @Test
    void planTextNamesEffectsAndSavings() throws IOException {
        Path scene = dir.resolve("s.txt");
        Files.copy(Path.of("scenes/glazed-base-vs-none.txt"), scene);
        assertEquals(0, run("--plan", scene.toString()));
        String o = out();
        assertTrue(o.startsWith("plan for " + scene + " (240x180, MaxDepth 10)\n"), o);
        // no exact skip changes anything here (a Glazed without a base has no direct term with or without the plan):
        // nothing is named as saved, and the bound is the same either way
        assertFalse(o.contains("saved:"), o);
        String bound = o.lines().filter(l -> l.startsWith("  bound: ")).findFirst().orElseThrow().substring(9);
        assertTrue(o.contains("  without the plan's skips: " + bound + "\n"), o);
        assertTrue(o.contains("  refraction          off  no material refracts"), o);
        Files.writeString(scene, Files.readString(scene).replaceAll("(?m)^AmbientLight .*$", "AmbientLight [0 0 0]"));
        assertEquals(0, run("--plan", scene.toString()));
        assertTrue(out().contains("  ambient             off  I_a = 0\n"), out());
        assertFalse(out().contains("saved:"), "no ray is saved by I_a = 0: " + out());
        assertFalse(Files.exists(dir.resolve("s.png")), "--plan renders nothing");
        // the command line's overrides are planned too
        assertEquals(0, run("--plan", "--samples", "3", "--sampler", "jittered", scene.toString()));
        assertTrue(out().contains("240 x 180 pixels x 3x3 samples (jittered sampler)   <= 388,800 camera rays"), out());
    }

    @Test
    void jsonNeedsPlanOrStats() {
        assertEquals(2, run("--json", "scenes/showcase.txt"));
        assertEquals("raytracer: --json goes with --plan or --stats", err().strip());
        assertEquals(2, run("--plan"));
        assertEquals("raytracer: --plan needs scene files", err().strip());
    }

    @Test
    void aSceneThatCannotBeReadFailsThePlanWithItsOneLine() {
        assertEquals(1, run("--plan", dir.resolve("missing.txt").toString()));
        assertEquals(dir.resolve("missing.txt") + ": cannot read the scene: no such file", err().strip());
    }
}
