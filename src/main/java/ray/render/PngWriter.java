package ray.render;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

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
        Path tmp = newTempFile(dir, target.getFileName().toString());
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
     * Creates a new empty hidden file {@code .<name>.<unique>.tmp} in {@code dir}. Not
     * Files.createTempFile: its random names come from SecureRandom, whose set-up (security
     * providers) costs ~10 ms of a short render's start-up; a name from the clock and a counter,
     * created with CREATE_NEW, is as safe against clobbering.
     */
    private static Path newTempFile(Path dir, String name) throws IOException {
        while (true) {
            Path p = dir.resolve("." + name + "." + Long.toHexString(System.nanoTime()) + "-" + COUNTER.incrementAndGet() + ".tmp");
            try {
                Files.newByteChannel(p, java.nio.file.StandardOpenOption.CREATE_NEW, java.nio.file.StandardOpenOption.WRITE).close();
                return p;
            } catch (java.nio.file.FileAlreadyExistsException taken) {
                // another writer picked the same name: try the next one
            }
        }
    }

    private static final java.util.concurrent.atomic.AtomicLong COUNTER = new java.util.concurrent.atomic.AtomicLong();

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException ignored) {
            // best effort: the temporary file is hidden and named after the target
        }
    }
}
