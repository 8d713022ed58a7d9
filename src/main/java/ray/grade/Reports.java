package ray.grade;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * What the grader writes from {@link SubmissionResult}s: Gradescope's results.json and a student's
 * index.html per submission; grades.csv and the class's index.html over all of them.
 */
public final class Reports {

    private Reports() {
    }

    // ------------------------------------------------------------------ Gradescope

    /** results.json in Gradescope's format (score, execution_time, output, tests, leaderboard). */
    public static String resultsJson(SubmissionResult r) {
        Map<String, Object> root = new LinkedHashMap<>();
        root.put("score", r.score());
        root.put("execution_time", (long) Math.ceil(r.seconds()));
        root.put("output", summary(r));
        root.put("visibility", "visible");
        root.put("stdout_visibility", "hidden");
        List<Object> tests = new ArrayList<>();
        int n = 0;
        for (TestResult t : r.tests()) {
            Map<String, Object> m = new LinkedHashMap<>();
            m.put("name", t.name());
            m.put("number", Integer.toString(++n));
            m.put("score", t.score());
            m.put("max_score", t.maxScore());
            m.put("status", t.passed() ? "passed" : "failed");
            StringBuilder out = new StringBuilder(t.passed() ? "passed" : t.message());
            if (t.images() != null && !t.images().metrics().isEmpty()) {
                out.append("\n");
                t.images().metrics().forEach((k, v) -> out.append("\n").append(k).append(": ").append(num(v)));
            }
            if (!t.output().isEmpty()) {
                out.append("\n\nYour program printed:\n").append(t.output());
            }
            m.put("output", out.toString());
            m.put("tags", List.of(t.group()));
            m.put("visibility", "visible");
            tests.add(m);
        }
        root.put("tests", tests);
        // a LinkedHashMap, not Map.of: Map.of's order changes from JVM to JVM, and results.json should not
        Map<String, Object> leader = new LinkedHashMap<>();
        leader.put("name", "Render time (s)");
        leader.put("value", Grader.round(r.renderSeconds()));
        leader.put("order", "asc");
        root.put("leaderboard", List.of(leader));
        return Json.write(root);
    }

    /** The overall text: score, isolation, notes about the hand-in, what to fix first. */
    static String summary(SubmissionResult r) {
        StringBuilder b = new StringBuilder();
        b.append("Score ").append(num(r.score())).append(" of ").append(num(r.maxScore())).append(".\n");
        List<String> fix = fixFirst(r);
        if (!fix.isEmpty()) {
            b.append("Fix first: ").append(String.join("; ", fix)).append(".\n");
        }
        for (String note : r.notes()) {
            b.append("Note: ").append(note).append('\n');
        }
        b.append("Ran in: ").append(r.sandbox()).append('.');
        return b.toString();
    }

    /**
     * What to fix first: the methods whose own checks fail, in the order the checks are listed (the
     * assignment's), then scenes that fail while every check of theirs passes.
     */
    static List<String> fixFirst(SubmissionResult r) {
        Map<String, String> methods = new LinkedHashMap<>();
        List<String> scenes = new ArrayList<>();
        for (TestResult t : r.tests()) {
            if (t.passed()) {
                continue;
            }
            if (t.kind() == TestSet.Kind.CHECK) {
                int colon = t.message().indexOf(':');
                String m = colon > 0 ? t.message().substring(0, colon) : t.name();
                if (m.matches("[A-Za-z_$][\\w$]*\\.[A-Za-z_$][\\w$]*")) {
                    methods.putIfAbsent(m, t.message());
                } else {
                    methods.putIfAbsent(t.name(), t.message());
                }
            } else if (t.images() == null || !t.message().contains("Fix first")) {
                scenes.add(t.name());
            }
        }
        List<String> out = new ArrayList<>(methods.keySet());
        if (out.size() > 3) {
            out = new ArrayList<>(out.subList(0, 3));
        }
        if (methods.isEmpty() && !scenes.isEmpty()) {
            out.add("the scene " + scenes.get(0) + " (its methods pass their own tests: compare the pictures)");
        }
        return out;
    }

    // ------------------------------------------------------------------ a student's page

