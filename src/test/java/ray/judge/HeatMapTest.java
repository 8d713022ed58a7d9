package ray.judge;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;
import ray.render.Image;

/** The heat map: magma ends, enlargement of small images, the scale bar below, side by side. */
class HeatMapTest {

    @Test
    void magmaRunsFromBlackToPaleYellow() {
        assertEquals(0x000004, HeatMap.magma(0));
        assertEquals(0xfcfdbf, HeatMap.magma(1));
        assertEquals(HeatMap.magma(0), HeatMap.magma(Double.NaN));
        int prev = -1;
        for (int i = 0; i <= 16; i++) {        // brightness grows along the map
            int c = HeatMap.magma(i / 16.0), sum = (c >> 16) + (c >> 8 & 255) + (c & 255);
            assertTrue(sum > prev, "magma brightness at " + i);
            prev = sum;
        }
    }

    @Test
    void aSmallImageIsEnlargedAndCarriesItsScale() {
        double[] steps = new double[20 * 10];
        steps[3 * 20 + 4] = 255;
        steps[5 * 20 + 7] = 1;
        BufferedImage img = HeatMap.ofSteps(steps, 20, 10);
        int k = 12;                           // 240 / 20
        assertEquals(20 * k, img.getWidth());
        assertTrue(img.getHeight() > 10 * k + 20, "room for the bar and its labels");
        assertEquals(HeatMap.magma(1), img.getRGB(4 * k + 5, 3 * k + 5) & 0xffffff);
        assertEquals(HeatMap.magma(0.125), img.getRGB(7 * k, 5 * k) & 0xffffff, "one step is an eighth of the log scale");
        assertEquals(HeatMap.magma(0), img.getRGB(0, 0) & 0xffffff);
        boolean dark = false;                 // tick labels are drawn in black below the bar
        for (int y = 10 * k + 19; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                dark |= (img.getRGB(x, y) & 0xffffff) == 0;
            }
        }
        assertTrue(dark, "labels under the bar");
    }

    @Test
    void sideBySideHoldsReferenceCandidateAndMap() {
        Image a = new Image(30, 20), b = new Image(30, 20);
        a.set(1, 1, 1, 0, 0);
        b.set(1, 1, 0, 1, 0);
        Judgement j = ImageJudge.judge(a, b);
        BufferedImage s = HeatMap.sideBySide(a, b, j.heatMap());
        int k = 8;                            // 240 / 30
        assertEquals(3 * 30 * k + 8, s.getWidth());
        assertEquals(0xff0000, s.getRGB(k + 1, k + 1) & 0xffffff);
        assertEquals(0x00ff00, s.getRGB(30 * k + 4 + k + 1, k + 1) & 0xffffff);
        assertEquals(HeatMap.magma(1), s.getRGB(2 * (30 * k + 4) + k + 1, k + 1) & 0xffffff);
    }
}
