package ray.grade;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import ray.grade.child.Harness;

/**
 * Grades one submission against one test set: the grader's API (the command line, the class report,
 * Gradescope and Spark all call {@link #grade}). The submission is compiled and run in its own child JVM
 * inside the {@link Sandbox} ({@link Harness} is what runs there); its images are judged here, in the
 * grader's JVM, against references the child never sees. Thread-safe: grade many submissions at once.
 */
public final class Grader {

    /** Time allowed for compiling a submission, on top of the items' own limits. */
    static final double COMPILE_SECONDS = 90;
    /** Most child JVMs started for one submission (each crash or time-out restarts from the next item). */
    static final int MAX_STARTS = 12;

    private final TestSet set;
    private final Sandbox sandbox;
    private final Judge judge;
    private final Path work;
    private Path lib;

    /**
     * @param work a folder for scratch space (each submission gets a fresh folder inside, deleted after)
     */
    public Grader(TestSet set, Sandbox sandbox, Judge judge, Path work) {
        this.set = set;
        this.sandbox = sandbox;
        this.judge = judge;
        this.work = work;
    }

    public TestSet testSet() {
        return set;
    }

    public Sandbox sandbox() {
        return sandbox;
    }

    /** The scratch folder given to the constructor. */
    public Path work() {
        return work;
    }

    /**
     * Grades {@code submission}; its images go into {@code reportDir} (created), named after the scenes.
     * Never throws for anything the submission does; an IOException means the grader itself could not
     * work (disk full, no JDK).
     */
    public SubmissionResult grade(Submission submission, Path reportDir) throws IOException {
        long t0 = System.nanoTime();
        Files.createDirectories(reportDir);
        Path shared = sharedLib();
        Path dir = Files.createTempDirectory(Files.createDirectories(work), "sub-");
        try {
            return grade(submission, reportDir, shared, dir, t0);
        } finally {
            deleteTree(dir);
        }
    }

