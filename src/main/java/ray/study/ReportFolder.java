package ray.study;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.TreeSet;
import ray.io.OutputFile;

/**
 * The study's report folder, which never loses a file the study did not write. The study lists what it
 * wrote in {@value #MANIFEST} inside the folder; an existing file of the same name as one it is about to
 * write is replaced only if that list names it (an earlier study's CSV, plot or index.html), and a
 * symbolic link there is never followed. Everything is checked before the first render
 * ({@link #claim}), and every file is written through {@link OutputFile} (temporary file, rename).
 */
final class ReportFolder implements OutputFile.Guard {

    /** The list of files studies wrote in this folder. */
    static final String MANIFEST = ".raytracer-study";
    private static final String HEADER = "# files written here by raytracer --study (an existing file not listed is never replaced)";

    private final Path dir;
    private final TreeSet<String> ours = new TreeSet<>();

    private ReportFolder(Path dir) {
        this.dir = dir;
    }

    /** Creates the folder if needed and reads its list of files; the reason in the message when it cannot. */
    static ReportFolder open(Path dir) throws IOException {
        try {
            Files.createDirectories(dir);
        } catch (IOException e) {
            throw new IOException("cannot create the report folder (" + OutputFile.reason(e) + ")", e);
        }
        ReportFolder f = new ReportFolder(dir);
        Path m = dir.resolve(MANIFEST);
        if (Files.exists(m, LinkOption.NOFOLLOW_LINKS)) {
            if (!Files.isRegularFile(m, LinkOption.NOFOLLOW_LINKS)) {
                throw new IOException(m + " is not a regular file; it is left as it is (remove it, or choose another --report-dir)");
            }
            List<String> lines;
            try {
                lines = Files.readAllLines(m, StandardCharsets.UTF_8);
            } catch (IOException e) {
                throw new IOException(m + ": cannot read the list of files an earlier study wrote (" + OutputFile.reason(e) + ")", e);
            }
            if (lines.isEmpty() || !lines.get(0).equals(HEADER)) {
                throw new IOException(m + " was not written by a study; it is left as it is (remove it, or choose another --report-dir)");
            }
            for (String l : lines.subList(1, lines.size())) {
                if (!l.isEmpty() && l.indexOf('/') < 0) {
                    f.ours.add(l);
                }
            }
        }
        return f;
    }

    Path path() {
        return dir;
    }

    /**
     * Checks that every file in {@code names} may be written (nothing there, or a file an earlier study
     * wrote; no link, no folder, nothing read-only), then records them as the study's. Throws naming the
     * first file that may not be written.
     */
    void claim(Collection<String> names) throws IOException {
        for (String n : names) {
            OutputFile.Pending p;
            try {
                p = OutputFile.prepare(dir.resolve(n), this);
            } catch (IOException e) {
                throw new IOException(dir.resolve(n) + ": " + e.getMessage(), e);
            }
            p.abandon();
        }
        TreeSet<String> all = new TreeSet<>(ours);
        all.addAll(names);
        StringBuilder b = new StringBuilder(HEADER).append('\n');
        for (String n : all) {
            b.append(n).append('\n');
        }
        byte[] bytes = b.toString().getBytes(StandardCharsets.UTF_8);
        try {
            OutputFile.write(dir.resolve(MANIFEST), new OutputFile.Guard() {
                @Override
                public String mayReplace(Path real) throws IOException {
                    return null;     // checked in open(): it is a list a study wrote
                }

                @Override
                public boolean noLinks() {
                    return true;
                }
            }, out -> out.write(bytes));
        } catch (IOException e) {
            throw new IOException(dir.resolve(MANIFEST) + ": " + e.getMessage(), e);
        }
        ours.addAll(names);
    }

    /** Writes {@code name} in the folder (claimed first). */
    void write(String name, OutputFile.Body body) throws IOException {
        try {
            OutputFile.write(dir.resolve(name), this, body);
        } catch (IOException e) {
            throw new IOException(dir.resolve(name) + ": " + e.getMessage(), e);
        }
    }

    void write(String name, byte[] bytes) throws IOException {
        write(name, (OutputStream out) -> out.write(bytes));
    }

    @Override
    public String mayReplace(Path real) throws IOException {
        Path parent = real.getParent();
        boolean inHere;
        try {
            inHere = parent != null && Files.isSameFile(parent, dir);
        } catch (NoSuchFileException e) {
            inHere = false;
        }
        return inHere && ours.contains(real.getFileName().toString()) ? null
                : "exists and was not written by a study (it is not in " + MANIFEST + "); it is left as it is "
                        + "(remove it, or choose another --report-dir)";
    }

    @Override
    public boolean noLinks() {
        return true;
    }

    /**
     * File-name stems for scenes, one each and all different: the scene's name without {@code .txt};
     * for a second scene of that name (x/s.txt, y/s.txt) its folder's name in front ({@code y-s}), then
     * a number.
     */
    static List<String> stems(List<Path> scenes) {
        List<String> out = new ArrayList<>();
        java.util.Set<String> used = new java.util.HashSet<>();
        for (Path p : scenes) {
            Path fn = p.getFileName();
            String n = p.toString().equals("-") ? "stdin" : fn == null ? "scene" : fn.toString();
            n = n.endsWith(".txt") ? n.substring(0, n.length() - 4) : n;
            if (n.isEmpty() || n.startsWith(".")) {
                n = "scene" + n;
            }
            String stem = n;
            if (used.contains(stem.toLowerCase(java.util.Locale.ROOT))) {
                Path parent = p.toAbsolutePath().normalize().getParent();
                Path pn = parent == null ? null : parent.getFileName();
                stem = pn == null ? n : pn + "-" + n;
                for (int k = 2; used.contains(stem.toLowerCase(java.util.Locale.ROOT)); k++) {
                    stem = n + "-" + k;
                }
            }
            used.add(stem.toLowerCase(java.util.Locale.ROOT));   // case-insensitive file systems too
            out.add(stem);
        }
        return out;
    }
}
