package ray.study;

import java.util.ArrayList;
import java.util.List;
import ray.Scene;

/**
 * The grid of settings the study renders. Full: {@code grid} at n_s = 1..8, every other
 * non-adaptive sampler at the same sample counts, {@code adaptive} at four targets with the n_s = 8
 * budget, and MaxDepth 0..min(MaxDepth - 1, 5) at n_s = 4 for scenes with mirrors; the reference from
 * two halves of n_s = 16 (512 samples per pixel, 8x the most studied), doubling n_s up to 32 while its
 * noise is not small beside the errors it judges ({@link Reference}). Quick: n_s = 1..4, two adaptive
 * targets, the reference from n_s = 8 (128 samples per pixel) up to 16.
 */
public final class StudySettings {

    public static final StudySettings FULL = new StudySettings(8, new double[] {4, 2, 1, 0.5}, 16, 32, 4);
    public static final StudySettings QUICK = new StudySettings(4, new double[] {2, 1}, 8, 16, 2);

    /**
     * The study renders a scene with more pixels than this at this many (200 x 150), same camera and
     * aspect ratio, unless asked for full size: errors are per pixel, so they keep their meaning, and a
     * 640 x 480 scene no longer costs ten times a small one.
     */
    public static final int MAX_PIXELS = 200 * 150;

    private final int maxNs;
    private final double[] targets;
    private final int referenceStartNs;
    private final int referenceNs;
    private final int depthNs;

    StudySettings(int maxNs, double[] targets, int referenceStartNs, int referenceNs, int depthNs) {
        this.maxNs = maxNs;
        this.targets = targets.clone();
        this.referenceStartNs = referenceStartNs;
        this.referenceNs = referenceNs;
        this.depthNs = depthNs;
    }

    /** n_s of each half of the reference's first level. */
    public int referenceStartNs() {
        return referenceStartNs;
    }

    /** The largest n_s of each half of the reference. */
    public int referenceNs() {
        return referenceNs;
    }

    /**
     * Shrinks {@code scene} to at most {@code maxPixels} pixels, keeping its aspect ratio and its camera
     * (the camera's image-plane aspect is fixed to the scene's own before the size changes).
     */
    public static void fit(Scene scene, int maxPixels) {
        long pixels = (long) scene.width * scene.height;
        if (pixels <= maxPixels) {
            return;
        }
        if (scene.camera != null && Double.isNaN(scene.camera.aspect)) {
            scene.camera.aspect = (double) scene.width / scene.height;
        }
        double s = Math.sqrt((double) maxPixels / pixels);
        scene.width = Math.max(1, (int) Math.round(scene.width * s));
        scene.height = Math.max(1, (int) Math.round(scene.height * s));
    }

    List<Setting> settings(List<String> samplers, int sceneMaxDepth, boolean mirrors) {
        List<Setting> out = new ArrayList<>();
        for (String sampler : samplers) {
            if (sampler.equals("adaptive")) {
                for (double t : targets) {
                    out.add(new Setting(sampler, "target=" + (t == Math.rint(t) ? Integer.toString((int) t) : Double.toString(t)), maxNs, t, sceneMaxDepth));
                }
            } else {
                for (int ns = 1; ns <= maxNs; ns++) {
                    out.add(new Setting(sampler, "n_s=" + ns, ns, 0, sceneMaxDepth));
                }
            }
        }
        if (mirrors) {
            for (int d = 0; d < Math.min(sceneMaxDepth, 6); d++) {
                out.add(new Setting("grid", "MaxDepth=" + d + " n_s=" + depthNs, depthNs, 0, d));
            }
        }
        return out;
    }
}
