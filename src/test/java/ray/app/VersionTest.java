package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/** --version prints the version the build says (build.gradle's, plus the commit when built from git). */
class VersionTest {

    @Test
    void versionIsTheBuilds() throws Exception {
        Matcher m = Pattern.compile("(?m)^version = '([^']+)'").matcher(Files.readString(Path.of("build.gradle")));
        assertTrue(m.find(), "build.gradle sets version");
        MainBadInputTest.Run r = MainBadInputTest.run("--version");
        assertEquals(0, r.status());
        assertTrue(r.out().matches("raytracer " + Pattern.quote(m.group(1)) + "(\\+[0-9a-f]{4,40})? \\(Java [^)]+\\)\\R"), r.out());
    }
}
