package ray.app;

import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Whether a standard stream is a terminal. Java only offers {@code System.console()}, which asks
 * about standard input <em>and</em> output together; the progress line needs stderr alone
 * ({@code raytracer s.txt > log} still shows progress, {@code raytracer s.txt 2> log} keeps the log
 * clean). The launcher script tests {@code [ -t 2 ]} and passes {@code -Draytracer.stderrTty=true|false};
 * without it (plain {@code java RayTracer}) Linux tells through {@code /proc/self/fd/N}, and elsewhere
 * the console is the best guess.
 */
final class Terminal {

    private Terminal() {
    }

    /** Is stderr a terminal? */
    static boolean stderr() {
        String p = System.getProperty("raytracer.stderrTty");
        if (p != null && !p.isEmpty()) {
            return Boolean.parseBoolean(p);
        }
        return isTerminal(2);
    }

    /** Is stdout a terminal? */
    static boolean stdout() {
        String p = System.getProperty("raytracer.stdoutTty");
        if (p != null && !p.isEmpty()) {
            return Boolean.parseBoolean(p);
        }
        return isTerminal(1);
    }

    private static boolean isTerminal(int fd) {
        try {
            String target = Files.readSymbolicLink(Path.of("/proc/self/fd/" + fd)).toString();
            return target.startsWith("/dev/pts/") || target.startsWith("/dev/tty") || target.equals("/dev/console");
        } catch (java.io.IOException | RuntimeException e) {
            return System.console() != null;      // not Linux
        }
    }
}
