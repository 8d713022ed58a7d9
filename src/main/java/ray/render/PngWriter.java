package ray.render;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Writes PNGs safely. {@link #prepare} checks the target <em>before</em> anything is rendered (the
 * folder exists, is writable, the name fits) by creating the hidden temporary file the image will be
 * written to; {@link Pending#commit} writes the image there and renames it over the target. A failed
 * or interrupted write never leaves a partial PNG and never clobbers the existing one.
 *
 * <p>Only a regular file (or nothing) is ever replaced: a symbolic link is followed and the file it
 * names is replaced; a FIFO or a character device (e.g. {@code /dev/stdout}, {@code /dev/null}) is
 * written into, as a user naming one means; anything else is refused. Temporary names are
 * {@code .raytracer-<pid>-<random>.tmp}, short whatever the target's name, and a stale one (its
 * process gone, e.g. killed with SIGKILL mid-write) is removed by the next write to that folder.
 * The bytes come from {@link PngEncoder} (not ImageIO: see there why).
 */
public final class PngWriter {

    /** The longest file name (in bytes) Linux and macOS file systems take (NAME_MAX). */
    public static final int NAME_MAX = 255;
    static final String TEMP_PREFIX = ".raytracer-";
    static final String TEMP_SUFFIX = ".tmp";

    /** Temporary files being written by this process, removed by one shutdown hook (Ctrl+C, System.exit). */
    private static final Set<Path> PENDING = ConcurrentHashMap.newKeySet();
    private static volatile boolean hookInstalled;

    private PngWriter() {
    }

    /** Writes {@code image} to {@code target} as {@link #prepare} and {@link Pending#commit} do. */
    public static void write(Image image, Path target) throws IOException {
        Pending p = prepare(target);
        try {
            p.commit(image);
        } finally {
            p.abandon();
        }
    }

    /**
     * Checks that a PNG can be written to {@code target} and reserves its temporary file. Throws an
     * {@link IOException} whose message is the reason in a few words ("no such folder",
     * "permission denied", "read-only file system", "name too long (300 bytes, at most 255)", "not a
     * regular file (a block device)") without the target's name.
     */
    public static Pending prepare(Path target) throws IOException {
        BasicFileAttributes attrs = attributes(target);
        if (attrs == null && Files.isSymbolicLink(target)) {
            throw new IOException("a symbolic link to a missing file (" + Files.readSymbolicLink(target) + ")");
        }
        if (attrs != null && attrs.isDirectory()) {
            throw new IOException("is a folder");
        }
        if (attrs != null && !attrs.isRegularFile()) {
            String kind = kind(target);
            if (kind.equals("a FIFO") || kind.equals("a character device")) {
                return new Pending(target, null);      // written into, not replaced
            }
            throw new IOException("not a regular file (" + kind + ")");
        }
        Path real = attrs != null ? target.toRealPath() : target.toAbsolutePath();
        Path name = real.getFileName();
        if (name == null) {
            throw new IOException("not a file name");
        }
        int bytes = name.toString().getBytes(StandardCharsets.UTF_8).length;
        if (bytes > NAME_MAX) {
            throw new IOException("name too long (" + bytes + " bytes, at most " + NAME_MAX + ")");
        }
        Path dir = real.getParent();
        BasicFileAttributes d = attributes(dir);
        if (d == null) {
            throw new IOException("no such folder");
        }
        if (!d.isDirectory()) {
            throw new IOException(dir + " is not a folder");
        }
        removeStaleTemporaries(dir);
        return new Pending(real, newTempFile(dir));
    }

    /** A reserved output: {@link #commit} once, and {@link #abandon} always (it is a no-op after commit). */
    public static final class Pending {
        private final Path target;
        private Path tmp;

        Pending(Path target, Path tmp) {
            this.target = target;
            this.tmp = tmp;
        }

        /** The file that will be written (symbolic links resolved). */
        public Path target() {
            return target;
        }

        /** Writes the image and puts it in place; an existing target is replaced only when complete. */
        public void commit(Image image) throws IOException {
            if (tmp == null) {      // a FIFO or device: write into it
                try (OutputStream out = Files.newOutputStream(target, StandardOpenOption.WRITE)) {
                    PngEncoder.write(image, out);
                }
                return;
            }
            try (OutputStream out = Files.newOutputStream(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
                PngEncoder.write(image, out);
            } catch (IOException e) {
                throw new IOException(reason(e), e);
            }
            BasicFileAttributes now = attributes(target);
            if (now != null && !now.isRegularFile()) {   // it changed since prepare(): still never replace it
                throw new IOException("not a regular file (" + kind(target) + ")");
            }
            try {
                try {
                    Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
                }
            } catch (IOException e) {
                throw new IOException(reason(e), e);
            }
            forget(tmp);
            tmp = null;
        }

        /** Removes the temporary file if the image was not committed. */
        public void abandon() {
            if (tmp != null) {
                deleteQuietly(tmp);
                forget(tmp);
                tmp = null;
            }
        }
    }

    /** Deletes every temporary file this process is writing (for a shutdown hook that halts the JVM). */
    public static void deletePendingTemporaries() {
        for (Path p : PENDING) {
            deleteQuietly(p);
        }
    }