    public static String studentHtml(SubmissionResult r) {
        StringBuilder b = new StringBuilder();
        head(b, r.name() + ": " + num(r.score()) + " / " + num(r.maxScore()));
        b.append("<h1>").append(h(r.name())).append(": ").append(num(r.score())).append(" of ").append(num(r.maxScore()))
                .append(" points</h1>\n");
        List<String> fix = fixFirst(r);
        if (!fix.isEmpty()) {
            b.append("<div class=fix><b>What to fix first:</b><ol>");
            for (String f : fix) {
                String why = "";
                for (TestResult t : r.tests()) {
                    if (!t.passed() && t.message().startsWith(f + ":")) {
                        why = t.message();
                        break;
                    }
                }
                b.append("<li><code>").append(h(f)).append("</code>").append(why.isEmpty() ? "" : ": " + h(why.substring(f.length() + 1).trim()))
                        .append("</li>");
            }
            b.append("</ol></div>\n");
        }
        if (!r.notes().isEmpty()) {
            b.append("<ul class=notes>");
            for (String n : r.notes()) {
                b.append("<li>").append(h(n)).append("</li>");
            }
            b.append("</ul>\n");
        }
        String group = null;
        for (TestResult t : r.tests()) {
            if (!t.group().equals(group)) {
                if (group != null) {
                    b.append("</table>\n");
                }
                group = t.group();
                double got = r.tests().stream().filter(x -> x.group().equals(t.group())).mapToDouble(TestResult::score).sum();
                double max = r.tests().stream().filter(x -> x.group().equals(t.group())).mapToDouble(TestResult::maxScore).sum();
                b.append("<h2>").append(h(group)).append(" <small>").append(num(got)).append(" / ").append(num(max)).append("</small></h2>\n");
                b.append("<table class=tests><tr><th>verdict</th><th>points</th><th>test</th><th>message</th></tr>\n");
            }
            b.append("<tr class=").append(t.status()).append("><td>").append(verdict(t)).append("</td><td>").append(num(t.score()))
                    .append(" / ").append(num(t.maxScore())).append("</td><td>").append(h(t.name())).append("</td><td>")
                    .append(h(t.message()));
            if (!t.output().isEmpty()) {
                b.append("<details><summary>printed</summary><pre>").append(h(t.output())).append("</pre></details>");
            }
            b.append("</td></tr>\n");
            if (t.images() != null) {
                b.append("<tr><td colspan=4><div class=imgs>");
                image(b, t.images().reference(), "reference");
                image(b, t.images().yours(), "yours");
                image(b, t.images().difference(), "difference");
                if (!t.images().metrics().isEmpty()) {
                    b.append("<table class=metrics>");
                    t.images().metrics().forEach((k, v) -> b.append("<tr><td>").append(h(k)).append("</td><td>").append(num(v))
                            .append("</td></tr>"));
                    b.append("<tr><td>where</td><td>").append(h(t.images().kind())).append("</td></tr>");
                    b.append("<tr><td>render time</td><td>").append(secs(t.seconds())).append("</td></tr></table>");
                }
                b.append("</div></td></tr>\n");
            }
        }
        if (group != null) {
            b.append("</table>\n");
        }
        if (!r.console().isBlank()) {
            b.append("<h2>Printed outside the tests</h2><pre>").append(h(r.console())).append("</pre>\n");
        }
        b.append("<p class=small>Graded in ").append(secs(r.seconds())).append("; your scenes rendered in ").append(secs(r.renderSeconds()))
                .append(". Ran in: ").append(h(r.sandbox())).append(".</p>\n</body></html>\n");
        return b.toString();
    }

    private static String verdict(TestResult t) {
        return switch (t.status()) {
            case "passed" -> "&#10004; passed";
            case "partial" -> "&#9680; partial";
            case "timeout" -> "&#8987; timed out";
            case "crashed" -> "&#10007; crashed";
            default -> "&#10007; failed";
        };
    }

    private static void image(StringBuilder b, String file, String caption) {
        b.append("<figure>");
        if (file != null) {
            b.append("<a href=\"").append(h(file)).append("\"><img src=\"").append(h(file)).append("\" alt=\"").append(caption).append("\"></a>");
        } else {
            b.append("<div class=noimg>no image</div>");
        }
        b.append("<figcaption>").append(caption).append("</figcaption></figure>");
    }

    // ------------------------------------------------------------------ the class

