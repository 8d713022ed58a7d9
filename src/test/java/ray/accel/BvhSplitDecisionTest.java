package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * Every node of the builder's tree is the binned-SAH decision for exactly the primitives under it
 * (Wald 2007, with the builder's documented parameters: min(16, max(2, n)) bins over the node's
 * centroid bounds, cost {@link BvhBuilder#TRAVERSAL_COST} + sum of child area x count over the parent's
 * area, a leaf when n <= {@link BvhBuilder#MAX_LEAF} and no split is cheaper, halving by count when no
 * split exists). The test restates the rule plainly, per node and from scratch: one axis at a time,
 * bins filled from the primitives' own boxes, centroids from those boxes. The builder computes the same
 * with its speed-ups (one pass bins all three axes, the children's boxes come out of the bins, their
 * centroid bounds out of the partition pass), so a speed-up that hands a child the wrong bounds, or a
 * wrong area or cost, makes some node decide differently. BvhTreeQualityTest measures the tree's cost
 * as a whole; this catches a change too small to move that total by a few percent. Both compute in
 * float with the same operations, so the decisions agree exactly.
 */
class BvhSplitDecisionTest {

    private static final long SEED = 20261202L;

    /** The cost of the split {@link #expected} found last (NaN when it found none). */
    private static float lastCost;

    /** One decision: a leaf, or the slot where the right child starts. */
    private static int expected(BvhBuilder b, int start, int end, int depth, String what) {
        return expected(b, start, end, depth, what, true);
    }

    /** {@link #expected}, checking that the slots are partitioned at the split only when {@code sides}. */
    private static int expected(BvhBuilder b, int start, int end, int depth, String what, boolean sides) {
        lastCost = Float.NaN;
        int n = end - start;
        if (n == 1) {
            return -1;
        }
        if (depth >= BvhBuilder.SAH_DEPTH) {
            return start + n / 2;   // past the SAH depth: halving by count, down to single primitives
        }
        float[] pb = b.primBoxes();
        float[] cent = new float[3 * n];
        float[] lo = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY};
        float[] hi = {Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                float c = 0.5f * pb[6 * (start + i) + a] + 0.5f * pb[6 * (start + i) + 3 + a];
                cent[3 * i + a] = c;
                lo[a] = Math.min(lo[a], c);
                hi[a] = Math.max(hi[a], c);
            }
        }
        int nb = Math.min(BvhBuilder.BINS, Math.max(2, n));
        float best = Float.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = -1;
        float[] scale = new float[3];
        for (int a = 0; a < 3; a++) {
            float ext = hi[a] - lo[a];
            scale[a] = ext > 0 ? nb * 0.99999f / ext : 0;
            if (scale[a] == 0) {
                continue;
            }
            int[] count = new int[nb];
            float[][] box = new float[nb][];
            for (int k = 0; k < nb; k++) {
                box[k] = empty();
            }
            for (int i = 0; i < n; i++) {
                int k = bin(cent[3 * i + a], lo[a], scale[a], nb);
                count[k]++;
                grow(box[k], pb, 6 * (start + i));
            }
            for (int split = 0; split < nb - 1; split++) {
                float[] l = empty(), r = empty();
                int cl = 0, cr = 0;
                for (int k = 0; k < nb; k++) {
                    if (k <= split) {
                        cl += count[k];
                        union(l, box[k]);
                    } else {
                        cr += count[k];
                        union(r, box[k]);
                    }
                }
                if (cl == 0 || cr == 0) {
                    continue;
                }
                float cost = area(l) * cl + area(r) * cr;
                if (cost < best) {
                    best = cost;
                    bestAxis = a;
                    bestBin = split;
                }
            }
        }
        if (bestAxis < 0) {
            return n <= BvhBuilder.MAX_LEAF ? -1 : start + n / 2;   // nothing to split by position: halve
        }
        float[] all = empty();
        for (int i = start; i < end; i++) {
            grow(all, pb, 6 * i);
        }
        float parentArea = area(all);
        float cost = parentArea > 0 ? BvhBuilder.TRAVERSAL_COST + best / parentArea : BvhBuilder.TRAVERSAL_COST + n;
        lastCost = cost;
        if (n <= BvhBuilder.MAX_LEAF && n <= cost || !sides) {
            return -1;
        }
        // the left child is every primitive whose centroid falls in a bin <= bestBin on bestAxis
        int left = 0;
        for (int i = 0; i < n; i++) {
            if (bin(cent[3 * i + bestAxis], lo[bestAxis], scale[bestAxis], nb) <= bestBin) {
                left++;
            }
        }
        for (int i = 0; i < n; i++) {
            boolean inLeft = bin(cent[3 * i + bestAxis], lo[bestAxis], scale[bestAxis], nb) <= bestBin;
            if (inLeft != (i < left)) {
                fail("slot " + (start + i) + " is on the wrong side of the split (axis " + bestAxis + ", bin " + bestBin
                        + ") of the node over slots [" + start + ", " + end + ") " + what);
            }
        }
        return start + left;
    }

    private static int bin(float c, float lo, float scale, int nb) {
        int k = (int) ((c - lo) * scale);
        return Math.max(0, Math.min(nb - 1, k));
    }

    private static float[] empty() {
        return new float[] {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
            Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
    }

    private static void grow(float[] acc, float[] src, int o) {
        for (int q = 0; q < 3; q++) {
            acc[q] = Math.min(acc[q], src[o + q]);
            acc[3 + q] = Math.max(acc[3 + q], src[o + 3 + q]);
        }
    }

    private static void union(float[] acc, float[] box) {
        grow(acc, box, 0);
    }

    private static float area(float[] b) {
        float x = b[3] - b[0], y = b[4] - b[1], z = b[5] - b[2];
        return x * y + y * z + z * x;
    }

    /** Walks the tree; returns the end slot of subtree {@code ref} starting at slot {@code start}. */
    private static int check(BvhBuilder b, int ref, int start, int end, int depth, String what) {
        int want = expected(b, start, end, depth, what);
        if (ref < 0) {
            int leaf = ~ref;
            assertEquals(start, leaf >>> 4, "leaf start " + what);
            assertEquals(end - start, leaf & 15, "leaf size " + what);
            if (want >= 0) {
                fail("a leaf of " + (end - start) + " where the binned SAH splits at slot " + want + " " + what);
            }
            return end;
        }
        if (want < 0) {
            fail("an inner node over slots [" + start + ", " + end + ") where the binned SAH makes a leaf " + what);
        }
        int mid = check(b, b.nodeChild[2 * ref], start, want, depth + 1, what);
        assertEquals(want, mid, what);
        return check(b, b.nodeChild[2 * ref + 1], want, end, depth + 1, what);
    }

    private static void checkTree(double[] box, String what) {
        int n = box.length / 6;
        BvhBuilder b = new BvhBuilder(box.clone());
        b.build();
        // the slots hold the input's boxes rounded outward to floats, moved along with their ids
        float[] pb = b.primBoxes();
        for (int i = 0; i < n; i++) {
            int id = b.order[i];
            for (int q = 0; q < 3; q++) {
                assertEquals(BvhBuilder.down(box[6 * id + q]), pb[6 * i + q], 0, what);
                assertEquals(BvhBuilder.up(box[6 * id + 3 + q]), pb[6 * i + 3 + q], 0, what);
                assertTrue(pb[6 * i + q] <= box[6 * id + q] && pb[6 * i + 3 + q] >= box[6 * id + 3 + q], what);
            }
        }
        check(b, b.root, 0, n, 0, what);
    }

    private static double[] random(Random r, int n, int kind) {
        double[] b = new double[6 * n];
        for (int i = 0; i < n; i++) {
            double x, y, z, ex, ey, ez;
            switch (kind) {
                case 0 -> {   // uniform in a cube, boxes of mixed sizes
                    x = 10 * r.nextDouble(); y = 10 * r.nextDouble(); z = 10 * r.nextDouble();
                    ex = 3 * r.nextDouble() * r.nextDouble(); ey = 3 * r.nextDouble() * r.nextDouble(); ez = 3 * r.nextDouble() * r.nextDouble();
                }
                case 1 -> {   // two or three clusters
                    int c = r.nextInt(3);
                    x = 40 * c + r.nextGaussian(); y = (c == 2 ? 30 : 0) + r.nextGaussian(); z = r.nextGaussian();
                    ex = 0.3 * r.nextDouble(); ey = 0.3 * r.nextDouble(); ez = 0.3 * r.nextDouble();
                }
                case 2 -> {   // flat: every box in the plane z = 1 (zero height: areas from two axes only)
                    x = 10 * r.nextDouble(); y = 10 * r.nextDouble(); z = 1;
                    ex = r.nextDouble(); ey = r.nextDouble(); ez = 0;
                }
                case 3 -> {   // centroids on a line along y (x and z alike): only y can split
                    x = 1; y = 10 * r.nextDouble(); z = 2;
                    ex = 2; ey = r.nextDouble(); ez = 2;
                }
                case 4 -> {   // centroids on a line along z
                    x = 1; y = 2; z = 10 * r.nextDouble();
                    ex = 2; ey = 2; ez = r.nextDouble();
                }
                case 5 -> {   // points on the x axis: zero areas, every split costs 0 and the first is taken, so
                              // the tree peels a few points off per level down to SAH_DEPTH, then halves
                    x = 10 * r.nextDouble(); y = 0; z = 0;
                    ex = 0; ey = 0; ez = 0;
                }
                case 6 -> {   // long boxes reaching back below every small one: the box whose centroid is the
                              // largest (the last bin) holds the node's smallest corner, so a parent box taken from
                              // fewer than all the bins is too small
                    boolean wide = r.nextInt(4) == 0;
                    x = wide ? -r.nextDouble() : 2 + 8 * r.nextDouble();
                    y = wide ? -r.nextDouble() : 2 + 8 * r.nextDouble();
                    z = wide ? -r.nextDouble() : 2 + 8 * r.nextDouble();
                    ex = wide ? 30 + r.nextDouble() : 0.5 * r.nextDouble();
                    ey = wide ? 30 + r.nextDouble() : 0.5 * r.nextDouble();
                    ez = wide ? 30 + r.nextDouble() : 0.5 * r.nextDouble();
                }
                default -> {   // large overlapping boxes (leaves pay) with a few small ones
                    x = r.nextDouble(); y = r.nextDouble(); z = r.nextDouble();
                    boolean big = r.nextInt(4) != 0;
                    ex = big ? 5 + r.nextDouble() : 0.1; ey = big ? 5 + r.nextDouble() : 0.1; ez = big ? 5 : 0.1;
                }
            }
            b[6 * i] = x; b[6 * i + 1] = y; b[6 * i + 2] = z;
            b[6 * i + 3] = x + ex; b[6 * i + 4] = y + ey; b[6 * i + 5] = z + ez;
        }
        return b;
    }

    /** Small sets (the leaf-or-split decisions) and larger ones (several levels), of eight kinds. */
    @Test
    void everyNodeIsTheBinnedSahDecisionForItsPrimitives() {
        Random r = new Random(SEED);
        int[] sizes = {2, 3, 4, 5, 6, 7, 8, 9, 12, 16, 17, 30, 64, 200, 1000};
        for (int kind = 0; kind < 8; kind++) {
            for (int n : sizes) {
                for (int rep = 0; rep < (n < 100 ? 6 : 1); rep++) {
                    long seed = r.nextLong();
                    checkTree(random(new Random(seed), n, kind), "(kind " + kind + ", n " + n + ", seed " + seed + ")");
                }
            }
        }
    }

    /**
     * The cost the builder's split search gives a node is the restated rule's, to the bit: the decisions
     * above agree as long as a wrong cost stays on the same side of a leaf's, so this checks the number
     * itself (a parent area taken from too few bins, say, moves it), on the root of small seeded sets.
     */
    @Test
    void theSearchsCostIsTheRestatedOne() {
        Random r = new Random(SEED + 1);
        for (int kind = 0; kind < 8; kind++) {
            for (int n = 2; n <= 17; n++) {
                for (int rep = 0; rep < 12; rep++) {
                    long seed = r.nextLong();
                    String what = "(kind " + kind + ", n " + n + ", seed " + seed + ")";
                    BvhBuilder b = new BvhBuilder(random(new Random(seed), n, kind));
                    float[] box = new float[6], cent = new float[6];
                    b.bounds(0, n, box, 0, cent, 0);
                    BvhBuilder.Scratch sc = new BvhBuilder.Scratch();
                    boolean found = b.findSplit(0, n, cent, 0, sc);
                    expected(b, 0, n, 0, what, false);
                    assertEquals(lastCost == lastCost, found, "a split found " + what);
                    if (found) {
                        assertEquals(Float.floatToIntBits(lastCost), Float.floatToIntBits(sc.cost), "cost " + lastCost + " vs " + sc.cost + " " + what);
                    }
                }
            }
        }
    }

    /**
     * Two boxes, however far apart, are one leaf (a split costs at least the traversal cost, 3 > 2); eight
     * tiny boxes in two far groups split (3 + almost 0 < 8); eight large overlapping boxes stay one leaf
     * (3 + almost 8 > 8).
     */
    @Test
    void leafOrSplitAtTheLeafSize() {
        double[] two = {0, 0, 0, 1, 1, 1, 100, 0, 0, 101, 1, 1};
        BvhBuilder b = new BvhBuilder(two);
        b.build();
        assertEquals(~(0 << 4 | 2), b.root, "two boxes: one leaf (a split costs at least 3)");
        double[] groups = new double[6 * 8], overlapping = new double[6 * 8];
        for (int i = 0; i < 8; i++) {
            double x = (i < 4 ? 0 : 1000) + 0.01 * i;
            double[] g = {x, 0, 0, x + 0.001, 0.001, 0.001};
            double[] o = {0.01 * i, 0, 0, 10 + 0.01 * i, 10, 10};
            System.arraycopy(g, 0, groups, 6 * i, 6);
            System.arraycopy(o, 0, overlapping, 6 * i, 6);
        }
        b = new BvhBuilder(groups);
        b.build();
        assertTrue(b.root >= 0, "two far groups of four split");
        assertEquals(~(0 << 4 | 4), b.nodeChild[0], "left: a leaf of the first four");
        assertEquals(~(4 << 4 | 4), b.nodeChild[1], "right: a leaf of the other four");
        b = new BvhBuilder(overlapping);
        b.build();
        assertEquals(~(0 << 4 | 8), b.root, "eight overlapping boxes: one leaf");
        checkTree(groups, "groups");
        checkTree(overlapping, "overlapping");
    }
}