    private SubmissionResult grade(Submission sub, Path reportDir, Path shared, Path dir, long t0) throws IOException {
        Path in = Files.createDirectories(dir.resolve("in"));
        Path out = Files.createDirectories(dir.resolve("out"));
        Files.createDirectories(out.resolve("images"));
        List<String> notes = new ArrayList<>(sub.notes());
        // the handout's files, the submission's replacing those of the same name
        Path src = Files.createDirectories(in.resolve("src"));
        Path framework = Files.createDirectories(in.resolve("framework"));
        Path checks = Files.createDirectories(in.resolve("checks"));
        Map<String, Path> checkFiles = TestSet.javaFiles(set.checks());
        for (Map.Entry<String, Path> f : TestSet.javaFiles(set.framework()).entrySet()) {
            Files.copy(f.getValue(), src.resolve(f.getKey()));
            Files.copy(f.getValue(), framework.resolve(f.getKey()));
        }
        for (Map.Entry<String, Path> f : checkFiles.entrySet()) {
            Files.copy(f.getValue(), checks.resolve(f.getKey()));
        }
        List<String> submitted = new ArrayList<>();
        for (Map.Entry<String, byte[]> f : sub.files().entrySet()) {
            if (checkFiles.containsKey(f.getKey())) {
                notes.add(f.getKey() + ": the grader has a class of this name, left out");
                continue;
            }
            Files.write(src.resolve(f.getKey()), f.getValue());
            submitted.add(f.getKey());
        }
        if (submitted.isEmpty()) {
            notes.add("the hand-in has no .java files: graded the handout as it is");
        }
        List<TestSet.Item> items = set.items();
        // the folders as the child sees them: mounted at fixed places in the sandbox, where they are without it
        boolean boxed = sandbox.kind() == Sandbox.Kind.BWRAP;
        String inDir = boxed ? Sandbox.IN : in.toString(), outDir = boxed ? Sandbox.OUT : out.toString();
        String libDir = boxed ? Sandbox.LIB : shared.toString();
        StringBuilder plan = new StringBuilder();
        plan.append("src\t").append(inDir).append("/src\n");
        plan.append("framework\t").append(inDir).append("/framework\n");
        plan.append("checks\t").append(inDir).append("/checks\n");
        plan.append("out\t").append(outDir).append('\n');
        plan.append("classpath\t").append(libDir).append("/vecmath.jar\n");
        plan.append("submitted\t").append(String.join(",", submitted)).append('\n');
        plan.append("heap-mb\t").append(set.limits().heapMb()).append('\n');
        if (set.render() != null) {
            plan.append("render\t").append(set.render()).append('\n');
        }
        for (TestSet.Item i : items) {
            plan.append("item\t").append(i.id()).append('\t');
            if (i.kind() == TestSet.Kind.CHECK) {
                plan.append("check\t").append(i.target());
            } else {
                plan.append("scene\t").append(libDir).append("/scenes/").append(i.target()).append('\t')
                        .append(outDir).append("/images/").append(TestSet.pngName(i.target())).append('\t').append(i.renders());
            }
            plan.append('\t').append(timeoutMs(i)).append('\n');
        }
        Files.writeString(in.resolve("plan.txt"), plan, StandardCharsets.UTF_8);

        // run, restarting after the item a crash or time-out ended
        Map<String, String[]> ends = new HashMap<>();
        Map<String, String> death = new HashMap<>();
        ByteArrayOutputStream console = new ByteArrayOutputStream();
        long deadline = System.nanoTime() + (long) ((set.limits().totalSeconds() + COMPILE_SECONDS) * 1e9);
        int start = 0;
        for (int starts = 0; start < items.size() && starts < MAX_STARTS; starts++) {
            double budget = (start == 0 ? COMPILE_SECONDS : 0) + 15;
            for (int i = start; i < items.size(); i++) {
                budget += budgetMs(items.get(i)) / 1000.0;
            }
            double left = (deadline - System.nanoTime()) / 1e9;
            if (left <= 1) {
                break;
            }
            Run run = runChild(in, out, shared, start, Math.min(budget, left), console);
            Log log = Log.read(out.resolve("results.txt"));
            ends.putAll(log.ends);
            int last = -1;
            for (int i = start; i < items.size(); i++) {
                if (log.begun.contains(items.get(i).id())) {
                    last = i;
                }
            }
            if (last < 0) {
                // nothing ran at all: the JVM did not start or the compile step died
                String why = run.killed ? "the compile step did not finish in time" : "the child JVM ended before any test (exit status "
                        + run.exit + ")" + (log.compileFailed != null ? ": " + log.compileFailed : "");
                for (int i = start; i < items.size(); i++) {
                    death.put(items.get(i).id(), why);
                }
                break;
            }
            String lastId = items.get(last).id();
            if (!ends.containsKey(lastId)) {
                death.put(lastId, deathMessage(run, log.exited.contains(lastId), set.limits()));
            }
            start = last + 1;
            if (run.exit == 0 && !run.killed) {
                break;
            }
        }
        notes.addAll(Log.read(out.resolve("results.txt")).compileNotes);

        // judge
        List<TestResult> results = new ArrayList<>();
        Map<String, String> failedMethods = new LinkedHashMap<>();
        double renderSeconds = 0;
        for (TestSet.Item i : items) {
            String output = readCapped(out.resolve(i.id() + ".out"), 20 * 1024);   // the harness keeps 16 KB and a note
            String[] end = ends.get(i.id());
            TestResult r;
            if (end == null) {
                String why = death.getOrDefault(i.id(), "not run: the submission's earlier tests used up its time ("
                        + (int) set.limits().totalSeconds() + " s in all)");
                r = new TestResult(i.id(), i.title(), i.group(), i.kind(), 0, i.points(),
                        why.startsWith("timed out") || why.startsWith("not run") ? "timeout" : "crashed", why, output, 0, null);
            } else {
                double secs = Long.parseLong(end[1]) / 1e9;
                if (i.kind() == TestSet.Kind.CHECK) {
                    boolean ok = end[0].equals("PASS");
                    r = new TestResult(i.id(), i.title(), i.group(), i.kind(), ok ? i.points() : 0, i.points(),
                            ok ? "passed" : end[0].equals("TIMEOUT") ? "timeout" : "failed", ok ? "" : end[2], output, secs, null);
                } else {
                    renderSeconds += secs;
                    r = judgeScene(i, end, out, reportDir, output, secs);
                }
            }
            if (i.kind() == TestSet.Kind.CHECK && !r.passed()) {
                String m = methodNamed(r.message());
                if (m != null) {
                    failedMethods.putIfAbsent(m, r.name());
                }
            }
            results.add(r);
        }
        // a scene's message names the methods it uses whose own checks fail: fix those first
        for (int k = 0; k < results.size(); k++) {
            TestResult r = results.get(k);
            TestSet.Item i = items.get(k);
            if (i.kind() == TestSet.Kind.SCENE && !r.passed() && (!i.uses().isEmpty() || !failedMethods.isEmpty())) {
                List<String> suspects = new ArrayList<>();
                for (String m : i.uses()) {
                    if (failedMethods.containsKey(m)) {
                        suspects.add(m);
                    }
                }
                if (suspects.isEmpty()) {
                    // every scene goes through the camera, trace and the render loop too: any failing method may be at fault
                    suspects.addAll(failedMethods.keySet());
                }
                String hint = suspects.isEmpty() ? " This scene uses " + String.join(", ", i.uses()) + "."
                        : " Fix first: " + String.join(", ", suspects) + " (" + (suspects.size() == 1 ? "its" : "their")
                        + " own tests fail).";
                results.set(k, new TestResult(r.id(), r.name(), r.group(), r.kind(), r.score(), r.maxScore(), r.status(),
                        r.message() + hint, r.output(), r.seconds(), r.images()));
            }
        }
        double score = results.stream().mapToDouble(TestResult::score).sum();
        String consoleText = console.toString(StandardCharsets.UTF_8);
        return new SubmissionResult(sub.name(), round(score), set.maxScore(), results, (System.nanoTime() - t0) / 1e9,
                renderSeconds, sandbox.description(), notes, consoleText);
    }

