package ray.course;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

/**
 * Writes the student handout and the course kit from the reference solution (docs/course.md).
 *
 * <p>Solution regions in the reference solution's sources:
 *
 * <pre>
 *     // BEGIN SOLUTION
 *     // STUB: return null;        the handout gets "return null;" here, at this indentation
 *     ...                          the solution: never reaches the handout
 *     // END SOLUTION
 * </pre>
 *
 * Everything outside the regions is copied as it is. Usage (what {@code gradle handout} and
 * {@code gradle courseKit} run):
 *
 * <pre>
 * Handout --solution DIR --tests DIR --test-resources DIR --project DIR --scenes DIR --references DIR
 *         --out DIR [--kit DIR]
 * </pre>
 */
public final class Handout {

    public static final String BEGIN = "// BEGIN SOLUTION";
    public static final String END = "// END SOLUTION";
    public static final String STUB = "// STUB:";

    /** The classes the 2003 framework has: a scene naming only these (and the six globals) is a handout scene. */
    public static final Set<String> CLASSES_2003 = Set.of("Camera", "Sphere", "Triangle", "Diffuse", "BlinnPhong",
            "GlazedMaterial", "Glazed", "PointLight");
    public static final Set<String> GLOBALS_2003 = Set.of("BGColor", "AmbientLight", "Width", "Height", "AASamples", "MaxDepth");

    private static final Pattern METHOD_NUMBER = Pattern.compile("method (\\d+) of (\\d+)");
    private static final Pattern DECLARATION = Pattern.compile("^\\s*public\\s+(?:abstract\\s+)?([\\w\\[\\]<>]+)\\s+(\\w+)\\s*\\(([^)]*)\\)");

    private Handout() {
    }

    /** A mistake in the solution's markers, naming the file and line. */
    public static final class MarkerException extends IllegalArgumentException {
        private static final long serialVersionUID = 1L;

        MarkerException(String file, int line, String message) {
            super(file + ":" + line + ": " + message);
        }
    }

    /** One solution region: where it is, the lines it holds and the stub that replaces it. */
    public record Region(String file, int beginLine, List<String> solution, List<String> stub) {
    }

    /** One of the methods the student writes: its number, class, name, signature and the stub body. */
    public record Method(int number, String className, String name, String returnType, String parameters, List<String> stub) {
        public String qualified() {
            return className + "." + name;
        }

        /** The per-method test class of the student tests: SphereIntersectsTest, CameraGetRayThroughTest... */
        public String testClass() {
            return className + Character.toUpperCase(name.charAt(0)) + name.substring(1) + "Test";
        }
    }

