package ray.render;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes PNGs atomically: the image goes to a temporary file in the target's directory, which is then
 * renamed over the target. A failed or interrupted write never leaves a partial PNG and never
 * clobbers the existing one. The bytes come from {@link PngEncoder} (not ImageIO: see there why).
 */
public final class PngWriter {

    private PngWriter() {
    }

    public static void write(Image image, Path target) throws IOException {
        Path dir = target.toAbsolutePath().getParent();
        Path tmp = newTempFile(dir, "." + target.getFileName() + ".");
        Thread cleanup = new Thread() {     // (not a lambda: linking one costs start-up time)
            @Override
            public void run() {
                deleteQuietly(tmp);
            }
        };
        Runtime.getRuntime().addShutdownHook(cleanup);   // Ctrl-C during the write: no stray temp file
        try {
            try (OutputStream out = Files.newOutputStream(tmp)) {
                PngEncoder.write(image, out);
            }
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } finally {
            deleteQuietly(tmp);
            try {
                Runtime.getRuntime().removeShutdownHook(cleanup);
            } catch (IllegalStateException shuttingDown) {
                // the hook runs anyway
            }
        }
    }

    /**
     * A new empty file {@code prefix<random>.tmp} in {@code dir}, created like any other file (so the
     * PNG gets the permissions the umask gives, not the owner-only ones of Files.createTempFile).
     */
    private static Path newTempFile(Path dir, String prefix) throws IOException {
        for (int attempt = 0; ; attempt++) {
            Path p = dir.resolve(prefix + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + ".tmp");
            try {
                Files.newOutputStream(p, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return p;
            } catch (FileAlreadyExistsException e) {
                if (attempt == 100) {
                    throw e;
                }
            }
        }
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException ignored) {
            // best effort: the temporary file is hidden and named after the target
        }
    }
}
