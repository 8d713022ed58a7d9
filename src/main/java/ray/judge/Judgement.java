package ray.judge;

import java.awt.image.BufferedImage;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The verdict on one candidate image: partial credit, pass or fail, where the differences are, a one-line
 * message, the named metric values and the per-pixel difference for a heat map.
 */
public final class Judgement {

    private final double score;
    private final boolean passed;
    private final Difference where;
    private final String message;
    private final Map<String, Double> metrics;
    private final int width, height;
    private final double[] map;
    private final boolean[] wrong;
    private final boolean flipScale;

    Judgement(double score, boolean passed, Difference where, String message, Map<String, Double> metrics,
              int width, int height, double[] map, boolean[] wrong, boolean flipScale) {
        this.score = score;
        this.passed = passed;
        this.where = where;
        this.message = message;
        this.metrics = Collections.unmodifiableMap(new LinkedHashMap<>(metrics));
        this.width = width;
        this.height = height;
        this.map = map;
        this.wrong = wrong;
        this.flipScale = flipScale;
    }

    /** Partial credit in [0, 1]: the share of the picture's content that is right (1 when passed). */
    public double score() {
        return score;
    }

    public boolean passed() {
        return passed;
    }

    /** Where the differences are. */
    public Difference where() {
        return where;
    }

    /** One line: the verdict, how much is wrong and where, the main metrics. */
    public String message() {
        return message;
    }

    /** What a student should look at first (from {@link #where()}). */
    public String advice() {
        return where.advice();
    }

    /** Named metric values in a fixed order (docs/grading.md lists them). */
    public Map<String, Double> metrics() {
        return metrics;
    }

    /** A metric's value, NaN when this judgement has none of that name. */
    public double metric(String name) {
        Double v = metrics.get(name);
        return v == null ? Double.NaN : v;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /**
     * The per-pixel difference the heat map shows, row by row: for images judged pixel by pixel the largest
     * channel difference in 8-bit steps; for stochastic images |t| of each pixel's test. Empty when the sizes differ.
     */
    public double[] differenceMap() {
        return map.clone();
    }

    /** Which pixels were judged wrong, row by row (empty when the sizes differ). */
    public boolean[] wrongPixels() {
        return wrong.clone();
    }

    /** The heat map with its scale bar (magma; see {@link HeatMap}); a 1 x 1 black image when the sizes differ. */
    public BufferedImage heatMap() {
        if (map.length == 0) {
            return new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        }
        return flipScale ? HeatMap.ofFlip(map, width, height) : HeatMap.ofSteps(map, width, height);
    }

    /** Reference | candidate | heat map side by side, enlarged alike (see {@link HeatMap#sideBySide}). */
    public BufferedImage sideBySide(ray.render.Image reference, ray.render.Image candidate) {
        return HeatMap.sideBySide(reference, candidate, heatMap());
    }

    /** {@link #sideBySide(ray.render.Image, ray.render.Image)} of two 8-bit images. */
    public BufferedImage sideBySide(BufferedImage reference, BufferedImage candidate) {
        return sideBySide(Images.fromBufferedImage(reference), Images.fromBufferedImage(candidate));
    }

    @Override
    public String toString() {
        return message;
    }
}
