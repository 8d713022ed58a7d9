package ray.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.stream.Stream;

/**
 * A course's test set: the rubric ({@code rubric.txt}) and the folders it names. The format, line by
 * line ({@code #} starts a comment; paths are relative to the rubric's folder; docs/grading.md has the
 * whole of it):
 * <pre>
 * framework  PATH        the handout's .java files (a submission's files of the same name replace them)
 * checks     PATH        the grader's per-method checks: default-package .java files, compiled with the submission
 * scenes     PATH        scene files (and what they read) shown to the submission, read-only
 * references PATH        NAME.png for each scene NAME.txt; never shown to the submission
 * render     CLASS.METHOD  a static method in the checks, String scene path -&gt; Vector3d[][] image [x][y]
 * method     NAME        the assignment's methods in its order (what to fix first follows it)
 * limit      KEY VALUE   check-seconds, scene-seconds, total-seconds, heap-mb, output-kb
 * group      TITLE       starts a test group (a column of grades.csv)
 * check      POINTS CLASS.METHOD TITLE      a check; fails when the method throws (its message is the test's)
 * scene      POINTS FILE [stochastic] [uses=A.m,B.n] TITLE   a scene rendered and judged against its reference
 * </pre>
 */
public final class TestSet {

    /** One graded item: a check method or a scene. */
    public record Item(String id, Kind kind, String group, double points, String target, String title,
                       boolean stochastic, List<String> uses, int renders) {
    }

    public enum Kind { CHECK, SCENE }

    /** The limits one submission runs under. */
    public record Limits(double checkSeconds, double sceneSeconds, double totalSeconds, int heapMb, int outputKb) {
    }

    private final Path root;
    private final Path framework;
    private final Path checks;
    private final Path scenes;
    private final Path references;
    private final String render;
    private final List<String> methods;
    private final List<String> groups;
    private final List<Item> items;
    private final Limits limits;

    private TestSet(Path root, Path framework, Path checks, Path scenes, Path references, String render,
                    List<String> methods, List<String> groups, List<Item> items, Limits limits) {
        this.root = root;
        this.framework = framework;
        this.checks = checks;
        this.scenes = scenes;
        this.references = references;
        this.render = render;
        this.methods = List.copyOf(methods);
        this.groups = List.copyOf(groups);
        this.items = List.copyOf(items);
        this.limits = limits;
    }

    /** Reads {@code dir/rubric.txt}; a mistake in it is an {@link IOException} naming the file and line. */
    public static TestSet load(Path dir) throws IOException {
        Path rubric = dir.resolve("rubric.txt");
        if (!Files.isRegularFile(rubric)) {
            throw new IOException(dir + ": no rubric.txt (not a test set; see docs/grading.md)");
        }
        List<String> lines = Files.readAllLines(rubric, StandardCharsets.UTF_8);
        Map<String, Path> folders = new LinkedHashMap<>();
        String render = null;
        List<String> methods = new ArrayList<>();
        List<String> groups = new ArrayList<>();
        List<Item> items = new ArrayList<>();
        Map<String, Double> limits = new TreeMap<>(Map.of("check-seconds", 10.0, "scene-seconds", 60.0,
                "total-seconds", 600.0, "heap-mb", 384.0, "output-kb", 1024.0));
        String group = null;
        for (int n = 1; n <= lines.size(); n++) {
            String line = lines.get(n - 1);
            int hash = line.indexOf('#');
            String[] w = (hash >= 0 ? line.substring(0, hash) : line).trim().split("\\s+");
            if (w[0].isEmpty()) {
                continue;
            }
            String where = rubric + ":" + n + ": ";
            switch (w[0]) {
                case "framework", "checks", "scenes", "references" -> {
                    need(w, 2, where, w[0] + " PATH");
                    Path p = dir.resolve(w[1]).normalize();
                    p = Files.isDirectory(p) ? p.toRealPath() : p;
                    if (!Files.isDirectory(p)) {
                        throw new IOException(where + w[0] + " folder " + p + " does not exist");
                    }
                    folders.put(w[0], p);
                }
                case "render" -> {
                    need(w, 2, where, "render CLASS.METHOD");
                    render = w[1];
                }
                case "method" -> {
                    need(w, 2, where, "method CLASS.METHOD");
                    methods.add(w[1]);
                }
                case "limit" -> {
                    need(w, 3, where, "limit KEY VALUE");
                    if (!limits.containsKey(w[1])) {
                        throw new IOException(where + "unknown limit " + w[1] + " (expected one of " + limits.keySet() + ")");
                    }
                    limits.put(w[1], number(w[2], where));
                }
                case "group" -> {
                    need(w, 2, where, "group TITLE");
                    group = rest(w, 1);
                    if (groups.contains(group)) {
                        throw new IOException(where + "group \"" + group + "\" appears twice");
                    }
                    groups.add(group);
                }
                case "check", "scene" -> {
                    need(w, 3, where, w[0] + " POINTS " + (w[0].equals("check") ? "CLASS.METHOD" : "FILE") + " TITLE");
                    if (group == null) {
                        throw new IOException(where + w[0] + " before the first group line");
                    }
                    double points = number(w[1], where);
                    boolean stochastic = false;
                    int renders = 1;
                    List<String> uses = new ArrayList<>();
                    int t = 3;
                    while (t < w.length && (w[t].equals("stochastic") || w[t].startsWith("uses=") || w[t].startsWith("renders="))) {
                        if (w[t].equals("stochastic")) {
                            stochastic = true;
                            renders = Math.max(renders, 4);
                        } else if (w[t].startsWith("renders=")) {
                            double r = number(w[t].substring(8), where);
                            if (r < 2 || r > 64 || r != Math.rint(r)) {
                                throw new IOException(where + "renders= takes a whole number from 2 to 64");
                            }
                            renders = (int) r;
                        } else {
                            uses.addAll(List.of(w[t].substring(5).split(",")));
                        }
                        t++;
                    }
                    if (renders > 1 && !stochastic) {
                        throw new IOException(where + "renders= goes with stochastic");
                    }
                    Kind kind = w[0].equals("check") ? Kind.CHECK : Kind.SCENE;
                    if (kind == Kind.CHECK && !w[2].matches("[A-Za-z_$][\\w$]*\\.[A-Za-z_$][\\w$]*")) {
                        throw new IOException(where + "check " + w[2] + " is not CLASS.METHOD");
                    }
                    String title = t < w.length ? rest(w, t) : w[2];
                    String id = (kind == Kind.CHECK ? "c" : "s") + (items.size() + 1);
                    items.add(new Item(id, kind, group, points, w[2], title, stochastic, uses, renders));
                }
                default -> throw new IOException(where + "unknown line \"" + w[0] + "\" (expected framework, checks, scenes, "
                        + "references, render, method, limit, group, check or scene)");
            }
        }
        for (String f : List.of("framework", "checks", "scenes", "references")) {
            if (!folders.containsKey(f)) {
                throw new IOException(rubric + ": no \"" + f + " PATH\" line");
            }
        }
        if (items.isEmpty()) {
            throw new IOException(rubric + ": no check or scene lines: nothing to grade");
        }
        boolean anyScene = items.stream().anyMatch(i -> i.kind() == Kind.SCENE);
        if (anyScene && render == null) {
            throw new IOException(rubric + ": scenes need a \"render CLASS.METHOD\" line");
        }
        for (Item i : items) {
            if (i.kind() == Kind.SCENE) {
                if (!Files.isRegularFile(folders.get("scenes").resolve(i.target()))) {
                    throw new IOException(rubric + ": scene " + i.target() + " is not in " + folders.get("scenes"));
                }
                if (!Files.isRegularFile(folders.get("references").resolve(pngName(i.target())))) {
                    throw new IOException(rubric + ": no reference image " + pngName(i.target()) + " in " + folders.get("references"));
                }
                if (i.stochastic() && referenceRenders(folders.get("references"), i.target()).size() < 2) {
                    throw new IOException(rubric + ": the stochastic scene " + i.target() + " needs independent reference renders "
                            + pngName(i.target()) + ", " + renderName(i.target(), 2) + ", ... (at least two) in " + folders.get("references"));
                }
            }
        }
        Limits l = new Limits(limits.get("check-seconds"), limits.get("scene-seconds"), limits.get("total-seconds"),
                limits.get("heap-mb").intValue(), limits.get("output-kb").intValue());
        return new TestSet(dir, folders.get("framework"), folders.get("checks"), folders.get("scenes"),
                folders.get("references"), render, methods, groups, items, l);
    }

