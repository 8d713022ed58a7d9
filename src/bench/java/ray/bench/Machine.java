package ray.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/** What the machine is and what it gives right now: the benchmark prints these beside its tables. */
final class Machine {

    private Machine() {
    }

    static String loadAverage() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).trim().split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }

    static String cpuName() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (l.startsWith("model name")) {
                    return l.substring(l.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            // not Linux
        }
        return System.getProperty("os.arch");
    }

    /**
     * How many cores' worth of throughput the machine gives right now, like run_peers.sh's parcheck:
     * the wall time of two threads each spinning a fixed loop, over the time of one (1.0: two free
     * cores; 2.0: one).
     */
    static double parallelCheck() throws InterruptedException {
        spin(20_000_000);   // compile it first
        long t0 = System.nanoTime();
        spin(200_000_000);
        long t1 = System.nanoTime();
        Thread a = new Thread(() -> spin(200_000_000)), b = new Thread(() -> spin(200_000_000));
        a.start();
        b.start();
        a.join();
        b.join();
        long t2 = System.nanoTime();
        return (double) (t2 - t1) / (t1 - t0);
    }

    private static volatile long sink;

    private static void spin(long n) {
        long x = 1;
        for (long i = 0; i < n; i++) {
            x = x * 6364136223846793005L + 1442695040888963407L;
        }
        sink = x;
    }
}
