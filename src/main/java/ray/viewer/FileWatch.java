package ray.viewer;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.zip.CRC32;

/**
 * Notices that a scene file changed on disk, by comparing its modification time, size, identity and
 * (for files up to {@value #HASHED} bytes) a checksum of its content with the last look: an edit that
 * keeps the size within the file system's clock tick is still seen. Polling works on every file system,
 * including network ones where WatchService does not, and sees editors that replace the file instead
 * of writing it. The viewer asks five times a second. Watching nothing ({@code null}) is allowed.
 */
final class FileWatch {

    /** Files up to this size are also checksummed on each look (a scene of 4 MB takes about a millisecond). */
    static final long HASHED = 4L << 20;

    private Path file;
    private String stamp;

    /** Starts watching {@code file} as it is now; null stops watching. */
    void watch(Path file) {
        this.file = file;
        this.stamp = file == null ? null : stamp(file);
    }

    Path file() {
        return file;
    }

    /** True once per change since the last call (or {@link #watch}): the file was written, replaced or removed. */
    boolean changed() {
        if (file == null) {
            return false;
        }
        String now = stamp(file);
        if (now.equals(stamp)) {
            return false;
        }
        stamp = now;
        return true;
    }

    private static String stamp(Path file) {
        try {
            BasicFileAttributes a = Files.readAttributes(file, BasicFileAttributes.class);
            String s = a.lastModifiedTime() + ":" + a.size() + ":" + a.fileKey();
            if (a.isRegularFile() && a.size() <= HASHED) {
                CRC32 crc = new CRC32();
                crc.update(Files.readAllBytes(file));
                s += ":" + Long.toHexString(crc.getValue());
            }
            return s;
        } catch (IOException | SecurityException | OutOfMemoryError e) {
            return "missing";
        }
    }
}
