package ray.judge;

/**
 * How {@link ImageJudge} tells a right image from a wrong one (docs/grading.md, "How images are judged").
 * All differences are in 8-bit steps (1/255 of the display range) per channel.
 *
 * @param pixelTolerance a pixel away from edges is wrong when a channel differs by more than this many steps
 * @param edgeContrast a reference pixel lies on an edge when a second difference (along a row, column or
 *     diagonal) exceeds this many steps in a channel; edges are then widened by one pixel
 * @param edgeShare an edge pixel is right when each channel lies within the reference neighbourhood's range
 *     (plus {@code pixelTolerance}) and differs from the reference by at most this share of that range (plus
 *     {@code pixelTolerance}): another anti-aliasing pattern passes, jaggies or a moved silhouette do not
 * @param biasTile the side of the square tiles in which a systematic difference is looked for
 * @param biasSteps a tile is systematically off when its off-edge pixels differ on average by more than this
 *     many steps in a channel and a t-test says that mean is not noise; more than one step, because two right
 *     programs differ by exactly one step over a flat area whose exact value lies on a rounding boundary
 *     (0.1 x 255 = 25.5: the mean of nine samples of 0.1 rounds to 25, one sample to 26)
 * @param biasAlpha the family-wise false-alarm rate of those t-tests (Sidak-corrected over tiles x channels)
 * @param maxWrongShare the image passes when at most this share of its pixels is wrong (and no tile is biased
 *     and FLIP stays below {@code maxFlipMean})
 * @param maxFlipMean the largest mean FLIP error a passing image may have
 * @param pixelsPerDegree the FLIP observer (67 for a 4K 0.7 m monitor seen from 0.7 m)
 */
public record Policy(double pixelTolerance, double edgeContrast, double edgeShare, int biasTile, double biasSteps,
                     double biasAlpha, double maxWrongShare, double maxFlipMean, double pixelsPerDegree) {

    /** The defaults the grader and the student tests use. */
    public static final Policy DEFAULT = new Policy(2, 16, 0.25, 8, 1.0, 1e-3, 0.001, 0.05, Flip.DEFAULT_PPD);

    public Policy {
        if (!(pixelTolerance >= 0) || !(edgeContrast >= 0) || !(edgeShare >= 0) || biasTile < 2 || !(biasSteps >= 0)
                || !(biasAlpha > 0 && biasAlpha < 1) || !(maxWrongShare >= 0 && maxWrongShare <= 1)
                || !(maxFlipMean >= 0) || !(pixelsPerDegree > 0)) {
            throw new IllegalArgumentException("invalid judging policy: " + this);
        }
    }

    public Policy withPixelTolerance(double steps) {
        return new Policy(steps, edgeContrast, edgeShare, biasTile, biasSteps, biasAlpha, maxWrongShare, maxFlipMean, pixelsPerDegree);
    }

    public Policy withEdgeShare(double share) {
        return new Policy(pixelTolerance, edgeContrast, share, biasTile, biasSteps, biasAlpha, maxWrongShare, maxFlipMean, pixelsPerDegree);
    }

    public Policy withMaxWrongShare(double share) {
        return new Policy(pixelTolerance, edgeContrast, edgeShare, biasTile, biasSteps, biasAlpha, share, maxFlipMean, pixelsPerDegree);
    }

    public Policy withMaxFlipMean(double flip) {
        return new Policy(pixelTolerance, edgeContrast, edgeShare, biasTile, biasSteps, biasAlpha, maxWrongShare, flip, pixelsPerDegree);
    }

    /** The policy with bias detection off (a min/max judge: only per-pixel tolerances). */
    public Policy withoutBias() {
        return new Policy(pixelTolerance, edgeContrast, edgeShare, biasTile, Double.MAX_VALUE, biasAlpha, maxWrongShare, maxFlipMean, pixelsPerDegree);
    }
}