    /** "Sphere.intersects: ..." -> "Sphere.intersects" when that is one of the test set's methods. */
    String methodNamed(String message) {
        for (String m : set.methods()) {
            if (message.startsWith(m)) {
                return m;
            }
        }
        int colon = message.indexOf(':');
        return colon > 0 && message.substring(0, colon).matches("[A-Za-z_$][\\w$]*\\.[A-Za-z_$][\\w$]*")
                ? message.substring(0, colon) : null;
    }

    private TestResult judgeScene(TestSet.Item i, String[] end, Path out, Path reportDir, String output, double secs)
            throws IOException {
        String base = TestSet.pngName(i.target()).replace(".png", "");
        Path refFile = set.references().resolve(TestSet.pngName(i.target()));
        BufferedImage ref = ImageIO.read(refFile.toFile());
        Path png = out.resolve("images").resolve(TestSet.pngName(i.target()));
        String refName = base + "-reference.png";
        Files.copy(refFile, reportDir.resolve(refName), StandardCopyOption.REPLACE_EXISTING);
        BufferedImage yours = end[0].equals("TIMEOUT") ? null : readCandidate(png, ref.getWidth(), ref.getHeight());
        if (yours == null) {
            String why = end[0].equals("PASS") ? "no image (or not a " + ref.getWidth() + "x" + ref.getHeight() + " PNG) came out"
                    : end[2];
            return new TestResult(i.id(), i.title(), i.group(), i.kind(), 0, i.points(),
                    end[0].equals("TIMEOUT") ? "timeout" : "failed", why, output, secs,
                    new TestResult.Images(refName, null, null, "none", Map.of()));
        }
        String yoursName = base + "-yours.png";
        ImageIO.write(yours, "png", reportDir.resolve(yoursName).toFile());
        Judge.Verdict v;
        if (i.stochastic()) {
            List<BufferedImage> refs = new ArrayList<>(), cands = new ArrayList<>();
            for (Path p : TestSet.referenceRenders(set.references(), i.target())) {
                refs.add(ImageIO.read(p.toFile()));
            }
            for (int k = 1; k <= i.renders(); k++) {
                BufferedImage c = k == 1 ? yours : readCandidate(out.resolve("images").resolve(TestSet.renderName(i.target(), k)),
                        ref.getWidth(), ref.getHeight());
                if (c != null) {
                    cands.add(c);
                }
            }
            v = cands.size() < 2 ? judge.judge(ref, yours, true) : judge.judge(refs, cands);
        } else {
            v = judge.judge(ref, yours, false);
        }
        String diffName = null;
        if (v.heatMap() != null) {
            diffName = base + "-difference.png";
            ImageIO.write(v.heatMap(), "png", reportDir.resolve(diffName).toFile());
        }
        TestResult.Images images = new TestResult.Images(refName, yoursName, diffName, v.kind(), v.metrics());
        if (!end[0].equals("PASS")) {
            // the render finished but some pixel was null or NaN: no credit, the harness says which
            return new TestResult(i.id(), i.title(), i.group(), i.kind(), 0, i.points(), "failed", end[2], output, secs, images);
        }
        double score = round(i.points() * v.fraction());
        String status = v.pass() ? "passed" : score > 0 ? "partial" : "failed";
        return new TestResult(i.id(), i.title(), i.group(), i.kind(), v.pass() ? i.points() : score, i.points(), status,
                v.pass() ? "" : v.message(), output, secs, images);
    }

