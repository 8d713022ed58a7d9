package ray.study;

import java.util.ArrayList;
import java.util.List;

/**
 * The grid of settings the study renders. Full: {@code grid} at n_s = 1..8, every other
 * non-adaptive sampler at the same sample counts, {@code adaptive} at four targets with the n_s = 8
 * budget, and MaxDepth 0..min(MaxDepth - 1, 5) at n_s = 4 for scenes with mirrors; the reference at
 * n_s = 24 (576 samples per pixel, 9x the most studied) and its check at n_s = 12. Quick: n_s = 1..4,
 * two adaptive targets, the reference at n_s = 16 and its check at 8.
 */
public final class StudySettings {

    public static final StudySettings FULL = new StudySettings(8, new double[] {4, 2, 1, 0.5}, 24, 4);
    public static final StudySettings QUICK = new StudySettings(4, new double[] {2, 1}, 16, 2);

    private final int maxNs;
    private final double[] targets;
    private final int referenceNs;
    private final int depthNs;

    StudySettings(int maxNs, double[] targets, int referenceNs, int depthNs) {
        this.maxNs = maxNs;
        this.targets = targets.clone();
        this.referenceNs = referenceNs;
        this.depthNs = depthNs;
    }

    public int referenceNs() {
        return referenceNs;
    }

    /**
     * The reference's sampler: a randomised one where the renderer has it (its error is noise that
     * shrinks with the samples, with no pattern shared with the grids studied), else the grid.
     */
    String referenceSampler(List<String> samplers) {
        return samplers.contains("jittered") ? "jittered" : "grid";
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
