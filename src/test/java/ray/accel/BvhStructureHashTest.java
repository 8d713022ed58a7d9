package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The tree's structure hash ({@link BvhBuilder#structureHash}, what {@code gradle buildTimes} prints to
 * compare a builder before and after a change) must be the same for the same boxes and tell apart trees
 * that differ in a node's box, in its references or in the order of the primitives in the leaves.
 */
class BvhStructureHashTest {

    /** {@code n} random boxes, 6 doubles each, from {@code seed}. */
    private static double[] boxes(long seed, int n) {
        Random r = new Random(seed);
        double[] b = new double[6 * n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                double lo = 100 * r.nextDouble(), size = 3 * r.nextDouble();
                b[6 * i + a] = lo;
                b[6 * i + 3 + a] = lo + size;
            }
        }
        return b;
    }

    private static long hash(double[] box) {
        BvhBuilder b = new BvhBuilder(box.clone());
        b.build();
        return b.structureHash();
    }

    @Test
    void theSameBoxesGiveTheSameHash() {
        for (long seed = 1; seed <= 5; seed++) {
            double[] box = boxes(seed, 3000);
            assertEquals(hash(box), hash(box), "seed " + seed);
        }
    }

    @Test
    void anotherTreeGivesAnotherHash() {
        double[] box = boxes(7, 3000);
        long h = hash(box);
        // one box grown well past its neighbours: the boxes of its leaf and of that leaf's ancestors change
        double[] grown = box.clone();
        grown[6 * 1234 + 3] += 50;
        assertNotEquals(h, hash(grown));
        // two primitives swapped in the input: the same boxes, so the same nodes, but other ids in the leaves
        double[] swapped = box.clone();
        for (int k = 0; k < 6; k++) {
            double t = swapped[6 * 10 + k];
            swapped[6 * 10 + k] = swapped[6 * 2000 + k];
            swapped[6 * 2000 + k] = t;
        }
        assertNotEquals(h, hash(swapped));
        // a different set of boxes altogether
        assertNotEquals(h, hash(boxes(8, 3000)));
    }
}
