package ray.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

/**
 * Where a submission's child JVM runs: inside bubblewrap when it works here, else (named in every report)
 * as a plain child process with the same limits.
 *
 * <p>With {@code bwrap}: new user, pid, network, IPC, UTS and cgroup namespaces (no network at all; the
 * child is uid 65534 without capabilities and cannot make further user namespaces); a file system of
 * only the system libraries and the JDK (read-only; no /bin, so no shell to start), the grading input
 * read-only at {@code /grade/in}, the grader's harness at {@code /grade/lib}, its scratch folder
 * {@code /grade/out} the only writable place beside a private, size-limited {@code /tmp}; a new session
 * (no terminal injection), killed with its whole pid namespace when the grader lets go of it
 * ({@code --die-with-parent}). Reference images, other submissions and the grader's files are simply not
 * in its world. Limits on top, inherited by anything it starts: CPU seconds, file size, open files,
 * address space (through {@code prlimit}), heap (-Xmx) and wall-clock (the grader kills it).
 *
 * <p>Fallback ({@code none}): the same child JVM, working directory and limits, but no file-system or
 * network isolation: use it only for code you trust (a course's own solution), or install bubblewrap.
 */
public final class Sandbox {

    public enum Kind { BWRAP, NONE }

    /** Limits for one child JVM. */
    public record Limits(long cpuSeconds, long fileBytes, long tmpBytes, long addressBytes) {
    }

    public static final String IN = "/grade/in";
    public static final String OUT = "/grade/out";
    public static final String LIB = "/grade/lib";

    private final Kind kind;
    private final String why;
    private final boolean prlimit;

    private Sandbox(Kind kind, String why, boolean prlimit) {
        this.kind = kind;
        this.why = why;
        this.prlimit = prlimit;
    }

    /**
     * {@code auto}: bubblewrap when it runs here, else the fallback; {@code bwrap}: bubblewrap or an
     * IOException saying why not; {@code none}: the fallback.
     */
    public static Sandbox choose(String mode) throws IOException {
        checkMode(mode);
        boolean prlimit = works(List.of("prlimit", "--cpu=10", "true"));
        switch (mode) {
            case "none" -> {
                return new Sandbox(Kind.NONE, "no sandbox (--sandbox none)", prlimit);
            }
            case "bwrap", "auto" -> {
                String problem = bwrapProblem();
                if (problem == null) {
                    return new Sandbox(Kind.BWRAP, "bubblewrap", prlimit);
                }
                if (mode.equals("bwrap")) {
                    throw new IOException("--sandbox bwrap: " + problem);
                }
                return new Sandbox(Kind.NONE, "NO SANDBOX: " + problem + "; student code ran as a plain child "
                        + "process (time, CPU, memory and output limits only)", prlimit);
            }
            default -> throw new IllegalStateException(mode);
        }
    }

    /** An IOException naming {@code --sandbox MODE} unless the mode is auto, bwrap or none (checked without probing anything). */
    public static void checkMode(String mode) throws IOException {
        if (!List.of("auto", "bwrap", "none").contains(mode)) {
            throw new IOException("--sandbox " + mode + ": expected auto, bwrap or none");
        }
    }

    private static String bwrapProblem() {
        List<String> probe = List.of("bwrap", "--unshare-all", "--unshare-user", "--die-with-parent", "--ro-bind", "/", "/",
                "--proc", "/proc", "--dev", "/dev", "true");
        try {
            Process p = new ProcessBuilder(probe).redirectErrorStream(true).start();
            byte[] out = p.getInputStream().readNBytes(4096);
            if (!p.waitFor(20, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                return "bwrap did not answer within 20 s";
            }
            return p.exitValue() == 0 ? null : "bwrap cannot make namespaces here ("
                    + new String(out, java.nio.charset.StandardCharsets.UTF_8).trim().replaceAll("\\s+", " ") + ")";
        } catch (IOException e) {
            return "bwrap is not installed (Debian: apt-get install bubblewrap)";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        }
    }

    private static boolean works(List<String> cmd) {
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(10, TimeUnit.SECONDS) && p.exitValue() == 0;
        } catch (IOException e) {
            return false;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return false;
        }
    }

