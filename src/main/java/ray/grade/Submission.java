package ray.grade;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipInputStream;

/**
 * One student's hand-in: the {@code .java} files of a folder or a zip, by file name (a file's folder
 * inside the hand-in does not matter: the framework lives in the default package). Read once, in the
 * grader, with limits on size and count; nothing of the hand-in is ever executed here.
 *
 * @param name   the submission's name: its folder's name, or its zip's without {@code .zip}
 * @param files  file name (e.g. {@code Sphere.java}) to its bytes
 * @param notes  what was left out of the hand-in and why (other files, duplicates, oversize)
 */
public record Submission(String name, Map<String, byte[]> files, List<String> notes) implements java.io.Serializable {

    /** Largest hand-in read (all .java files together): a course assignment is tens of kilobytes. */
    public static final long MAX_TOTAL_BYTES = 4L << 20;
    /** Most .java files read from one hand-in. */
    public static final int MAX_FILES = 500;

    public Submission {
        files = Collections.unmodifiableMap(new TreeMap<>(files));
        notes = List.copyOf(notes);
    }

    /** A folder or a zip; anything else is a {@link IOException} whose message names the path. */
    public static Submission read(Path path) throws IOException {
        if (Files.isDirectory(path)) {
            return readFolder(path);
        }
        if (Files.isRegularFile(path) && path.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".zip")) {
            return readZip(path);
        }
        throw new IOException(path + ": not a folder or a .zip of .java files");
    }

    /**
     * Reads each hand-in; one that cannot be read adds its one-line message to {@code problems} and is left
     * out. Two hand-ins of the same name (a/x.zip, b/x.zip) are both kept, the second as x-2.
     */
    public static List<Submission> readAll(List<Path> paths, List<String> problems) {
        List<Submission> subs = new ArrayList<>();
        java.util.Set<String> names = new java.util.HashSet<>();
        for (Path p : paths) {
            try {
                Submission s = read(p);
                String name = s.name();
                for (int k = 2; !names.add(name); k++) {
                    name = s.name() + "-" + k;
                }
                subs.add(name.equals(s.name()) ? s : new Submission(name, s.files(), s.notes()));
            } catch (IOException e) {
                problems.add(e.getMessage());
            }
        }
        return subs;
    }

    /** The name a submission gets in the class report: its folder's or zip's name, made safe for a file name. */
    public static String nameOf(Path path) {
        String n = path.toAbsolutePath().normalize().getFileName() == null ? "submission"
                : path.toAbsolutePath().normalize().getFileName().toString();
        if (n.toLowerCase(java.util.Locale.ROOT).endsWith(".zip")) {
            n = n.substring(0, n.length() - 4);
        }
        n = n.replaceAll("[^A-Za-z0-9._@+-]", "_");
        // no hidden names, and nothing a spreadsheet reads as a formula (=, +, -, @) in grades.csv
        return n.isEmpty() || n.startsWith(".") || "=+-@".indexOf(n.charAt(0)) >= 0 ? "_" + n : n;
    }

    private static Submission readFolder(Path dir) throws IOException {
        Map<String, byte[]> files = new TreeMap<>();
        List<String> notes = new ArrayList<>();
        long[] total = {0};
        try (Stream<Path> walk = Files.walk(dir, 8)) {
            for (Path p : (Iterable<Path>) walk.sorted()::iterator) {
                if (!Files.isRegularFile(p, java.nio.file.LinkOption.NOFOLLOW_LINKS)) {
                    continue;
                }
                String rel = dir.relativize(p).toString().replace('\\', '/');
                long size = Files.size(p);
                add(files, notes, total, rel, size, () -> Files.readAllBytes(p));
            }
        }
        return new Submission(nameOf(dir), files, notes);
    }

    private static Submission readZip(Path zip) throws IOException {
        Map<String, byte[]> files = new TreeMap<>();
        List<String> notes = new ArrayList<>();
        long[] total = {0};
        try (ZipInputStream in = new ZipInputStream(Files.newInputStream(zip))) {
            ZipEntry e;
            while ((e = in.getNextEntry()) != null) {
                if (e.isDirectory()) {
                    continue;
                }
                String rel = e.getName().replace('\\', '/');
                ZipInputStream from = in;
                add(files, notes, total, rel, e.getSize(), () -> readAtMost(from, MAX_TOTAL_BYTES + 1));
            }
        } catch (java.util.zip.ZipException | IllegalArgumentException e) {
            throw new IOException(zip + ": not a readable zip (" + e.getMessage() + ")");
        }
        return new Submission(nameOf(zip), files, notes);
    }

    private interface Bytes {
        byte[] get() throws IOException;
    }

    private static void add(Map<String, byte[]> files, List<String> notes, long[] total, String rel, long size, Bytes bytes)
            throws IOException {
        String base = rel.substring(rel.lastIndexOf('/') + 1);
        if (rel.startsWith("__MACOSX/") || base.startsWith("._") || !base.endsWith(".java")) {
            if (!base.startsWith(".") && !rel.startsWith("__MACOSX/") && !base.endsWith(".class")) {
                notes.add(rel + ": not a .java file, left out");
            }
            return;
        }
        if (!base.matches("[A-Za-z_$][A-Za-z0-9_$]*\\.java")) {
            notes.add(rel + ": not a Java class file name, left out");
            return;
        }
        if (files.size() >= MAX_FILES) {
            notes.add(rel + ": more than " + MAX_FILES + " .java files, left out");
            return;
        }
        if (files.containsKey(base)) {
            notes.add(rel + ": a second " + base + " in the hand-in, left out (the first one is graded)");
            return;
        }
        byte[] b = size > MAX_TOTAL_BYTES ? null : bytes.get();
        if (b == null || total[0] + b.length > MAX_TOTAL_BYTES) {
            notes.add(rel + ": the hand-in's .java files exceed " + (MAX_TOTAL_BYTES >> 20) + " MB, left out");
            return;
        }
        total[0] += b.length;
        files.put(base, b);
    }

    private static byte[] readAtMost(InputStream in, long limit) throws IOException {
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        byte[] buf = new byte[8192];
        int n;
        while ((n = in.read(buf)) > 0) {
            out.write(buf, 0, n);
            if (out.size() > limit) {
                return null;
            }
        }
        return out.toByteArray();
    }
}
