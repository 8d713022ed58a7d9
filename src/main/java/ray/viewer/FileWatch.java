package ray.viewer;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * Notices that a scene file changed on disk, by comparing its modification time and size with the
 * last look (polling: works on every file system, including network ones where WatchService does not,
 * and sees editors that replace the file instead of writing it). The viewer asks twice a second.
 */
final class FileWatch {

    private Path file;
    private String stamp;

    /** Starts watching {@code file} as it is now. */
    void watch(Path file) {
        this.file = file;
        this.stamp = stamp(file);
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
            return a.lastModifiedTime() + ":" + a.size() + ":" + a.fileKey();
        } catch (IOException | SecurityException e) {
            return "missing";
        }
    }
}