    public Kind kind() {
        return kind;
    }

    /** One line for the reports: which isolation the submissions ran under. */
    public String description() {
        return why + (prlimit ? "" : " (prlimit missing: no CPU, file-size or address-space limits)");
    }

    /**
     * The command that runs {@code java} (a list of arguments after the java binary, with the paths
     * {@link #IN}, {@link #OUT} and {@link #LIB}) for one child. In the fallback, those paths are
     * replaced by the real folders.
     */
    public List<String> command(Path in, Path out, Path lib, Limits limits, List<String> javaArgs) throws IOException {
        Path javaHome = Path.of(System.getProperty("java.home")).toRealPath();
        List<String> cmd = new ArrayList<>();
        if (prlimit) {
            cmd.addAll(List.of("prlimit", "--cpu=" + limits.cpuSeconds(), "--fsize=" + limits.fileBytes(), "--nofile=512",
                    "--core=0", "--as=" + limits.addressBytes(), "--"));
        }
        if (kind == Kind.NONE) {
            cmd.add(javaHome.resolve("bin/java").toString());
            for (String a : javaArgs) {
                cmd.add(a.replace(IN, in.toString()).replace(OUT, out.toString()).replace(LIB, lib.toString()));
            }
            return cmd;
        }
        cmd.addAll(List.of("bwrap", "--unshare-all", "--unshare-user", "--uid", "65534", "--gid", "65534",
                "--disable-userns", "--cap-drop", "ALL", "--die-with-parent", "--new-session", "--clearenv",
                "--hostname", "sandbox", "--setenv", "HOME", OUT, "--setenv", "LANG", "C.UTF-8",
                "--setenv", "PATH", javaHome.resolve("bin").toString()));
        for (String sys : List.of("/usr/lib", "/usr/lib64", "/usr/lib32", "/usr/share/zoneinfo")) {
            if (Files.isDirectory(Path.of(sys))) {
                cmd.addAll(List.of("--ro-bind", sys, sys));
            }
        }
        for (String l : List.of("/lib", "/lib64", "/lib32")) {
            Path p = Path.of(l);
            if (Files.isSymbolicLink(p)) {
                cmd.addAll(List.of("--symlink", Files.readSymbolicLink(p).toString(), l));
            } else if (Files.isDirectory(p)) {
                cmd.addAll(List.of("--ro-bind", l, l));
            }
        }
        cmd.addAll(List.of("--ro-bind", javaHome.toString(), javaHome.toString()));
        for (Path target : outsideLinks(javaHome)) {
            cmd.addAll(List.of("--ro-bind-try", target.toString(), target.toString()));
        }
        cmd.addAll(List.of("--proc", "/proc", "--dev", "/dev", "--size", Long.toString(limits.tmpBytes()), "--tmpfs", "/tmp",
                "--ro-bind", in.toString(), IN, "--ro-bind", lib.toString(), LIB, "--bind", out.toString(), OUT,
                "--chdir", OUT, "--", javaHome.resolve("bin/java").toString()));
        cmd.addAll(javaArgs);
        return cmd;
    }

    /**
     * Files the JDK links to outside its own folder and the system library folders (Debian keeps the
     * JDK's conf/ and security files under /etc/java-NN-openjdk): bound read-only so the JVM starts.
     */
    private static Set<Path> outsideLinks(Path javaHome) throws IOException {
        Set<Path> out = new LinkedHashSet<>();
        try (Stream<Path> walk = Files.walk(javaHome, 4)) {
            for (Path p : (Iterable<Path>) walk::iterator) {
                if (Files.isSymbolicLink(p)) {
                    try {
                        Path real = p.toRealPath();
                        if (!real.startsWith(javaHome) && !real.startsWith("/usr/lib") && Files.exists(real, LinkOption.NOFOLLOW_LINKS)) {
                            out.add(Files.isDirectory(real) ? real : real.getParent());
                        }
                    } catch (IOException e) {
                        // a dangling link: the JDK works without it
                    }
                }
            }
        }
        // a folder and a file inside it: keep the folder only
        out.removeIf(p -> out.stream().anyMatch(q -> !q.equals(p) && p.startsWith(q)));
        return out;
    }
}
