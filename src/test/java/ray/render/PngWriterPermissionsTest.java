package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The atomic write must not leave the PNG owner-only (as a Files.createTempFile file would be). */
class PngWriterPermissionsTest {

    @Test
    void pngGetsTheSamePermissionsAsAnyNewFile(@TempDir Path dir) throws IOException {
        assumeTrue(Files.getFileAttributeView(dir, PosixFileAttributeView.class) != null, "no POSIX permissions here");
        Path plain = Files.write(dir.resolve("plain.bin"), new byte[] {1});     // what the umask gives a new file
        Path png = dir.resolve("out.png");
        PngWriter.write(new Image(2, 2), png);
        assertEquals(PosixFilePermissions.toString(Files.getPosixFilePermissions(plain)),
                PosixFilePermissions.toString(Files.getPosixFilePermissions(png)));
    }
}
