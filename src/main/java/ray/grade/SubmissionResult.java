package ray.grade;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Everything the grader found about one submission: what the reports and results.json are written from.
 * Serializable: raytracer-spark's executors send it to the driver.
 *
 * @param seconds       wall-clock time spent grading it (compile, run, judge)
 * @param renderSeconds the submission's own time to render the test set's scenes (the leaderboard's number)
 * @param sandbox       the isolation it ran under (see {@link Sandbox#description()})
 * @param notes         about the hand-in and its compilation: files left out, files that did not compile
 * @param console       what the child JVM printed outside any item (capped)
 */
public record SubmissionResult(String name, double score, double maxScore, List<TestResult> tests, double seconds,
                               double renderSeconds, String sandbox, List<String> notes, String console) implements java.io.Serializable {

    public SubmissionResult {
        tests = List.copyOf(tests);
        notes = List.copyOf(notes);
    }

    /** Points per group, in the test set's group order. */
    public Map<String, Double> groupScores(List<String> groups) {
        Map<String, Double> out = new LinkedHashMap<>();
        for (String g : groups) {
            out.put(g, 0.0);
        }
        for (TestResult t : tests) {
            out.merge(t.group(), t.score(), Double::sum);
        }
        return out;
    }
}
