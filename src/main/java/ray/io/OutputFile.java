package ray.io;

import java.io.IOException;
import java.io.InputStream;
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
import java.nio.file.attribute.PosixFilePermission;
import java.util.Arrays;
import java.util.Collection;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Every file the program writes (the CLI's PNGs, the viewer's saves, the study's report) goes through
 * here, so one set of rules decides what may be replaced. {@link #prepare} checks the target
 * <em>before</em> the work that produces it (the folder exists and is writable, the name fits, an
 * existing file may be replaced) and reserves the hidden temporary file the bytes will go to;
 * {@link Pending#commit} writes them there and renames the file over the target. A failed or
 * interrupted write never leaves a partial file and never clobbers the existing one.
 *
 * <p>The rules, for the file a path finally names (symbolic links are resolved first, so a link
 * {@code a.png -> notes.txt} is judged as {@code notes.txt}):
 * <ul>
 * <li>a regular file is replaced only if its {@link Guard} accepts it (for an image: empty or a PNG;
 *     for the study's report: a file an earlier study wrote), never when its owner may not write it
 *     (mode {@code 444}: read-only is a request to keep it, even where the folder would allow the
 *     rename), never when it is one of the {@link Pending#protect inputs} of the work (a scene file, an
 *     OBJ file it reads); the replacement keeps the old file's permission bits;</li>
 * <li>a FIFO or a character device (e.g. {@code /dev/stdout}, {@code /dev/null}) is written into, as
 *     a user naming one means; a folder, block device or socket is refused;</li>
 * <li>with {@link Guard#noLinks}, a symbolic link at the target is refused instead of followed (the
 *     study's files inside its report folder).</li>
 * </ul>
 * Temporary names are {@code .raytracer-<pid>-<random>.tmp}, short whatever the target's name; a stale
 * one (its process gone, e.g. killed with SIGKILL, or ended by {@code Runtime.halt}, which runs no
 * clean-up) is removed by the next write to that folder.
 */
public final class OutputFile {

    /** The longest file name (in bytes) Linux and macOS file systems take (NAME_MAX). */
    public static final int NAME_MAX = 255;
    static final String TEMP_PREFIX = ".raytracer-";
    static final String TEMP_SUFFIX = ".tmp";

    /** Temporary files being written by this process, removed by one shutdown hook (Ctrl+C, System.exit). */
    private static final Set<Path> PENDING = ConcurrentHashMap.newKeySet();
    private static volatile boolean hookInstalled;

    private OutputFile() {
    }

    /** What produces the file's bytes. */
    public interface Body {
        void writeTo(OutputStream out) throws IOException;
    }

    /**
     * Which existing regular file may be replaced: {@link #mayReplace} returns null for yes, else the
     * reason it is kept (shown after the file's name).
     */
    public interface Guard {
        String mayReplace(Path real) throws IOException;

        /** Whether a symbolic link at the target is refused rather than followed. */
        default boolean noLinks() {
            return false;
        }

        /** An image: an existing file is replaced only if it is empty or a PNG. */
        Guard PNG = new Guard() {    // (not a lambda: linking one costs start-up time)
            @Override
            public String mayReplace(Path real) throws IOException {
                return isEmptyOrStartsWith(real, PNG_SIGNATURE) ? null
                        : "is not a PNG image; it is left as it is (remove it, or name another file)";
            }
        };
    }

    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

    /** Whether {@code p} is empty or starts with {@code signature}; an unreadable file is neither. */
    public static boolean isEmptyOrStartsWith(Path p, byte[] signature) throws IOException {
        try (InputStream in = Files.newInputStream(p)) {
            byte[] head = in.readNBytes(signature.length);
            return head.length == 0 || Arrays.equals(head, signature);
        } catch (AccessDeniedException e) {
            throw new IOException("permission denied (it cannot be read, so it is not replaced)", e);
        }
    }

    /**
     * Checks that a file can be written to {@code target} and reserves its temporary file. Throws an
     * {@link IOException} whose message is the reason in a few words ("no such folder", "permission
     * denied", "read-only file system", "name too long (300 bytes, at most 255)", "not a regular file (a
     * block device)", "notes.txt (where the link a.png points) is not a PNG image; ...") without the
     * target's own name in front.
     */
    public static Pending prepare(Path target, Guard guard) throws IOException {
        BasicFileAttributes link = attributes(target, LinkOption.NOFOLLOW_LINKS);
        if (link != null && link.isSymbolicLink() && guard.noLinks()) {
            throw new IOException("it is a symbolic link (to " + Files.readSymbolicLink(target)
                    + "); it is not followed and is left as it is (remove it)");
        }
        BasicFileAttributes attrs = attributes(target);
        if (attrs == null && link != null && link.isSymbolicLink()) {
            throw new IOException("a symbolic link to a missing file (" + Files.readSymbolicLink(target) + ")");
        }
        if (attrs != null && attrs.isDirectory()) {
            throw new IOException("is a folder");
        }
        if (attrs != null && !attrs.isRegularFile()) {
            String kind = kind(target);
            if (kind.equals("a FIFO") || kind.equals("a character device")) {
                return new Pending(target, null, guard);      // written into, not replaced
            }
            throw new IOException("not a regular file (" + kind + ")");
        }
        Path real = attrs != null ? target.toRealPath() : realParent(target);
        if (attrs != null) {
            checkReplaceable(target, real, guard);
        }
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
        return new Pending(real, newTempFile(dir), guard);
    }

    /** The absolute path with its folder's links resolved when the folder exists (the file itself does not). */
    private static Path realParent(Path target) {
        Path abs = target.toAbsolutePath();
        Path dir = abs.getParent();
        try {
            return dir != null && Files.isDirectory(dir) ? dir.toRealPath().resolve(abs.getFileName().toString()) : abs;
        } catch (IOException e) {
            return abs;
        }
    }

    /** Throws the reason an existing regular file {@code real} (named {@code asGiven} by the caller) is kept. */
    private static void checkReplaceable(Path asGiven, Path real, Guard guard) throws IOException {
        String shown = shown(asGiven, real);
        Set<PosixFilePermission> perms = permissions(real);
        if (perms != null && !perms.contains(PosixFilePermission.OWNER_WRITE)) {
            throw new IOException(shown + "is read-only (mode " + octal(perms) + "); it is left as it is (make it writable, or name another file)");
        }
        String refusal = guard.mayReplace(real);
        if (refusal != null) {
            throw new IOException(shown + refusal);
        }
    }

    /** "" when the caller's name is the file itself, else "notes.txt (where the link a.png points) ". */
    private static String shown(Path asGiven, Path real) {
        Path abs = asGiven.toAbsolutePath().normalize();
        return abs.equals(real) ? "it " : real + " (where " + asGiven + " leads) ";
    }

    /** A reserved output: {@link #commit} once, and {@link #abandon} always (it is a no-op after commit). */
    public static final class Pending {
        private final Path target;
        private final Guard guard;
        private Path tmp;
        private final java.util.List<Path> inputs = new java.util.ArrayList<>();

        Pending(Path target, Path tmp, Guard guard) {
            this.target = target;
            this.tmp = tmp;
            this.guard = guard;
        }

        /** The file that will be written (symbolic links resolved). */
        public Path target() {
            return target;
        }

        /** Whether the target is a FIFO or device written into rather than a file replaced. */
        public boolean streams() {
            return tmp == null;
        }

        /**
         * Refuses now, and again at {@link #commit}, if the target is one of {@code files} (the files the
         * work reads: the same file on disk, however its path is spelled). The message names the input.
         */
        public void protect(Collection<Path> files) throws IOException {
            inputs.addAll(files);
            checkInputs();
        }

        private void checkInputs() throws IOException {
            if (!Files.exists(target)) {
                return;
            }
            for (Path in : inputs) {
                try {
                    if (Files.exists(in) && Files.isSameFile(in, target)) {
                        throw new IOException("it is " + in + ", a file the scene reads; it is left as it is (name another file)");
                    }
                } catch (NoSuchFileException gone) {
                    // removed meanwhile: not the same file any more
                }
            }
        }

        /** Writes the file and puts it in place; an existing target is replaced only when complete. */
        public void commit(Body body) throws IOException {
            if (tmp == null) {      // a FIFO or device: write into it
                try (OutputStream out = Files.newOutputStream(target, StandardOpenOption.WRITE)) {
                    body.writeTo(out);
                }
                return;
            }
            try (OutputStream out = Files.newOutputStream(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
                body.writeTo(out);
            } catch (NoSuchFileException e) {
                throw new IOException(vanished(), e);
            } catch (IOException e) {
                throw new IOException(reason(e), e);
            }
            BasicFileAttributes link = attributes(target, LinkOption.NOFOLLOW_LINKS);
            BasicFileAttributes now = attributes(target);
            if (now != null && !now.isRegularFile()) {   // it changed since prepare(): still never replace it
                throw new IOException("not a regular file (" + kind(target) + ")");
            }
            if (link != null && link.isSymbolicLink()) { // became a link since prepare(): judged as at prepare()
                throw new IOException("it became a symbolic link while the work ran; it is left as it is");
            }
            checkInputs();
            if (now != null) {
                checkReplaceable(target, target, guard);
                Set<PosixFilePermission> perms = permissions(target);
                if (perms != null) {
                    Files.setPosixFilePermissions(tmp, perms);     // replacing a file keeps its mode (600 stays 600)
                }
            }
            try {
                try {
                    Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
                } catch (AtomicMoveNotSupportedException e) {
                    Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
                }
            } catch (NoSuchFileException e) {
                throw new IOException(Files.isDirectory(target.getParent()) ? vanished() : "no such folder (it was removed while the work ran)", e);
            } catch (IOException e) {
                throw new IOException(reason(e), e);
            }
            forget(tmp);
            tmp = null;
        }

        private String vanished() {
            return Files.isDirectory(tmp.getParent())
                    ? "the temporary file " + tmp.getFileName() + " was removed while the work ran (by another program?); nothing was written"
                    : "no such folder (it was removed while the work ran)";
        }

        /** Removes the temporary file if nothing was committed. */
        public void abandon() {
            if (tmp != null) {
                deleteQuietly(tmp);
                forget(tmp);
                tmp = null;
            }
        }
    }

    /** Prepares, commits and cleans up in one call. */
    public static void write(Path target, Guard guard, Body body) throws IOException {
        Pending p = prepare(target, guard);
        try {
            p.commit(body);
        } finally {
            p.abandon();
        }
    }

    /** Deletes every temporary file this process is writing (for a shutdown hook that halts the JVM). */
    public static void deletePendingTemporaries() {
        for (Path p : PENDING) {
            deleteQuietly(p);
        }
    }

    /** The file's attributes (links followed unless told), or null if it does not exist (or cannot be seen). */
    private static BasicFileAttributes attributes(Path p, LinkOption... options) {
        try {
            return Files.readAttributes(p, BasicFileAttributes.class, options);
        } catch (IOException | SecurityException e) {
            return null;
        }
    }

    private static Set<PosixFilePermission> permissions(Path p) {
        try {
            return Files.getPosixFilePermissions(p);
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return null;
        }
    }

    private static String octal(Set<PosixFilePermission> perms) {
        int m = 0;
        for (PosixFilePermission p : perms) {
            m |= 1 << (8 - p.ordinal());
        }
        return Integer.toOctalString(m);
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
    public static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such folder";
        }
        String r = e instanceof FileSystemException fs && fs.getReason() != null ? fs.getReason() : e.getMessage();
        return r == null || r.isEmpty() ? e.getClass().getSimpleName() : Character.toLowerCase(r.charAt(0)) + r.substring(1);
    }

    /** A new empty file {@code .raytracer-<pid>-<random>.tmp} (at most 40 characters) in {@code dir}. */
    private static Path newTempFile(Path dir) throws IOException {
        installHook();
        String prefix = TEMP_PREFIX + pid() + "-";
        for (int attempt = 0; ; attempt++) {
            Path p = dir.resolve(prefix + Long.toUnsignedString(ThreadLocalRandom.current().nextLong(), 36) + TEMP_SUFFIX);
            PENDING.add(p);
            try {
                // created like any other file, so a new file gets the permissions the umask gives
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
                    Runtime.getRuntime().addShutdownHook(new Thread("output-cleanup") {
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
