package ray.grade.child;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintStream;
import java.lang.reflect.Array;
import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * The grader's side inside a submission's child JVM (run in the sandbox, never in the grader's JVM). It
 * compiles the submission, then runs the items of its plan one by one, each in its own thread with a
 * time limit, and appends to the results file as it goes:
 * <pre>
 * COMPILE OK | COMPILE REVERTED file message | COMPILE DROPPED file message | COMPILE FAILED message
 * CHECKS-FAILED class message        (a check file that does not compile against the submission)
 * BEGIN id
 * END id PASS|FAIL|TIMEOUT nanos message
 * EXIT id                            (the program called System.exit during item id)
 * </pre>
 * Messages are escaped onto one line ({@code \n}, {@code \t}, {@code \\}). On a time-out it halts the JVM
 * at once (a runaway thread cannot be stopped) and the grader starts a new child from the next item;
 * anything that kills the JVM mid-item (System.exit, a crash) leaves a BEGIN without an END, which the
 * grader reports on that item. Depends on the JDK alone (and javax.vecmath, the framework's own library).
 *
 * <p>Plan file, tab-separated: {@code src DIR}, {@code checks DIR}, {@code out DIR}, {@code classpath PATH},
 * {@code render CLASS.METHOD}, {@code heap-mb N}, {@code item ID check CLASS.METHOD TIMEOUT_MS},
 * {@code item ID scene SCENE_PATH PNG_PATH RENDERS TIMEOUT_MS} (the limit is per render).
 */
public final class Harness {

    private final Map<String, String> conf = new LinkedHashMap<>();
    private final List<String[]> items = new ArrayList<>();
    private PrintStream results;
    private volatile String running;
    private ClassLoader loader;
    private final Map<String, String> brokenChecks = new LinkedHashMap<>();
    private final Set<String> checkClasses = new TreeSet<>();
    private final Capture capture = new Capture(16 * 1024);

    public static void main(String[] args) throws Exception {
        new Harness().run(Path.of(args[0]), Integer.parseInt(args[1]));
    }

    private void run(Path planFile, int start) throws Exception {
        for (String line : Files.readAllLines(planFile, StandardCharsets.UTF_8)) {
            String[] f = line.split("\t");
            if (f[0].equals("item")) {
                items.add(f);
            } else if (f.length == 2) {
                conf.put(f[0], f[1]);
            }
        }
        Path out = Path.of(conf.get("out"));
        results = new PrintStream(new FileOutputStream(out.resolve("results.txt").toFile(), true), true, StandardCharsets.UTF_8);
        PrintStream realOut = System.out;
        System.setOut(new PrintStream(capture, true, StandardCharsets.UTF_8));
        System.setErr(new PrintStream(capture, true, StandardCharsets.UTF_8));
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            String r = running;
            if (r != null) {
                record("EXIT " + r);
            }
        }));
        Path classes = out.resolve("classes");
        Path checkOut = out.resolve("check-classes");
        if (start == 0) {
            compile(Path.of(conf.get("src")), Path.of(conf.get("checks")), classes, checkOut);
        } else {
            readBrokenChecks(out);
        }
        loader = new URLClassLoader(new URL[] {classes.toUri().toURL(), checkOut.toUri().toURL()}, Harness.class.getClassLoader());
        Thread.currentThread().setContextClassLoader(loader);
        for (int i = start; i < items.size(); i++) {
            runItem(items.get(i));
        }
        realOut.flush();
        results.flush();
        Runtime.getRuntime().halt(0);   // threads the submission left running must not keep the JVM alive
    }

    // ------------------------------------------------------------------ compiling

    private void compile(Path src, Path checks, Path classes, Path checkOut) throws IOException {
        Files.createDirectories(classes);
        Files.createDirectories(checkOut);
        Path originals = Path.of(conf.get("framework"));
        Set<String> submitted = new TreeSet<>(List.of(conf.getOrDefault("submitted", "").split(",")));
        submitted.remove("");
        Map<String, Path> sources = new LinkedHashMap<>();
        for (File f : sorted(src.toFile().listFiles((d, n) -> n.endsWith(".java")))) {
            sources.put(f.getName(), f.toPath());
        }
        String cp = conf.get("classpath");
        for (int round = 0; ; round++) {
            Map<String, List<String>> errors = javac(new ArrayList<>(sources.values()), cp, classes, null);
            if (errors.isEmpty()) {
                record("COMPILE OK");
                break;
            }
            // a submitted file that does not compile is replaced by the handout's (or left out when it has
            // none), so the error costs only the methods of that file
            boolean changed = false;
            for (Map.Entry<String, List<String>> e : errors.entrySet()) {
                String file = e.getKey();
                if (submitted.remove(file)) {
                    Path original = originals.resolve(file);
                    if (Files.isRegularFile(original)) {
                        sources.put(file, original);
                        record("COMPILE REVERTED " + file + " " + escape(String.join("\n", e.getValue())));
                    } else {
                        sources.remove(file);
                        record("COMPILE DROPPED " + file + " " + escape(String.join("\n", e.getValue())));
                    }
                    changed = true;
                }
            }
            if (!changed && !submitted.isEmpty()) {
                // the errors are in the handout's files: some submitted file changed what they use
                for (String file : List.copyOf(submitted)) {
                    submitted.remove(file);
                    Path original = originals.resolve(file);
                    if (Files.isRegularFile(original)) {
                        sources.put(file, original);
                    } else {
                        sources.remove(file);
                    }
                }
                record("COMPILE REVERTED * " + escape("the handout's files no longer compile with yours: "
                        + String.join("\n", errors.values().iterator().next())));
                changed = true;
            }
            if (!changed) {
                record("COMPILE FAILED " + escape(String.join("\n", errors.values().iterator().next())));
                return;
            }
        }
        List<Path> checkFiles = new ArrayList<>();
        for (File f : sorted(checks.toFile().listFiles((d, n) -> n.endsWith(".java")))) {
            checkFiles.add(f.toPath());
            checkClasses.add(f.getName().substring(0, f.getName().length() - 5));
        }
        String checkCp = classes + File.pathSeparator + cp;
        if (!javac(checkFiles, checkCp, checkOut, null).isEmpty()) {
            // one check file at a time (its helpers found on the source path), so a submission whose API
            // breaks one check file loses only the checks in it
            for (Path f : checkFiles) {
                Map<String, List<String>> errors = javac(List.of(f), checkCp, checkOut, checks);
                if (!errors.isEmpty()) {
                    String name = f.getFileName().toString().replace(".java", "");
                    String msg = String.join("\n", errors.values().iterator().next());
                    brokenChecks.put(name, msg);
                    record("CHECKS-FAILED " + name + " " + escape(msg));
                }
            }
        }
    }

    private void readBrokenChecks(Path out) throws IOException {
        for (String line : Files.readAllLines(out.resolve("results.txt"), StandardCharsets.UTF_8)) {
            if (line.startsWith("CHECKS-FAILED ")) {
                String[] f = line.split(" ", 3);
                brokenChecks.put(f[1], unescape(f.length > 2 ? f[2] : ""));
            } else if (line.startsWith("COMPILE FAILED")) {
                brokenChecks.put("*", unescape(line.substring("COMPILE FAILED".length()).trim()));
            }
        }
    }

    private static File[] sorted(File[] files) {
        if (files == null) {
            return new File[0];
        }
        java.util.Arrays.sort(files);
        return files;
    }

    /** Compiles; returns the errors by file name (at most 5 lines each), empty when it compiled. */
    private static Map<String, List<String>> javac(List<Path> files, String cp, Path out, Path sourcePath) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diags = new DiagnosticCollector<>();
        Map<String, List<String>> errors = new LinkedHashMap<>();
        try (StandardJavaFileManager fm = javac.getStandardFileManager(diags, Locale.ROOT, StandardCharsets.UTF_8)) {
            List<String> options = new ArrayList<>(List.of("-proc:none", "-nowarn", "-g", "-encoding", "UTF-8",
                    "-cp", cp, "-d", out.toString(), "-Xmaxerrs", "50", "-implicit:class"));
            if (sourcePath != null) {
                options.addAll(List.of("-sourcepath", sourcePath.toString()));
            }
            Boolean ok = javac.getTask(null, fm, diags, options, null, fm.getJavaFileObjectsFromPaths(files)).call();
            for (Diagnostic<? extends JavaFileObject> d : diags.getDiagnostics()) {
                if (d.getKind() == Diagnostic.Kind.ERROR) {
                    String file = d.getSource() == null ? "(javac)" : Path.of(d.getSource().toUri()).getFileName().toString();
                    List<String> l = errors.computeIfAbsent(file, k -> new ArrayList<>());
                    if (l.size() < 5) {
                        l.add(file + ":" + d.getLineNumber() + ": " + d.getMessage(Locale.ROOT).lines().findFirst().orElse(""));
                    }
                }
            }
            if (!ok && errors.isEmpty()) {
                errors.put("(javac)", List.of("javac failed without a message"));
            }
        }
        return errors;
    }

    // ------------------------------------------------------------------ running the items

    private void runItem(String[] item) throws Exception {
        String id = item[1];
        long timeoutMs = Long.parseLong(item[item.length - 1]) * (item[2].equals("scene") ? Integer.parseInt(item[5]) : 1);
        record("BEGIN " + id);
        running = id;
        capture.reset();
        String[] verdict = new String[2];
        long t0 = System.nanoTime();
        Thread t = new Thread(null, () -> {
            try {
                verdict[1] = item[2].equals("check") ? check(item[3]) : scenes(item[3], item[4], Integer.parseInt(item[5]));
                verdict[0] = verdict[1] == null ? "PASS" : "FAIL";
            } catch (Throwable e) {
                verdict[0] = "FAIL";
                verdict[1] = describe(e);
            }
        }, "grade-" + id, 64L << 20);
        t.setDaemon(true);
        t.setContextClassLoader(loader);
        t.start();
        t.join(timeoutMs);
        long nanos = System.nanoTime() - t0;
        Files.write(Path.of(conf.get("out"), id + ".out"), capture.bytes());
        if (t.isAlive()) {
            running = null;
            record("END " + id + " TIMEOUT " + nanos + " " + escape(blame("did not finish within " + (timeoutMs / 1000.0)
                    + " s (an endless loop?)", t.getStackTrace())));
            Runtime.getRuntime().halt(124);
        }
        running = null;
        record("END " + id + " " + verdict[0] + " " + nanos + " " + escape(verdict[1] == null ? "" : verdict[1]));
    }

    /** Runs a check: null when it passed, else its message. */
    private String check(String target) throws Exception {
        int dot = target.lastIndexOf('.');
        String cls = target.substring(0, dot);
        if (brokenChecks.containsKey("*")) {
            return "your code did not compile: " + brokenChecks.get("*");
        }
        if (brokenChecks.containsKey(cls)) {
            return "this check does not compile against your classes (did you change a name or a signature?): "
                    + brokenChecks.get(cls);
        }
        Method m = Class.forName(cls, true, loader).getMethod(target.substring(dot + 1));
        if (!Modifier.isStatic(m.getModifiers())) {
            throw new IllegalStateException("check " + target + " is not static");
        }
        try {
            m.invoke(null);
        } catch (InvocationTargetException e) {
            Throwable c = e.getCause();
            if (c instanceof AssertionError && c.getMessage() != null) {
                return c.getMessage();
            }
            return describe(c);
        }
        return null;
    }

    /** Renders a scene {@code renders} times (a stochastic scene: independent renders png, png-2, ...). */
    private String scenes(String scenePath, String png, int renders) throws Exception {
        for (int k = 1; k <= renders; k++) {
            String problem = scene(scenePath, k == 1 ? png : png.substring(0, png.length() - 4) + "-" + k + ".png");
            if (problem != null) {
                return problem;
            }
        }
        return null;
    }

    /** Renders a scene with the test set's render method and writes the PNG: null when every pixel was a colour. */
    private String scene(String scenePath, String png) throws Exception {
        if (brokenChecks.containsKey("*")) {
            return "your code did not compile: " + brokenChecks.get("*");
        }
        String target = conf.get("render");
        int dot = target.lastIndexOf('.');
        String cls = target.substring(0, dot);
        if (brokenChecks.containsKey(cls)) {
            return "the grader's renderer does not compile against your classes: " + brokenChecks.get(cls);
        }
        Method m = Class.forName(cls, true, loader).getMethod(target.substring(dot + 1), String.class);
        Object image;
        try {
            image = m.invoke(null, scenePath);
        } catch (InvocationTargetException e) {
            Throwable c = e.getCause();
            return c instanceof AssertionError && c.getMessage() != null ? c.getMessage() : describe(c);
        }
        if (image == null || !image.getClass().isArray() || Array.getLength(image) == 0) {
            return "Scene.renderAll returned " + (image == null ? "null" : "an empty image") + " instead of a [width][height] array of colours";
        }
        int w = Array.getLength(image);
        Object col0 = Array.get(image, 0);
        int h = col0 == null ? 0 : Array.getLength(col0);
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(w, Math.max(1, h), java.awt.image.BufferedImage.TYPE_INT_RGB);
        String problem = null;
        int bad = 0;
        java.lang.reflect.Field fx = null, fy = null, fz = null;
        for (int x = 0; x < w; x++) {
            Object col = Array.get(image, x);
            for (int y = 0; y < h; y++) {
                Object v = col == null || Array.getLength(col) <= y ? null : Array.get(col, y);
                int rgb;
                if (v == null) {
                    rgb = 0xff00ff;
                    bad++;
                    if (problem == null) {
                        problem = "pixel (" + x + ", " + y + ") has no colour (null): Scene.renderPixel, Scene.trace or a "
                                + "material's shade returned null";
                    }
                } else {
                    if (fx == null) {
                        fx = v.getClass().getField("x");
                        fy = v.getClass().getField("y");
                        fz = v.getClass().getField("z");
                    }
                    double r = fx.getDouble(v), g = fy.getDouble(v), b = fz.getDouble(v);
                    if (Double.isNaN(r) || Double.isNaN(g) || Double.isNaN(b)) {
                        rgb = 0xff00ff;
                        bad++;
                        if (problem == null) {
                            problem = "pixel (" + x + ", " + y + ") is not a number (NaN): a division by zero or the square root "
                                    + "of a negative number in an intersection, a light or a material";
                        }
                    } else {
                        rgb = channel(r) << 16 | channel(g) << 8 | channel(b);
                    }
                }
                img.setRGB(x, y, rgb);
            }
        }
        File tmp = new File(png + ".tmp");
        javax.imageio.ImageIO.write(img, "png", tmp);
        Files.move(tmp.toPath(), Path.of(png), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        return problem == null ? null : problem + (bad > 1 ? " (" + bad + " such pixels, shown magenta)" : "");
    }

    /** A channel as the reference PNGs store it: clamped to [0, 1], then floor(255 v + 0.5). */
    static int channel(double v) {
        if (!(v > 0)) {
            return 0;
        }
        if (v >= 1) {
            return 255;
        }
        return (int) Math.floor(255 * v + 0.5);
    }

    /** An exception as a student reads it: what, and where in their code. */
    private String describe(Throwable e) {
        String what;
        if (e instanceof StackOverflowError) {
            what = "endless recursion (StackOverflowError)";
        } else if (e instanceof OutOfMemoryError) {
            what = "ran out of memory (" + e.getMessage() + "; the heap limit is " + conf.getOrDefault("heap-mb", "?") + " MB)";
        } else {
            what = e.getClass().getName() + (e.getMessage() == null ? "" : ": " + e.getMessage());
        }
        return blame(what, e.getStackTrace());
    }

    /** "Class.method: what (File.java:line)" naming the submission's frame, or just "what" when there is none. */
    private String blame(String what, StackTraceElement[] trace) {
        String at = where(trace);
        if (at.isEmpty()) {
            return what;
        }
        int paren = at.indexOf(" (");
        String method = (paren < 0 ? at : at.substring(0, paren)).substring(" in ".length());
        return method + ": " + what + (paren < 0 ? "" : at.substring(paren));
    }

    /** " in Class.method (File.java:line)" for the first frame of the submission's code, or "". */
    private String where(StackTraceElement[] trace) {
        for (StackTraceElement f : trace) {
            String c = f.getClassName();
            int nested = c.indexOf('$');
            String top = nested < 0 ? c : c.substring(0, nested);
            if (top.contains(".") || checkClasses.contains(top)) {
                continue;   // the JDK, javax.vecmath, this harness, or a check
            }
            return " in " + c.replace('$', '.') + "." + f.getMethodName()
                    + (f.getFileName() != null && f.getLineNumber() > 0 ? " (" + f.getFileName() + ":" + f.getLineNumber() + ")" : "");
        }
        return "";
    }

    private synchronized void record(String line) {
        results.println(line);
        results.flush();
    }

    static String escape(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> b.append(c < ' ' ? ' ' : c);
            }
        }
        return b.toString();
    }

    /** The inverse of {@link #escape}. */
    public static String unescape(String s) {
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '\\' && i + 1 < s.length()) {
                char n = s.charAt(++i);
                b.append(n == 'n' ? '\n' : n == 'r' ? '\r' : n == 't' ? '\t' : n);
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }

    /** What an item printed: the first {@code limit} bytes kept, the rest counted. */
    static final class Capture extends OutputStream {
        private final int limit;
        private final ByteArrayOutputStream kept = new ByteArrayOutputStream();
        private long dropped;

        Capture(int limit) {
            this.limit = limit;
        }

        synchronized void reset() {
            kept.reset();
            dropped = 0;
        }

        @Override
        public synchronized void write(int b) {
            if (kept.size() < limit) {
                kept.write(b);
            } else {
                dropped++;
            }
        }

        @Override
        public synchronized void write(byte[] b, int off, int len) {
            int keep = Math.max(0, Math.min(len, limit - kept.size()));
            kept.write(b, off, keep);
            dropped += len - keep;
        }

        synchronized byte[] bytes() {
            if (dropped == 0) {
                return kept.toByteArray();
            }
            byte[] note = ("\n[... " + dropped + " more bytes of output left out]\n").getBytes(StandardCharsets.UTF_8);
            byte[] k = kept.toByteArray();
            byte[] all = java.util.Arrays.copyOf(k, k.length + note.length);
            System.arraycopy(note, 0, all, k.length, note.length);
            return all;
        }
    }
}