    /** Render {@code k} (from 1) of a stochastic scene: {@code a.png}, {@code a-2.png}, {@code a-3.png} ... */
    public static String renderName(String scene, int k) {
        String png = pngName(scene);
        return k == 1 ? png : png.substring(0, png.length() - 4) + "-" + k + ".png";
    }

    /** A stochastic scene's reference renders: NAME.png, NAME-2.png, ... as long as they go on. */
    public static List<Path> referenceRenders(Path references, String scene) {
        List<Path> out = new ArrayList<>();
        for (int k = 1; k <= 1000 && Files.isRegularFile(references.resolve(renderName(scene, k))); k++) {
            out.add(references.resolve(renderName(scene, k)));
        }
        return out;
    }

    /** {@code a.txt} -> {@code a.png}. */
    public static String pngName(String scene) {
        int dot = scene.lastIndexOf('.');
        return (dot > 0 ? scene.substring(0, dot) : scene) + ".png";
    }

    private static void need(String[] w, int n, String where, String form) throws IOException {
        if (w.length < n) {
            throw new IOException(where + "expected \"" + form + "\"");
        }
    }

    private static String rest(String[] w, int from) {
        return String.join(" ", java.util.Arrays.copyOfRange(w, from, w.length));
    }

    private static double number(String s, String where) throws IOException {
        try {
            double v = Double.parseDouble(s);
            if (!(v >= 0) || Double.isInfinite(v)) {
                throw new NumberFormatException();
            }
            return v;
        } catch (NumberFormatException e) {
            throw new IOException(where + s + " is not a number of 0 or more");
        }
    }

    /** The .java files of a folder, by file name. */
    static Map<String, Path> javaFiles(Path dir) throws IOException {
        Map<String, Path> out = new TreeMap<>();
        try (Stream<Path> s = Files.list(dir)) {
            s.filter(p -> p.getFileName().toString().endsWith(".java")).forEach(p -> out.put(p.getFileName().toString(), p));
        }
        return out;
    }

    public Path root() {
        return root;
    }

    public Path framework() {
        return framework;
    }

    public Path checks() {
        return checks;
    }

    public Path scenes() {
        return scenes;
    }

    public Path references() {
        return references;
    }

    public String render() {
        return render;
    }

    /** The assignment's methods in its order. */
    public List<String> methods() {
        return methods;
    }

    public List<String> groups() {
        return groups;
    }

    public List<Item> items() {
        return items;
    }

    public Limits limits() {
        return limits;
    }

    public double maxScore() {
        return items.stream().mapToDouble(Item::points).sum();
    }

    public double maxScore(String group) {
        return items.stream().filter(i -> i.group().equals(group)).mapToDouble(Item::points).sum();
    }
}
