package ray.grade;

import java.awt.image.BufferedImage;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import ray.judge.ImageJudge;
import ray.judge.Images;
import ray.judge.Judgement;
import ray.judge.Samples;
import ray.judge.StatJudge;

/**
 * The project's tolerance policy ({@code ray.judge}, docs/grading.md "How images are judged") as the
 * grader's {@link Judge}: one image against its reference by {@link ImageJudge}, a stochastic scene's
 * renders against the reference's renders by {@link StatJudge} (t-tests of pixel and region means,
 * Sidak-corrected).
 */
final class RayJudge implements Judge {

    @Override
    public Verdict judge(BufferedImage reference, BufferedImage candidate, boolean stochastic) {
        return verdict(ImageJudge.judge(reference, candidate));
    }

    @Override
    public Verdict judge(List<BufferedImage> references, List<BufferedImage> candidates) {
        return verdict(StatJudge.judge(Samples.of(references.stream().map(Images::fromBufferedImage).toList()),
                Samples.of(candidates.stream().map(Images::fromBufferedImage).toList())));
    }

    private static Verdict verdict(Judgement j) {
        Map<String, Double> metrics = new LinkedHashMap<>(j.metrics());
        String kind = j.where().summary();
        // "FAIL: 1234 of 43200 pixels wrong (2.86%), only shadows differ; ... credit 94%" and what to look at
        String message = j.message().replaceFirst("^(PASS|FAIL): ", "");
        if (!j.passed()) {
            String advice = j.advice();
            message += ". " + (advice.isEmpty() ? "" : Character.toUpperCase(advice.charAt(0)) + advice.substring(1) + ".");
        }
        return new Verdict(j.score(), j.passed(), message, kind, metrics, j.width() > 0 ? j.heatMap() : null);
    }
}
