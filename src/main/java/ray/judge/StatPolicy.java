package ray.judge;

/**
 * How {@link StatJudge} judges a stochastic image (docs/grading.md, "Stochastic images").
 *
 * @param alpha the family-wise false-alarm rate: a right image fails with at most this probability (Nori's
 *     default 0.01), each test held to Sidak's 1 - (1 - alpha)^(1/tests)
 * @param region the side of the square regions whose means are tested besides each pixel's
 * @param minSteps a rejected test counts only when the means differ by more than this many 8-bit steps: a
 *     difference too small to see is never a failure, however significant, and 8-bit renders of two right
 *     programs differ by exactly one step where a value lies on a rounding tie (see {@link Policy#biasSteps})
 */
public record StatPolicy(double alpha, int region, double minSteps) {

    public static final StatPolicy DEFAULT = new StatPolicy(0.01, 8, 1.0);

    public StatPolicy {
        if (!(alpha > 0 && alpha < 1) || region < 1 || !(minSteps >= 0)) {
            throw new IllegalArgumentException("invalid statistical policy: " + this);
        }
    }
}