    /** grades.csv: submission, score, max_score, then one column per group. */
    public static String gradesCsv(List<SubmissionResult> results, TestSet set) {
        StringBuilder b = new StringBuilder("submission,score,max_score");
        for (String g : set.groups()) {
            b.append(',').append(csv(g));
        }
        b.append('\n');
        for (SubmissionResult r : results) {
            b.append(csv(r.name())).append(',').append(num(r.score())).append(',').append(num(r.maxScore()));
            for (double v : r.groupScores(set.groups()).values()) {
                b.append(',').append(num(v));
            }
            b.append('\n');
        }
        return b.toString();
    }

    /** The class page: a histogram of scores, the most common failures and the slowest submissions. */
    public static String classHtml(List<SubmissionResult> results, TestSet set, String sandbox, double wallSeconds, int parallel) {
        StringBuilder b = new StringBuilder();
        head(b, "Grades");
        double max = set.maxScore();
        b.append("<h1>").append(results.size()).append(" submission").append(results.size() == 1 ? "" : "s").append("</h1>\n");
        double mean = results.stream().mapToDouble(SubmissionResult::score).average().orElse(0);
        b.append("<p>Mean ").append(num(Grader.round(mean))).append(" of ").append(num(max)).append(". Graded in ").append(secs(wallSeconds))
                .append(" with ").append(parallel).append(" at a time (").append(results.isEmpty() ? "-" : secs(wallSeconds / results.size()))
                .append(" per submission; each took ").append(results.isEmpty() ? "-" : secs(
                        results.stream().mapToDouble(SubmissionResult::seconds).sum() / results.size()))
                .append(" on average). Student code ran in: ").append(h(sandbox)).append(".</p>\n");
        // histogram: ten bins of the maximum
        int[] bins = new int[10];
        for (SubmissionResult r : results) {
            bins[Math.min(9, (int) Math.floor(10 * (max > 0 ? r.score() / max : 0)))]++;
        }
        int top = 1;
        for (int c : bins) {
            top = Math.max(top, c);
        }
        b.append("<h2>Scores</h2>\n<svg width=520 height=180 role=img aria-label=\"score histogram\">");
        for (int i = 0; i < 10; i++) {
            int hgt = (int) Math.round(140.0 * bins[i] / top);
            b.append(String.format(Locale.ROOT, "<rect x=%d y=%d width=44 height=%d fill=\"#4a7bd0\"/>", 10 + 50 * i, 150 - hgt, hgt));
            b.append(String.format(Locale.ROOT, "<text x=%d y=%d font-size=11 text-anchor=middle>%d</text>", 32 + 50 * i, 145 - hgt, bins[i]));
            b.append(String.format(Locale.ROOT, "<text x=%d y=170 font-size=10 text-anchor=middle>%d-%d%%</text>", 32 + 50 * i, 10 * i,
                    10 * i + 10));
        }
        b.append("</svg>\n");
        // the most common failures
        Map<String, Integer> fails = new TreeMap<>();
        for (SubmissionResult r : results) {
            for (TestResult t : r.tests()) {
                if (!t.passed()) {
                    fails.merge(t.name(), 1, Integer::sum);
                }
            }
        }
        List<Map.Entry<String, Integer>> common = new ArrayList<>(fails.entrySet());
        common.sort(Map.Entry.<String, Integer>comparingByValue().reversed());
        b.append("<h2>Most common failures</h2>\n<table><tr><th>submissions</th><th>test</th></tr>\n");
        for (Map.Entry<String, Integer> e : common.subList(0, Math.min(15, common.size()))) {
            b.append("<tr><td>").append(e.getValue()).append(" (").append(Math.round(100.0 * e.getValue() / results.size()))
                    .append("%)</td><td>").append(h(e.getKey())).append("</td></tr>\n");
        }
        if (common.isEmpty()) {
            b.append("<tr><td colspan=2>none: every test passed</td></tr>\n");
        }
        b.append("</table>\n");
        List<SubmissionResult> slow = new ArrayList<>(results);
        slow.sort(Comparator.comparingDouble(SubmissionResult::renderSeconds).reversed());
        b.append("<h2>Slowest submissions</h2>\n<table><tr><th>render time</th><th>graded in</th><th>submission</th><th>score</th></tr>\n");
        for (SubmissionResult r : slow.subList(0, Math.min(10, slow.size()))) {
            b.append("<tr><td>").append(secs(r.renderSeconds())).append("</td><td>").append(secs(r.seconds())).append("</td><td><a href=\"")
                    .append(h(r.name())).append("/index.html\">").append(h(r.name())).append("</a></td><td>").append(num(r.score()))
                    .append("</td></tr>\n");
        }
        b.append("</table>\n<h2>Everyone</h2>\n<table><tr><th>submission</th><th>score</th>");
        for (String g : set.groups()) {
            b.append("<th>").append(h(g)).append("</th>");
        }
        b.append("</tr>\n");
        for (SubmissionResult r : results) {
            b.append("<tr><td><a href=\"").append(h(r.name())).append("/index.html\">").append(h(r.name())).append("</a></td><td>")
                    .append(num(r.score())).append("</td>");
            for (double v : r.groupScores(set.groups()).values()) {
                b.append("<td>").append(num(v)).append("</td>");
            }
            b.append("</tr>\n");
        }
        b.append("</table>\n</body></html>\n");
        return b.toString();
    }

