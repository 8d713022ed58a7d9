package ray.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** results.json, the student page and grades.csv from a hand-made result: no child JVM needed. */
class ReportsTest {

    static SubmissionResult result() {
        Map<String, Double> metrics = new LinkedHashMap<>();
        metrics.put("wrong_share", 0.03);
        TestResult check = new TestResult("c1", "Sphere.intersects: a hit", "Intersections", TestSet.Kind.CHECK, 0, 4, "failed",
                "Sphere.intersects: must hit at t = 4; yours returned false", "printed \"quotes\"\n<b>", 0.01, null);
        TestResult scene = new TestResult("s2", "Shadows", "Scenes", TestSet.Kind.SCENE, 1.5, 2, "partial", "only shadows differ",
                "", 0.25, new TestResult.Images("a-reference.png", "a-yours.png", "a-difference.png", "only shadows differ", metrics));
        return new SubmissionResult("alice", 1.5, 6, List.of(check, scene), 3.2, 0.25, "bubblewrap",
                List.of("notes.txt: not a .java file, left out"), "");
    }

    @Test
    void resultsJsonIsGradescopes() {
        String json = Reports.resultsJson(result());
        assertTrue(json.startsWith("{\n  \"score\": 1.5,\n  \"execution_time\": 4,\n  \"output\": \"Score 1.5 of 6.\\nFix first: "
                + "Sphere.intersects.\\nNote: notes.txt: not a .java file, left out\\nRan in: bubblewrap.\",\n"), json);
        assertTrue(json.contains("\"name\": \"Sphere.intersects: a hit\",\n      \"number\": \"1\",\n      \"score\": 0,\n"
                + "      \"max_score\": 4,\n      \"status\": \"failed\",\n"), json);
        assertTrue(json.contains("Your program printed:\\nprinted \\\"quotes\\\"\\n<b>"), json);
        assertTrue(json.contains("\"leaderboard\": [\n    {\n"), json);
        assertTrue(json.contains("\"name\": \"Render time (s)\"") && json.contains("\"value\": 0.25") && json.contains("\"order\": \"asc\""), json);
        assertTrue(json.contains("wrong_share: 0.03"), json);
    }

    @Test
    void studentPageEscapesAndShowsThePictures() {
        String html = Reports.studentHtml(result());
        assertTrue(html.contains("printed &quot;quotes&quot;\n&lt;b&gt;"), html);
        assertTrue(html.contains("<img src=\"a-difference.png\"") && html.contains("What to fix first"), html);
        assertTrue(html.contains("<code>Sphere.intersects</code>: must hit at t = 4; yours returned false"), html);
    }

    @Test
    void gradesCsvHasAColumnPerGroup() {
        String csv = Reports.gradesCsv(List.of(result()), setWithGroups());
        assertEquals("submission,score,max_score,Intersections,Scenes\nalice,1.5,6,0,1.5\n", csv);
    }

    static TestSet setWithGroups() {
        try {
            java.nio.file.Path d = java.nio.file.Files.createTempDirectory("reports-test");
            for (String f : new String[] {"fw", "checks", "scenes", "refs"}) {
                java.nio.file.Files.createDirectories(d.resolve(f));
            }
            java.nio.file.Files.writeString(d.resolve("rubric.txt"), "framework fw\nchecks checks\nscenes scenes\nreferences refs\n"
                    + "group Intersections\ncheck 4 C.a T\ngroup Scenes\ncheck 2 C.b T\n");
            TestSet t = TestSet.load(d);
            Grader.deleteTree(d);
            return t;
        } catch (java.io.IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
