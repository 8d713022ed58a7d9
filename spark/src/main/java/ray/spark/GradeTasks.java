package ray.spark;

import java.io.IOException;
import java.io.Serializable;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;
import org.apache.spark.api.java.function.Function;
import org.apache.spark.broadcast.Broadcast;
import ray.grade.GradeOptions;
import ray.grade.Grader;
import ray.grade.Judge;
import ray.grade.Sandbox;
import ray.grade.Submission;
import ray.grade.SubmissionResult;
import ray.grade.TestSet;

/**
 * What {@code raytracer-spark grade} ships and runs: the test set as bytes (sent once per executor), one
 * task per submission, and on each executor JVM one {@link Grader} per test set (its sandbox chosen
 * there, since bubblewrap is a property of the executor's host, not the driver's).
 */
final class GradeTasks {

    private GradeTasks() {
    }

    /** The folders a rubric names, each shipped under this name (the rubric's own lines rewritten to match). */
    static final List<String> FOLDERS = List.of("framework", "checks", "scenes", "references");

    /**
     * A test set as the executors get it: its rubric with the four folder lines pointing at folders of the
     * same name beside it, and every file of those folders by {@code folder/relative/path}. Loading it on
     * an executor gives the driver's test set: the same items, limits, scenes and references.
     */
    static final class TestSetBundle implements Serializable {
        private static final long serialVersionUID = 1L;
        final String rubric;
        final Map<String, byte[]> files;
        /** SHA-256 of the rubric and the files: the executor cache's key. */
        final String key;

        private TestSetBundle(String rubric, Map<String, byte[]> files) {
            this.rubric = rubric;
            this.files = files;
            try {
                MessageDigest d = MessageDigest.getInstance("SHA-256");
                SceneBundle.update(d, rubric.getBytes(StandardCharsets.UTF_8));
                for (Map.Entry<String, byte[]> f : files.entrySet()) {
                    SceneBundle.update(d, f.getKey().getBytes(StandardCharsets.UTF_8));
                    SceneBundle.update(d, f.getValue());
                }
                this.key = SceneBundle.hex(d);
            } catch (NoSuchAlgorithmException e) {
                throw new IllegalStateException(e);
            }
        }

        /** The bundle of a test set the driver has loaded (so its rubric is known to be right). */
        static TestSetBundle of(TestSet set) throws IOException {
            StringBuilder rubric = new StringBuilder();
            for (String line : Files.readAllLines(set.root().resolve("rubric.txt"), StandardCharsets.UTF_8)) {
                String[] w = (line.indexOf('#') >= 0 ? line.substring(0, line.indexOf('#')) : line).trim().split("\\s+");
                // the same line count, so a line number in a message is the driver's
                rubric.append(FOLDERS.contains(w[0]) ? w[0] + " " + w[0] : line).append('\n');
            }
            Map<String, byte[]> files = new TreeMap<>();
            Path[] dirs = {set.framework(), set.checks(), set.scenes(), set.references()};
            for (int i = 0; i < dirs.length; i++) {
                try (Stream<Path> walk = Files.walk(dirs[i])) {
                    for (Path p : (Iterable<Path>) walk.sorted()::iterator) {
                        if (Files.isRegularFile(p)) {
                            files.put(FOLDERS.get(i) + "/" + dirs[i].relativize(p).toString().replace('\\', '/'), Files.readAllBytes(p));
                        }
                    }
                }
            }
            return new TestSetBundle(rubric.toString(), files);
        }

        long size() {
            return files.values().stream().mapToLong(b -> b.length).sum() + rubric.length();
        }

        /** Writes the test set into {@code dir} (rubric.txt and the four folders) and loads it from there. */
        TestSet writeTo(Path dir) throws IOException {
            for (String f : FOLDERS) {
                Files.createDirectories(dir.resolve(f));
            }
            Files.writeString(dir.resolve("rubric.txt"), rubric, StandardCharsets.UTF_8);
            for (Map.Entry<String, byte[]> f : files.entrySet()) {
                Path target = dir.resolve(f.getKey()).normalize();
                if (!target.startsWith(dir)) {
                    throw new IOException("a test set file outside its folder: " + f.getKey());
                }
                Files.createDirectories(target.getParent());
                Files.write(target, f.getValue());
            }
            return TestSet.load(dir);
        }
    }

