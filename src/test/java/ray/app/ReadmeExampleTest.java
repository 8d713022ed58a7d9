package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;

/** The README's complete scene example must stay a valid scene that shows what it says. */
class ReadmeExampleTest {

    static String example() throws Exception {
        String readme = new String(Files.readAllBytes(Paths.get("README.md")), "UTF-8");
        int start = readme.indexOf("    # a red sphere");
        int end = readme.indexOf("An object is a header");
        assertTrue(start > 0 && end > start, "README example not found");
        StringBuilder sb = new StringBuilder();
        for (String line : readme.substring(start, end).split("\n", -1)) {
            sb.append(line.length() >= 4 ? line.substring(4) : "").append('\n');
        }
        return sb.toString();
    }

    @Test
    void readmeExampleParsesWithoutWarnings() throws Exception {
        List<String> warnings = new ArrayList<>();
        Scene s = Parser.parse(example(), "README.md", warnings);
        assertEquals(List.of(), warnings);
        assertEquals(320, s.width);
        assertEquals(3, s.samplesPerPixel);
        assertEquals(3, s.materials.size());
        assertEquals(3, s.surfaces.size());
        assertEquals(1, s.lights.size());
    }

    /** The camera looks at the sphere's centre: the middle pixel is lit red (red channel far above the others). */
    @Test
    void readmeExampleShowsARedSphereInTheMiddle() throws Exception {
        Scene s = Parser.parse(example(), "README.md", new ArrayList<>());
        Vector3d c = s.renderPixel(s.width / 2, s.height / 2);
        assertTrue(c.x > 0.3 && c.y < 0.2 && c.z < 0.2, "centre pixel " + c);
    }
}