    /** The file's attributes, following links, or null if it does not exist (or cannot be seen). */
    private static BasicFileAttributes attributes(Path p) {
        try {
            return Files.readAttributes(p, BasicFileAttributes.class);
        } catch (IOException | SecurityException e) {
            return null;
        }
    }

    /** "a FIFO", "a character device", ... for a file that exists and is not regular. */
    public static String kind(Path p) {
        try {
            Object mode = Files.getAttribute(p, "unix:mode");
            int type = (Integer) mode & 0170000;
            return switch (type) {
                case 0010000 -> "a FIFO";
                case 0020000 -> "a character device";
                case 0060000 -> "a block device";
                case 0140000 -> "a socket";
                case 0040000 -> "a folder";
                default -> "a special file";
            };
        } catch (IOException | RuntimeException e) {
            return "a special file";
        }
    }

    /** A short reason for a failed write: "permission denied", "read-only file system", ... */
    static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such folder";
        }
        String r = e instanceof FileSystemException fs && fs.getReason() != null ? fs.getReason() : e.getMessage();
        return r == null ? e.getClass().getSimpleName() : Character.toLowerCase(r.charAt(0)) + r.substring(1);
    }

    /** A new empty file {@code .raytracer-<pid>-<random>.tmp} (at most 40 characters) in {@code dir}. */
    private static Path newTempFile(Path dir) throws IOException {
        installHook();
        String prefix = TEMP_PREFIX + pid() + "-";
        for (int attempt = 0; ; attempt++) {
            Path p = dir.resolve(prefix + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + TEMP_SUFFIX);
            PENDING.add(p);
            try {
                // created like any other file, so the PNG gets the permissions the umask gives
                Files.newOutputStream(p, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                return p;
            } catch (FileAlreadyExistsException e) {
                forget(p);
                if (attempt == 100) {
                    throw e;
                }
            } catch (IOException e) {
                forget(p);
                throw new IOException(reason(e), e);
            }
        }
    }

    private static volatile long pid;   // volatile: a long written by one thread may otherwise be read torn by another

    /**
     * This process's id: the target of /proc/self on Linux (ProcessHandle's first use sets up its
     * process-reaper machinery, which a render that never starts a process does not need), else
     * ProcessHandle's.
     */
    static long pid() {
        if (pid == 0) {
            try {
                pid = Long.parseLong(Files.readSymbolicLink(Path.of("/proc/self")).toString());
            } catch (IOException | RuntimeException e) {
                pid = ProcessHandle.current().pid();
            }
        }
        return pid;
    }

    /**
     * Removes our own temporary files in {@code dir} whose process is gone (same machine: a process of
     * this name pattern that is alive keeps its file). Best effort: a folder we cannot list is left.
     */
    static void removeStaleTemporaries(Path dir) {
        // every name is checked by tempPid, so no glob (a glob compiles a regular expression at start-up)
        try (DirectoryStream<Path> s = Files.newDirectoryStream(dir)) {
            for (Path p : s) {
                long pid = tempPid(p.getFileName().toString());
                if (pid > 0 && ProcessHandle.of(pid).isEmpty() && Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                    deleteQuietly(p);
                }
            }
        } catch (IOException | RuntimeException e) {
            // listing is only housekeeping
        }
    }

    /** The pid in {@code .raytracer-<pid>-<random>.tmp}, or -1 if the name is not one of ours. */
    static long tempPid(String name) {
        if (!name.startsWith(TEMP_PREFIX) || !name.endsWith(TEMP_SUFFIX)) {
            return -1;
        }
        String mid = name.substring(TEMP_PREFIX.length(), name.length() - TEMP_SUFFIX.length());
        int dash = mid.indexOf('-');
        if (dash < 1 || dash > 19 || dash == mid.length() - 1) {
            return -1;
        }
        for (int i = 0; i < mid.length(); i++) {
            char c = mid.charAt(i);
            boolean ok = i < dash ? c >= '0' && c <= '9' : i == dash || c >= '0' && c <= '9' || c >= 'a' && c <= 'z';
            if (!ok) {
                return -1;
            }
        }
        try {
            return Long.parseLong(mid.substring(0, dash));
        } catch (NumberFormatException e) {
            return -1;
        }
    }

    private static void installHook() {
        if (hookInstalled) {
            return;
        }
        synchronized (PENDING) {
            if (!hookInstalled) {
                try {
                    // (not a lambda: linking one costs start-up time)
                    Runtime.getRuntime().addShutdownHook(new Thread("png-cleanup") {
                        @Override
                        public void run() {
                            deletePendingTemporaries();
                        }
                    });
                } catch (IllegalStateException shuttingDown) {
                    // too late for a hook: the finally blocks still delete
                }
                hookInstalled = true;
            }
        }
    }

    private static void forget(Path p) {
        PENDING.remove(p);
    }

    private static void deleteQuietly(Path p) {
        try {
            Files.deleteIfExists(p);
        } catch (IOException ignored) {
            // best effort: the temporary file is hidden and removed by the next write once stale
        }
    }
}
