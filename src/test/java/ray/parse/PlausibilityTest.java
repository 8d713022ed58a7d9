package ray.parse;

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
import org.junit.jupiter.api.io.TempDir;
import ray.app.Main;

/**
 * Legal but implausible values are warned about, one line each at the field's line, and the render goes
 * on exactly as given: negative colours and mirror coefficients, ones above 1 (more light out than in),
 * negative light intensities; a user's subclass through the fields it inherits. The repository's own
 * scenes give none.
 */
class PlausibilityTest {

    static final String SCENE = """
            Width 8
            Height 6
            Camera Camera
            Vector3d eye [0 0 5]
            Material Diffuse bad
            Vector3d diffuseColor [-1 5 0]
            Material BlinnPhong shiny
            Vector3d diffuseColor [0.2 0.2 0.2]
            Vector3d specularColor [1.5 1.5 1.5]
            Material GlazedMaterial glaze
            double mirrorCoefficient 1.2
            ref base shiny
            Surface Sphere
            double radius 1
            ref material bad
            Surface Sphere
            Vector3d center [2 0 0]
            ref material glaze
            Light PointLight
            Vector3d position [3 3 3]
            Vector3d intensity [-5 -5 -5]
            """;

    @Test
    void implausibleValuesAreOneLineWarningsAtTheirLinesAndTheRenderGoesOn(@TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("s.txt"), SCENE);
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8),
                scene.toString());          // (not -q: it keeps only errors)
        assertEquals(0, status, err.toString(StandardCharsets.UTF_8));
        assertTrue(Files.size(dir.resolve("s.png")) > 0, "rendered");
        List<String> lines = err.toString(StandardCharsets.UTF_8).lines().toList();
        assertEquals(List.of(
                scene + ":6: warning: Diffuse diffuseColor [-1 5 0] is negative: the surface gives out negative light (rendered as given)",
                scene + ":9: warning: BlinnPhong specularColor [1.5 1.5 1.5] is above 1: the surface reflects more light than it receives (rendered as given)",
                scene + ":11: warning: GlazedMaterial mirrorCoefficient 1.2 is above 1: the surface reflects more light than it receives (rendered as given)",
                scene + ":21: warning: PointLight intensity [-5 -5 -5] is negative: the light takes light away (rendered as given)"),
                lines);
    }

    @Test
    void aDefaultValueIsWarnedAtTheObjectsHeader() throws SceneFormatException {
        List<String> w = new ArrayList<>();
        Parser.parse("Width 2\nHeight 2\nCamera Camera\nMaterial Diffuse d\nSurface Sphere\nref material d\nLight PointLight\n"
                + "Vector3d intensity [-1 0 0]\n", "t.txt", w);
        assertEquals(List.of("t.txt:8: warning: PointLight intensity [-1 0 0] is negative: the light takes light away (rendered as given)"), w);
    }

    @Test
    void theRepositorysScenesGiveNoWarning() throws IOException, SceneFormatException {
        try (Stream<Path> scenes = Files.list(Path.of("scenes"))) {
            for (Path p : scenes.filter(s -> s.toString().endsWith(".txt")).sorted().toList()) {
                List<String> w = new ArrayList<>();
                Parser.parse(p, w);
                assertEquals(List.of(), w.stream().filter(s -> s.contains(" is negative") || s.contains(" is above 1")).toList(), p.toString());
            }
        }
    }
}
