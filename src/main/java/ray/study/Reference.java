package ray.study;

import java.util.List;
import ray.Scene;
import ray.render.Image;

/**
 * A scene's converged reference, and how converged it is. It is the mean of two independent renders
 * (the {@code sobol} sampler with seeds 1 and 2, so it shares no points with any setting studied), which
 * makes its own error measurable: half the RMS difference of the two is the RMSE of their mean against
 * the truth ({@link #noiseSteps}; exact in expectation, as both are unbiased and independent). It is
 * built in levels, n_s doubling (4x the samples) from {@code startNs}, and stops at the first level whose
 * noise is at most {@link #FRACTION} of the smallest error it has to judge (or at {@code maxNs}): cheap
 * scenes stop early, noisy ones go on. The change between the last two levels is kept for the report.
 */
record Reference(Image image, int ns, int levels, double noiseSteps, ImageError change, String sampler) {

    /** The reference's noise may be at most this share of the smallest error it judges. */
    static final double FRACTION = 1.0 / 3;

    /** Samples per pixel of the whole reference (both halves). */
    int spp() {
        return 2 * ns * ns;
    }

    /**
     * Builds the reference for {@code scene}, judging {@code images}; {@code tick} is told the work of
     * each render (samples x pixels).
     */
    static Reference build(StudyRenderer renderer, Scene scene, int startNs, int maxNs, List<Image> images, SceneStudy.Tick tick) {
        String sampler = renderer.samplers().contains("sobol") ? "sobol" : "jittered";
        Image previous = null, mean = null;
        double noise = Double.NaN;
        int ns = startNs, levels = 0;
        ImageError change = null;
        while (true) {
            List<Image> halves = render(renderer, scene, sampler, ns, tick);
            Image a = halves.get(0), b = halves.get(1);
            levels++;
            mean = mean(a, b);
            noise = ImageError.of(a, b).rmse / 2 / ImageError.STEP;
            if (previous != null) {
                change = ImageError.of(mean, previous);
            }
            if (ns * 2 > maxNs || noise <= FRACTION * smallestError(images, mean, noise)) {
                break;
            }
            previous = mean;
            ns *= 2;
        }
        return new Reference(mean, ns, levels, noise, change, sampler);
    }

    /** The two halves of a level (seeds 1 and 2), as one batch (raytracer-spark renders both at once, in tiles). */
    private static List<Image> render(StudyRenderer renderer, Scene scene, String sampler, int ns, SceneStudy.Tick tick) {
        List<StudyRenderer.Result> r = renderer.renderAll(scene, List.of(new Setting(sampler, Setting.REFERENCE, ns, 0, scene.maxDepth, 1),
                new Setting(sampler, Setting.REFERENCE, ns, 0, scene.maxDepth, 2)));
        tick.rendered(2.0 * scene.width * scene.height * ns * ns);
        return List.of(r.get(0).image(), r.get(1).image());
    }

    /**
     * The smallest error among {@code images} against {@code mean}, its noise taken out (in squares: the
     * reference's noise adds to every image's squared error), in 8-bit steps; never below 0.
     */
    private static double smallestError(List<Image> images, Image mean, double noise) {
        double least = Double.POSITIVE_INFINITY;
        for (Image img : images) {
            double e = ImageError.of(img, mean).rmse / ImageError.STEP;
            least = Math.min(least, Math.sqrt(Math.max(0, e * e - noise * noise)));
        }
        return least;
    }

    private static Image mean(Image a, Image b) {
        Image m = new Image(a.width, a.height);
        for (int i = 0; i < m.rgb.length; i++) {
            m.rgb[i] = (a.rgb[i] + b.rgb[i]) / 2;
        }
        return m;
    }

    /**
     * The RMSE (8-bit steps) of an image whose RMSE against this reference is {@code measuredSteps},
     * with the reference's own noise taken out: sqrt(measured^2 - noise^2), 0 when the noise covers it.
     */
    double trueSteps(double measuredSteps) {
        return Math.sqrt(Math.max(0, measuredSteps * measuredSteps - noiseSteps * noiseSteps));
    }
}