    /** {@code source} with every solution region replaced by its stub lines. */
    public static String stub(String source, String file) {
        StringBuilder out = new StringBuilder(source.length());
        String[] lines = source.split("\n", -1);
        int begin = 0;
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i];
            String t = line.strip();
            if (t.equals(BEGIN)) {
                if (begin > 0) {
                    throw new MarkerException(file, i + 1, "BEGIN SOLUTION inside the region begun at line " + begin);
                }
                begin = i + 1;
            } else if (t.equals(END)) {
                if (begin == 0) {
                    throw new MarkerException(file, i + 1, "END SOLUTION without a BEGIN SOLUTION");
                }
                begin = 0;
            } else if (begin > 0) {
                if (t.startsWith(STUB)) {
                    String indent = line.substring(0, line.indexOf(STUB));
                    String body = t.substring(STUB.length());
                    out.append(indent).append(body.startsWith(" ") ? body.substring(1) : body).append('\n');
                }
            } else if (t.startsWith(STUB) || t.contains("BEGIN SOLUTION") || t.contains("END SOLUTION")) {
                throw new MarkerException(file, i + 1, "a marker outside the form '" + BEGIN + "' / '" + END + "' / '" + STUB
                        + "' inside a region: " + t);
            } else {
                out.append(line);
                if (i < lines.length - 1) {
                    out.append('\n');
                }
            }
        }
        if (begin > 0) {
            throw new MarkerException(file, begin, "BEGIN SOLUTION without an END SOLUTION");
        }
        return out.toString();
    }

    /** The solution regions of {@code source}. */
    public static List<Region> regions(String source, String file) {
        stub(source, file);     // the markers are well formed
        List<Region> regions = new ArrayList<>();
        String[] lines = source.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].strip().equals(BEGIN)) {
                List<String> solution = new ArrayList<>(), stub = new ArrayList<>();
                int j = i + 1;
                for (; !lines[j].strip().equals(END); j++) {
                    String t = lines[j].strip();
                    if (t.startsWith(STUB)) {
                        stub.add(t.substring(STUB.length()).strip());
                    } else {
                        solution.add(lines[j]);
                    }
                }
                regions.add(new Region(file, i + 1, solution, stub));
                i = j;
            }
        }
        return regions;
    }

    /** The methods the student writes, in the assignment's order (from the "method N of 11" stub comments). */
    public static List<Method> methods(Path solutionDir) throws IOException {
        TreeMap<Integer, Method> byNumber = new TreeMap<>();
        int total = -1;
        for (Path p : javaFiles(solutionDir)) {
            String file = p.getFileName().toString();
            String cls = file.substring(0, file.length() - ".java".length());
            String source = read(p);
            String[] lines = source.split("\n", -1);
            for (Region r : regions(source, file)) {
                Matcher m = null;
                for (String s : r.stub()) {
                    Matcher mm = METHOD_NUMBER.matcher(s);
                    if (mm.find()) {
                        m = mm;
                    }
                }
                if (m == null) {
                    throw new MarkerException(file, r.beginLine(), "the stub names no 'method N of M'");
                }
                Matcher d = null;
                for (int i = r.beginLine() - 2; i >= 0 && d == null; i--) {
                    Matcher dd = DECLARATION.matcher(lines[i]);
                    if (dd.find()) {
                        d = dd;
                    }
                }
                if (d == null) {
                    throw new MarkerException(file, r.beginLine(), "no method declaration above the region");
                }
                int n = Integer.parseInt(m.group(1));
                total = Integer.parseInt(m.group(2));
                List<String> body = r.stub().stream().filter(s -> !s.startsWith("//")).collect(Collectors.toList());
                Method prev = byNumber.put(n, new Method(n, cls, d.group(2), d.group(1), d.group(3).strip(), body));
                if (prev != null) {
                    throw new MarkerException(file, r.beginLine(), "method " + n + " is also " + prev.qualified());
                }
            }
        }
        List<Method> list = new ArrayList<>(byNumber.values());
        for (int i = 0; i < list.size(); i++) {
            if (list.get(i).number() != i + 1 || list.size() != total) {
                throw new IllegalArgumentException("the methods are not numbered 1 to " + total + ": " + byNumber.keySet());
            }
        }
        return list;
    }

    /** True when a scene file uses only the 2003 framework's classes and global settings. */
    public static boolean is2003Scene(String text) {
        for (String raw : text.split("\r\n|\r|\n")) {
            String s = raw.strip();
            if (s.isEmpty() || s.startsWith("#")) {
                continue;
            }
            String[] w = s.split("\\s+");
            switch (w[0]) {
                case "Camera", "Surface", "Material", "Light" -> {
                    if (w.length < 2 || !CLASSES_2003.contains(w[1])) {
                        return false;
                    }
                }
                case "int", "double", "String", "ref", "Vector3d" -> {
                }
                default -> {
                    if (!GLOBALS_2003.contains(w[0])) {
                        return false;
                    }
                }
            }
        }
        return true;
    }

    /** The names (without .txt) of the 2003 scenes in {@code scenes} that have a reference image, sorted. */
    public static List<String> scenes2003(Path scenes, Path references) throws IOException {
        List<String> names = new ArrayList<>();
        try (Stream<Path> s = Files.list(scenes)) {
            for (Path p : s.sorted().collect(Collectors.toList())) {
                String n = p.getFileName().toString();
                if (n.endsWith(".txt") && is2003Scene(read(p))) {
                    String base = n.substring(0, n.length() - 4);
                    if (Files.isRegularFile(references.resolve(base + ".png"))) {
                        names.add(base);
                    }
                }
            }
        }
        return names;
    }

    public static void main(String[] args) throws IOException {
        TreeMap<String, Path> a = new TreeMap<>();
        for (int i = 0; i + 1 < args.length; i += 2) {
            a.put(args[i], Path.of(args[i + 1]));
        }
        for (String k : List.of("--solution", "--tests", "--test-resources", "--project", "--scenes", "--references", "--out")) {
            if (!a.containsKey(k)) {
                throw new IllegalArgumentException("missing " + k + " (usage in ray.course.Handout)");
            }
        }
        Path out = a.get("--out");
        writeHandout(a.get("--solution"), a.get("--tests"), a.get("--test-resources"), a.get("--project"), a.get("--scenes"),
                a.get("--references"), out);
        if (a.containsKey("--kit")) {
            writeKit(a.get("--solution"), out, a.get("--kit"), a.get("--grading"));
        }
    }

    /** Writes the student project into {@code out} (emptied first). */
    public static void writeHandout(Path solution, Path tests, Path testResources, Path project, Path scenes, Path references,
                                    Path out) throws IOException {
        deleteTree(out);
        Path main = Files.createDirectories(out.resolve("src/main/java"));
        for (Path p : javaFiles(solution)) {
            String file = p.getFileName().toString();
            write(main.resolve(file), stub(read(p), file));
        }
        copyTree(tests, out.resolve("src/test/java"));
        if (Files.isDirectory(testResources)) {
            copyTree(testResources, out.resolve("src/test/resources"));
        }
        copyTree(project, out);
        Path gitignore = out.resolve("gitignore");
        if (Files.exists(gitignore)) {
            Files.move(gitignore, out.resolve(".gitignore"), StandardCopyOption.REPLACE_EXISTING);
        }
        Path sc = Files.createDirectories(out.resolve("scenes")), ref = Files.createDirectories(out.resolve("reference-images"));
        for (String name : scenes2003(scenes, references)) {
            Files.copy(scenes.resolve(name + ".txt"), sc.resolve(name + ".txt"));
            Files.copy(references.resolve(name + ".png"), ref.resolve(name + ".png"));
        }
        List<Method> methods = methods(solution);
        Path readme = out.resolve("README.md");
        if (Files.exists(readme)) {
            write(readme, read(readme).replace("@METHODS@", methodList(methods)));
        }
    }

    /** The README's numbered list of the methods. */
    static String methodList(List<Method> methods) {
        StringBuilder b = new StringBuilder();
        for (Method m : methods) {
            b.append(m.number()).append(". `").append(m.className()).append('.').append(m.name()).append('(')
                    .append(m.parameters()).append(")` in `src/main/java/").append(m.className()).append(".java`")
                    .append(" (tests: `").append(m.testClass()).append("`)\n");
        }
        return b.toString().stripTrailing();
    }

    /** Writes the course kit: the handout, the solution, methods.tsv and kit.properties. */
    public static void writeKit(Path solution, Path handout, Path kit, Path grading) throws IOException {
        deleteTree(kit);
        copyTree(handout, kit.resolve("handout"));
        copyTree(solution, kit.resolve("solution"));
        if (grading != null && Files.isDirectory(grading)) {
            copyTree(grading, kit.resolve("grading"));
        }
        StringBuilder tsv = new StringBuilder("# number\tmethod\treturns\tparameters\tstub\ttest class\n");
        for (Method m : methods(solution)) {
            tsv.append(m.number()).append('\t').append(m.qualified()).append('\t').append(m.returnType()).append('\t')
                    .append(m.parameters()).append('\t').append(String.join(" ", m.stub())).append('\t').append(m.testClass()).append('\n');
        }
        write(kit.resolve("methods.tsv"), tsv.toString());
        List<String> scenes;
        try (Stream<Path> s = Files.list(handout.resolve("scenes"))) {
            scenes = s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".txt")).sorted()
                    .map(n -> n.substring(0, n.length() - 4)).collect(Collectors.toList());
        }
        write(kit.resolve("kit.properties"), "# the course kit (docs/course.md)\nformat=1\nmethods=" + methods(solution).size()
                + "\nscenes=" + String.join(",", scenes) + "\n");
    }

    // ---- files ----

    static List<Path> javaFiles(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> p.getFileName().toString().endsWith(".java")).sorted().collect(Collectors.toList());
        }
    }

    static String read(Path p) throws IOException {
        return new String(Files.readAllBytes(p), StandardCharsets.UTF_8).replace("\r\n", "\n");
    }

    private static void write(Path p, String text) throws IOException {
        Files.createDirectories(p.toAbsolutePath().getParent());
        Files.write(p, text.getBytes(StandardCharsets.UTF_8));
    }

    /** Copies a folder's tree (file modes kept, so gradlew stays executable). */
    static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : s.sorted().collect(Collectors.toList())) {
                Path target = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) {
                    Files.createDirectories(target);
                } else {
                    Files.createDirectories(target.getParent());
                    Files.copy(p, target, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.COPY_ATTRIBUTES);
                }
            }
        }
    }

    static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) {
            return;
        }
        try (Stream<Path> s = Files.walk(dir)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> {
                try {
                    Files.delete(p);
                } catch (IOException e) {
                    throw new UncheckedIOException(e);
                }
            });
        }
    }
}
