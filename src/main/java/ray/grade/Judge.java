package ray.grade;

import java.awt.image.BufferedImage;
import java.util.Map;

/**
 * How the grader judges a rendered image against its reference (in the grader's JVM, never in student
 * code): the seam between the grader and {@code ray.judge}. {@link #standard()} is the project's
 * tolerance policy (docs/grading.md); a course could plug in another.
 */
public interface Judge {

    /**
     * @param fraction  partial credit in [0, 1]: how much of the image is right
     * @param pass      the image counts as correct
     * @param message   one line for the student: what differs and where
     * @param kind      where the differences are ("none", "whole image", "edges", "shadows", "highlights", ...)
     * @param metrics   named values for the report, in the order to show them
     * @param heatMap   the difference as an image of the same size (black = same)
     */
    record Verdict(double fraction, boolean pass, String message, String kind, Map<String, Double> metrics,
                   BufferedImage heatMap) {
    }

    /** {@code stochastic}: the scene is rendered with random samples; judge it statistically. */
    Verdict judge(BufferedImage reference, BufferedImage candidate, boolean stochastic);

    /**
     * A stochastic scene: independent renders of the reference and of the candidate, compared by the means
     * and variances they show (the first of each is what the report pictures).
     */
    Verdict judge(java.util.List<BufferedImage> references, java.util.List<BufferedImage> candidates);

    /** The project's tolerance policy: {@code ray.judge} (docs/grading.md, "How images are judged"). */
    static Judge standard() {
        return new RayJudge();
    }
}