    /**
     * The submission's PNG, read only when it is a regular file (not a link the child planted to some
     * other file of the grader's) of the expected size, so a hostile file cannot make the grader decode
     * a huge image.
     */
    private static BufferedImage readCandidate(Path png, int w, int h) {
        try {
            BasicFileAttributes a = Files.readAttributes(png, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
            if (!a.isRegularFile() || a.size() > 64L << 20) {
                return null;
            }
            try (ImageInputStream iis = ImageIO.createImageInputStream(png.toFile())) {
                var readers = ImageIO.getImageReaders(iis);
                if (!readers.hasNext()) {
                    return null;
                }
                ImageReader r = readers.next();
                try {
                    r.setInput(iis);
                    if (r.getWidth(0) != w || r.getHeight(0) != h) {
                        return null;
                    }
                    return r.read(0);
                } finally {
                    r.dispose();
                }
            }
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** An item's time limit (a stochastic scene's is per render: {@link #budgetMs} counts them all). */
    private long timeoutMs(TestSet.Item i) {
        return (long) (1000 * (i.kind() == TestSet.Kind.CHECK ? set.limits().checkSeconds() : set.limits().sceneSeconds()));
    }

    private long budgetMs(TestSet.Item i) {
        return timeoutMs(i) * i.renders();
    }

    private static String deathMessage(Run run, boolean exited, TestSet.Limits limits) {
        if (run.killed) {
            return "timed out: the program did not finish (killed after the whole run's time limit)";
        }
        if (exited) {
            return "the program called System.exit(" + run.exit + ") during this test (never call System.exit)";
        }
        return switch (run.exit) {
            case 124 -> "timed out";
            case 137 -> "killed (signal 9): the program used more memory than its " + limits.heapMb() + " MB heap allows, "
                    + "or was stopped";
            case 152 -> "killed: the program used up its CPU time limit (an endless loop?)";
            case 134 -> "the JVM crashed (abort)";
            default -> "the program ended during this test (exit status " + run.exit + ")";
        };
    }

    /** One child JVM's run. */
    private record Run(int exit, boolean killed) {
    }

    private Run runChild(Path in, Path out, Path shared, int start, double seconds, ByteArrayOutputStream console) throws IOException {
        TestSet.Limits l = set.limits();
        List<String> java = List.of("-Xmx" + l.heapMb() + "m", "-Xss2m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1",
                "-XX:ActiveProcessorCount=1", "-XX:MaxMetaspaceSize=256m", "-XX:ReservedCodeCacheSize=64m",
                "-XX:CompressedClassSpaceSize=128m", "-XX:MaxDirectMemorySize=32m", "-XX:-UsePerfData",
                "-Xshare:auto", "-Djava.awt.headless=true", "-Djava.io.tmpdir=/tmp", "-Dfile.encoding=UTF-8",
                "-cp", Sandbox.LIB + "/harness:" + Sandbox.LIB + "/vecmath.jar",
                Harness.class.getName(), Sandbox.IN + "/plan.txt", Integer.toString(start));
        long cpu = (long) Math.ceil(seconds) + 30;
        List<String> cmd = sandbox.command(in, out, shared, new Sandbox.Limits(cpu, 64L << 20, 64L << 20, 6L << 30), java);
        if (sandbox.kind() == Sandbox.Kind.NONE) {
            Files.createDirectories(out.resolve("tmp"));
            cmd = cmd.stream().map(a -> a.equals("-Djava.io.tmpdir=/tmp") ? "-Djava.io.tmpdir=" + out.resolve("tmp") : a).toList();
        }
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(out.toFile()).redirectErrorStream(true);
        if (sandbox.kind() == Sandbox.Kind.NONE) {
            pb.environment().clear();
            pb.environment().put("HOME", out.toString());
            pb.environment().put("LANG", "C.UTF-8");
        }
        Process p = pb.start();
        p.getOutputStream().close();
        int cap = l.outputKb() * 1024;
        Thread pump = new Thread(() -> pump(p.getInputStream(), console, cap), "grade-output");
        pump.setDaemon(true);
        pump.start();
        boolean killed = false;
        try {
            if (!p.waitFor((long) (seconds * 1000), TimeUnit.MILLISECONDS)) {
                killed = true;
            }
        } catch (InterruptedException e) {
            killed = true;
            Thread.currentThread().interrupt();
        }
        if (killed) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly();
            try {
                p.waitFor(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        // in the fallback a child could leave processes behind; bubblewrap's pid namespace takes them with it
        p.descendants().forEach(ProcessHandle::destroyForcibly);
        try {
            pump.join(5000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return new Run(killed ? -1 : p.exitValue(), killed);
    }

    private static void pump(InputStream in, ByteArrayOutputStream console, int cap) {
        byte[] buf = new byte[8192];
        long dropped = 0;
        try (in) {
            int n;
            while ((n = in.read(buf)) > 0) {
                synchronized (console) {
                    int keep = Math.max(0, Math.min(n, cap - console.size()));
                    console.write(buf, 0, keep);
                    dropped += n - keep;
                }
            }
        } catch (IOException e) {
            // the child is gone
        }
        if (dropped > 0) {
            synchronized (console) {
                console.writeBytes(("\n[... " + dropped + " more bytes of output left out: the limit is " + cap / 1024
                        + " KB]\n").getBytes(StandardCharsets.UTF_8));
            }
        }
    }

    /** The harness classes, the framework's vecmath jar and the scenes, prepared once for every child. */
    private synchronized Path sharedLib() throws IOException {
        if (lib != null) {
            return lib;
        }
        Path d = Files.createTempDirectory(Files.createDirectories(work), "lib-");
        Path h = Files.createDirectories(d.resolve("harness/ray/grade/child"));
        for (String c : List.of("Harness.class", "Harness$Capture.class")) {
            try (InputStream s = Harness.class.getResourceAsStream(c)) {
                if (s == null) {
                    throw new IOException("the grader's own class " + c + " is missing from its class path");
                }
                Files.copy(s, h.resolve(c));
            }
        }
        try {
            Path jar = Path.of(javax.vecmath.Vector3d.class.getProtectionDomain().getCodeSource().getLocation().toURI());
            Files.copy(jar, d.resolve("vecmath.jar"));
        } catch (java.net.URISyntaxException | NullPointerException e) {
            throw new IOException("cannot find the vecmath jar on the grader's class path");
        }
        // the scenes and what they read, without any image that has a reference's name
        Path scenes = Files.createDirectories(d.resolve("scenes"));
        try (Stream<Path> s = Files.walk(set.scenes())) {
            for (Path p : (Iterable<Path>) s::iterator) {
                Path rel = set.scenes().relativize(p);
                if (Files.isDirectory(p) || p.getFileName().toString().toLowerCase(java.util.Locale.ROOT).endsWith(".png")) {
                    continue;
                }
                Files.createDirectories(scenes.resolve(rel).getParent());
                Files.copy(p, scenes.resolve(rel));
            }
        }
        lib = d;
        return d;
    }

    /** Deletes the scratch space this grader made (the shared library folder); submissions' folders go as they finish. */
    public synchronized void close() throws IOException {
        if (lib != null) {
            deleteTree(lib);
            lib = null;
        }
    }

    static String readCapped(Path p, int cap) {
        try {
            BasicFileAttributes a = Files.readAttributes(p, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
            if (!a.isRegularFile()) {
                return "";
            }
            try (InputStream in = Files.newInputStream(p)) {
                byte[] b = in.readNBytes(cap);
                return new String(b, StandardCharsets.UTF_8) + (a.size() > cap ? "\n[... output cut at " + cap / 1024 + " KB]" : "");
            }
        } catch (IOException e) {
            return "";
        }
    }

    static double round(double v) {
        return Math.round(v * 100) / 100.0;
    }

    static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir, LinkOption.NOFOLLOW_LINKS)) {
            return;
        }
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : (Iterable<Path>) s.sorted(Comparator.reverseOrder())::iterator) {
                // the child may have made a folder unwritable; make it writable to empty it
                if (Files.isDirectory(p, LinkOption.NOFOLLOW_LINKS)) {
                    p.toFile().setWritable(true);
                }
                Files.deleteIfExists(p);
            }
        }
    }

    /** The results file the harness wrote, read without following links and capped. */
    static final class Log {
        final Map<String, String[]> ends = new HashMap<>();
        final java.util.Set<String> begun = new java.util.HashSet<>();
        final java.util.Set<String> exited = new java.util.HashSet<>();
        final List<String> compileNotes = new ArrayList<>();
        String compileFailed;

        static Log read(Path file) {
            Log log = new Log();
            for (String line : readCapped(file, 4 << 20).split("\n")) {
                String[] f = line.split(" ", 5);
                switch (f[0]) {
                    case "BEGIN" -> {
                        if (f.length > 1) {
                            log.begun.add(f[1]);
                        }
                    }
                    case "EXIT" -> {
                        if (f.length > 1) {
                            log.exited.add(f[1]);
                        }
                    }
                    case "END" -> {
                        if (f.length >= 4 && f[3].matches("\\d{1,18}")) {
                            log.ends.put(f[1], new String[] {f[2], f[3], f.length > 4 ? Harness.unescape(f[4]) : ""});
                        }
                    }
                    case "COMPILE" -> {
                        String[] g = line.split(" ", 4);
                        if (g.length >= 2 && g[1].equals("FAILED")) {
                            log.compileFailed = Harness.unescape(line.substring("COMPILE FAILED".length()).trim());
                            log.compileNotes.add("your code did not compile: " + log.compileFailed);
                        } else if (g.length >= 3 && g[1].equals("REVERTED")) {
                            log.compileNotes.add((g[2].equals("*") ? "your files" : g[2]) + " did not compile, so the handout's "
                                    + (g[2].equals("*") ? "files were" : g[2] + " was") + " graded instead: "
                                    + (g.length > 3 ? Harness.unescape(g[3]) : ""));
                        } else if (g.length >= 3 && g[1].equals("DROPPED")) {
                            log.compileNotes.add(g[2] + " did not compile and was left out: " + (g.length > 3 ? Harness.unescape(g[3]) : ""));
                        }
                    }
                    case "CHECKS-FAILED" -> {
                        String[] g = line.split(" ", 3);
                        log.compileNotes.add("the grader's checks in " + (g.length > 1 ? g[1] : "?")
                                + " do not compile against your classes: " + (g.length > 2 ? Harness.unescape(g[2]) : ""));
                    }
                    default -> {
                    }
                }
            }
            return log;
        }
    }
}
