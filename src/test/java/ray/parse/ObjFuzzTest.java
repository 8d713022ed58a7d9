package ray.parse;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.code_intelligence.jazzer.junit.DictionaryEntries;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Timeout;

/**
 * Jazzer fuzz test of OBJ files as a scene's Mesh reads them: whatever the bytes, reading the scene
 * succeeds or throws one {@link SceneFormatException} on one line naming the OBJ file or the scene;
 * no other exception, no hang, no memory blow-up. {@code gradle test} runs it on the seeds in
 * {@code src/test/resources/ray/parse/ObjFuzzTestInputs/objOnlyThrowsSceneFormatException/} (plus the
 * {@code scenes/*.obj} files the build adds); {@code gradle fuzz -Ptests='.*ObjFuzzTest'} fuzzes.
 */
class ObjFuzzTest {

    private static Path dir;

    private static synchronized Path folder() throws IOException {
        if (dir == null) {
            dir = Files.createTempDirectory("raytracer-obj-fuzz");
            Files.writeString(dir.resolve("s.txt"), "Width 4\nHeight 3\n\nCamera Camera\n\nMaterial Diffuse d\n\n"
                    + "Surface Mesh\nString file m.obj\nint smooth 1\nref material d\n");
        }
        return dir;
    }

    @Timeout(value = 5, unit = TimeUnit.SECONDS)
    @DictionaryEntries({"v ", "vn ", "vt ", "f ", "/", "//", "-1", "\t", "\uFEFF", "#", "g ", "usemtl", "o ", "s off",
        "0x1p0", "1f", "1d", "NaN", "1e39", "2147483648", "99999999999", "\r\n"})
    @FuzzTest(maxDuration = "60s")
    void objOnlyThrowsSceneFormatException(byte[] data) throws IOException {
        Path d = folder();
        Files.write(d.resolve("m.obj"), data);
        try {
            Parser.parse(d.resolve("s.txt"), new ArrayList<>());
        } catch (SceneFormatException e) {
            String m = e.getMessage();
            assertTrue(m.startsWith(d.resolve("m.obj") + ":") || m.startsWith(d.resolve("s.txt") + ":"), m);
            assertFalse(m.contains("\n") || m.contains("\r"), "one line: " + m);
        }
    }
}
