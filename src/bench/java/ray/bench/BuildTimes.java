package ray.bench;

import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import ray.Scene;
import ray.accel.Bvh;
import ray.parse.Parser;

/**
 * {@code gradle buildTimes}: how long parsing a scene and building its BVH take in one JVM, first time
 * and best of several, and the hash of each tree built ({@link Bvh#structureHash}, in a JVM run with
 * {@code -Dray.bvh.hash=true}). A change to the builder that means to build the same trees runs this in
 * both checkouts and compares the hashes; the times are what the change bought. The first parse and the
 * first build include the JIT's warm-up, as in a render; the best is the steady state. Every build of one
 * scene must give the same hash (the builder is deterministic, whatever the thread count), and a line
 * says so when one does not.
 *
 * <pre>
 * java -Dray.bvh.hash=true ray.bench.BuildTimes [--parses N] [--builds N] scene.txt ...
 * </pre>
 */
public final class BuildTimes {

    private BuildTimes() {
    }

    /**
     * One scene's numbers: milliseconds of the first and the best parse and build, nodes, primitives, the
     * hash. (A class, not a record: Gradle 4.4.1's class reader calls record classes malformed.)
     */
    static final class Row {
        final String scene;
        final double parseFirst, parseBest, buildFirst, buildBest;
        final int nodes, primitives;
        final long hash;
        final boolean deterministic;

        Row(String scene, double parseFirst, double parseBest, double buildFirst, double buildBest, int nodes, int primitives,
            long hash, boolean deterministic) {
            this.scene = scene;
            this.parseFirst = parseFirst;
            this.parseBest = parseBest;
            this.buildFirst = buildFirst;
            this.buildBest = buildBest;
            this.nodes = nodes;
            this.primitives = primitives;
            this.hash = hash;
            this.deterministic = deterministic;
        }
    }

    static Row measure(Path scene, int parses, int builds) throws Exception {
        double pFirst = 0, pBest = Double.POSITIVE_INFINITY;
        Scene s = null;
        for (int k = 0; k < parses; k++) {
            long t0 = System.nanoTime();
            s = Parser.parse(scene);
            double ms = (System.nanoTime() - t0) / 1e6;
            pFirst = k == 0 ? ms : pFirst;
            pBest = Math.min(pBest, ms);
        }
        double bFirst = 0, bBest = Double.POSITIVE_INFINITY;
        long hash = 0;
        boolean same = true;
        Bvh bvh = null;
        for (int k = 0; k < builds; k++) {
            long t0 = System.nanoTime();
            bvh = Bvh.build(s.surfaces, s);
            double ms = (System.nanoTime() - t0) / 1e6;
            bFirst = k == 0 ? ms : bFirst;
            bBest = Math.min(bBest, ms);
            same &= k == 0 || bvh.structureHash() == hash;
            hash = bvh.structureHash();
        }
        return new Row(scene.toString(), pFirst, pBest, bFirst, bBest, bvh.nodeCount(), bvh.primitiveCount(), hash, same);
    }

    static void print(List<Row> rows, PrintStream out) {
        out.println("| scene | parse ms, first / best | build ms, first / best | inner nodes | primitives | tree hash |");
        out.println("|---|---:|---:|---:|---:|---|");
        for (Row r : rows) {
            out.println(String.format(Locale.ROOT, "| %s | %.1f / %.1f | %.1f / %.1f | %,d | %,d | %s |", r.scene, r.parseFirst,
                    r.parseBest, r.buildFirst, r.buildBest, r.nodes, r.primitives,
                    r.hash == 0 ? "- (run with -Dray.bvh.hash=true)" : String.format("%016x", r.hash)
                            + (r.deterministic ? "" : " NOT THE SAME IN EVERY BUILD")));
        }
    }

    public static void main(String[] args) throws Exception {
        int parses = 1, builds = 5;
        List<Path> scenes = new ArrayList<>();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--parses" -> parses = Math.max(1, Integer.parseInt(args[++i]));
                case "--builds" -> builds = Math.max(1, Integer.parseInt(args[++i]));
                default -> scenes.add(Path.of(args[i]));
            }
        }
        if (scenes.isEmpty()) {
            System.err.println("usage: BuildTimes [--parses N] [--builds N] scene.txt ...");
            System.exit(2);
        }
        List<Row> rows = new ArrayList<>();
        for (Path p : scenes) {
            try {
                rows.add(measure(p, parses, builds));
            } catch (ray.parse.SceneFormatException | java.io.IOException e) {
                System.err.println(e.getMessage());   // a scene that does not read: its one line, as the renderer says it
                System.exit(1);
            }
        }
        System.out.println("JVM: " + String.join(" ", java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments())
                + "; " + Runtime.getRuntime().availableProcessors() + " processor(s)");
        System.out.println();
        print(rows, System.out);
        boolean bad = false;
        for (Row r : rows) {
            bad |= !r.deterministic;
        }
        if (bad) {
            System.exit(1);
        }
    }
}
