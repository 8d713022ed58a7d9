package ray.grade;

import java.util.Map;

/**
 * One graded item of one submission.
 *
 * @param status  {@code passed}, {@code partial} (some credit), {@code failed}, {@code timeout} or
 *                {@code crashed} (the program ended during the item)
 * @param message what the student reads: why it failed, naming the method at fault where known
 * @param output  what the item printed (capped)
 * @param images  for a scene: the report's image files and the judge's values; null for a check
 */
public record TestResult(String id, String name, String group, TestSet.Kind kind, double score, double maxScore,
                         String status, String message, String output, double seconds, Images images)
        implements java.io.Serializable {

    /** A scene's pictures (file names inside the submission's report folder) and the judge's numbers. */
    public record Images(String reference, String yours, String difference, String kind, Map<String, Double> metrics)
            implements java.io.Serializable {
    }

    public boolean passed() {
        return status.equals("passed");
    }
}