    /** A submission's line on the console: {@code name: 87.5 / 100 (16.2 s)}. */
    public static String scoreLine(SubmissionResult r) {
        return r.name() + ": " + num(r.score()) + " / " + num(r.maxScore()) + " (" + num(Grader.round(r.seconds())) + " s)";
    }

    /**
     * Writes the class's grades.csv and index.html into {@code dir} and returns the closing console line
     * ({@code parallel}: submissions graded at once).
     */
    public static String writeClass(Path dir, List<SubmissionResult> results, TestSet set, String sandbox, double wallSeconds,
                                    int parallel) throws IOException {
        Files.writeString(dir.resolve("grades.csv"), gradesCsv(results, set), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve("index.html"), classHtml(results, set, sandbox, wallSeconds, parallel), StandardCharsets.UTF_8);
        return results.size() + " graded in " + num(Grader.round(wallSeconds)) + " s (" + parallel + " at a time; " + sandbox + "): "
                + dir.resolve("index.html");
    }

    /** Writes results.json and index.html for one submission into {@code dir}. */
    public static void writeSubmission(SubmissionResult r, Path dir) throws IOException {
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("results.json"), resultsJson(r), StandardCharsets.UTF_8);
        Files.writeString(dir.resolve("index.html"), studentHtml(r), StandardCharsets.UTF_8);
    }

    private static void head(StringBuilder b, String title) {
        b.append("<!DOCTYPE html>\n<html lang=en><head><meta charset=utf-8><title>").append(h(title)).append("</title>\n<style>\n")
                .append("body{font:14px/1.4 system-ui,sans-serif;margin:2em;max-width:1200px;color:#222}\n")
                .append("table{border-collapse:collapse;margin:.5em 0}td,th{border-bottom:1px solid #ddd;padding:4px 8px;text-align:left;"
                        + "vertical-align:top}td:first-child,td:nth-child(2){white-space:nowrap}table.tests{width:100%}"
                        + "table.tests td:nth-child(3){width:32%}\n")
                .append("tr.passed td:first-child{color:#1a7f37}tr.failed td:first-child,tr.crashed td:first-child,"
                        + "tr.timeout td:first-child{color:#c62828}tr.partial td:first-child{color:#b26a00}\n")
                .append(".imgs{display:flex;gap:12px;align-items:flex-start}figure{margin:0}img{image-rendering:pixelated;max-width:320px;"
                        + "border:1px solid #ccc}figcaption{font-size:12px;color:#555}.noimg{width:160px;height:120px;background:#eee;"
                        + "display:flex;align-items:center;justify-content:center}\n")
                .append(".fix{background:#fff4e5;border-left:4px solid #b26a00;padding:.5em 1em}.notes{color:#8a4b00}.small{color:#666;"
                        + "font-size:12px}table.metrics td{border:0;padding:1px 6px;font-size:12px}\n")
                .append("</style></head><body>\n");
    }

    static String h(String s) {
        if (s == null) {
            return "";
        }
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;").replace("'", "&#39;");
    }

    static String num(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e15) {
            return Long.toString((long) v);
        }
        String s = String.format(Locale.ROOT, "%.3f", v).replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }

    /** Seconds to a tenth: "12.3 s". */
    static String secs(double seconds) {
        return String.format(Locale.ROOT, "%.1f s", seconds);
    }

    private static String csv(String s) {
        return s.matches("[^,\"\\n\\r]*") ? s : "\"" + s.replace("\"", "\"\"") + "\"";
    }
}