    /** One task: the {@code index}-th submission of the command line, its .java files read on the driver. */
    record Hand(int index, Submission submission) implements Serializable {
    }

    /**
     * A task's result: the grader's result and the report's images (file name to bytes), or the one line
     * saying why the grader itself could not work on that executor (no JDK, disk full, no bubblewrap with
     * {@code --sandbox bwrap}); where it ran.
     */
    record Graded(int index, SubmissionResult result, Map<String, byte[]> images, String failure, String executor)
            implements Serializable {
    }

    /**
     * Grades one submission on an executor with the JVM's grader for the test set. Nothing a submission
     * does makes the grader throw (a hang, a crash or hostile code is a result), so a failure here is the
     * executor's and comes back as a message for the driver to report, not as a task failure retried
     * four times.
     */
    static final class Grade implements Function<Hand, Graded> {
        private static final long serialVersionUID = 1L;
        private final Broadcast<TestSetBundle> set;
        private final String sandbox;
        private final String work;

        Grade(Broadcast<TestSetBundle> set, String sandbox, String work) {
            this.set = set;
            this.sandbox = sandbox;
            this.work = work;
        }

        @Override
        public Graded call(Hand h) {
            org.apache.spark.SparkEnv env = org.apache.spark.SparkEnv.get();
            String executor = env == null ? "" : env.executorId() + " (" + env.blockManager().blockManagerId().host() + ")";
            Path report = null;
            try {
                Grader grader = station(set.value(), sandbox, work).grader;
                report = Files.createTempDirectory(grader.work(), "report-");
                SubmissionResult r = grader.grade(h.submission(), report);
                return new Graded(h.index(), r, images(report), null, executor);
            } catch (IOException | RuntimeException e) {
                return new Graded(h.index(), null, null, "the grader failed on executor " + executor + ": "
                        + ray.app.RenderReport.message(e), executor);
            } finally {
                if (report != null) {
                    SceneBundle.deleteTree(report);
                }
            }
        }

        /** The files the grader wrote into a report folder (pictures, flat), by name. */
        private static Map<String, byte[]> images(Path dir) throws IOException {
            Map<String, byte[]> out = new TreeMap<>();
            try (Stream<Path> s = Files.list(dir)) {
                for (Path p : (Iterable<Path>) s.sorted()::iterator) {
                    if (Files.isRegularFile(p, LinkOption.NOFOLLOW_LINKS)) {
                        out.put(p.getFileName().toString(), Files.readAllBytes(p));
                    }
                }
            }
            return out;
        }
    }

    // ---- the executor side: one grader per (test set, sandbox, scratch folder) and JVM ----

    /** A test set unpacked on this JVM and its grader; everything under {@code home}, deleted when the JVM ends. */
    private record Station(Path home, Grader grader) {
    }

    private static final Map<String, Station> STATIONS = new TreeMap<>();
    private static boolean hooked;

    private static Station station(TestSetBundle b, String mode, String work) throws IOException {
        String key = b.key + "\n" + mode + "\n" + work;
        synchronized (STATIONS) {
            Station s = STATIONS.get(key);
            if (s != null) {
                return s;
            }
            Path home = Files.createTempDirectory(GradeOptions.scratch(work == null ? null : Path.of(work)), "raytracer-spark-grade-");
            try {
                TestSet set = b.writeTo(Files.createDirectories(home.resolve("tests")));
                s = new Station(home, new Grader(set, Sandbox.choose(mode), Judge.standard(), Files.createDirectories(home.resolve("work"))));
            } catch (IOException | RuntimeException e) {
                SceneBundle.deleteTree(home);
                throw e;
            }
            STATIONS.put(key, s);
            if (!hooked) {
                hooked = true;
                Runtime.getRuntime().addShutdownHook(new Thread(GradeTasks::release, "raytracer-spark-grade-cleanup"));
            }
            return s;
        }
    }

    /**
     * Deletes every test set and scratch folder this JVM unpacked (a JVM's end does it too; the driver
     * calls it after a job, which in local mode ran in its own JVM).
     */
    static void release() {
        List<Station> all;
        synchronized (STATIONS) {
            all = new ArrayList<>(STATIONS.values());
            STATIONS.clear();
        }
        for (Station s : all) {
            try {
                s.grader.close();
            } catch (IOException e) {
                // deleted with the rest below
            }
            SceneBundle.deleteTree(s.home);
        }
    }
}
