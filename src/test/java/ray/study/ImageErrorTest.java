package ray.study;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import ray.render.Image;

class ImageErrorTest {

    private static Image filled(int w, int h, double v) {
        Image img = new Image(w, h);
        java.util.Arrays.fill(img.rgb, v);
        return img;
    }

    @Test
    void identicalImagesHaveNoErrorAndInfinitePsnr() {
        ImageError e = ImageError.of(filled(3, 2, 0.4), filled(3, 2, 0.4));
        assertEquals(0, e.rmse);
        assertEquals(Double.POSITIVE_INFINITY, e.psnrDb);
        assertEquals(0, e.maxError);
        assertEquals(0, e.shareOffByMoreThanOneStep);
    }

    @Test
    void oneChannelOfOnePixelOff() {
        Image ref = filled(2, 2, 0.5), img = filled(2, 2, 0.5);
        img.set(1, 0, 0.5, 0.5 + 0.12, 0.5);   // one of 12 channels off by 0.12
        ImageError e = ImageError.of(img, ref);
        assertEquals(Math.sqrt(0.12 * 0.12 / 12), e.rmse, 1e-15);
        assertEquals(-20 * Math.log10(e.rmse), e.psnrDb, 1e-12);
        assertEquals(0.12, e.maxError, 1e-15);
        assertEquals(0.25, e.shareOffByMoreThanOneStep);
    }

    @Test
    void measuredOnTheClampedImage() {
        // 3.0 and 1.0 both show as white; -2 and 0 both as black; NaN as black
        Image ref = filled(1, 1, 1.0), img = filled(1, 1, 3.0);
        assertEquals(0, ImageError.of(img, ref).rmse);
        img.set(0, 0, -2, Double.NaN, 0);
        ref.set(0, 0, 0, 0, 0);
        assertEquals(0, ImageError.of(img, ref).rmse);
    }

    @Test
    void oneStepIsTheThresholdNotOff() {
        Image ref = filled(2, 1, 0.5), img = filled(2, 1, 0.5);
        img.set(0, 0, 0.5 + ImageError.STEP, 0.5, 0.5);              // exactly one step: not "more than one"
        img.set(1, 0, 0.5, 0.5, 0.5 - 1.5 * ImageError.STEP);       // a step and a half: off
        assertEquals(0.5, ImageError.of(img, ref).shareOffByMoreThanOneStep);
    }

    @Test
    void psnrOfKnownErrors() {
        assertEquals(40, ImageError.psnr(0.01), 1e-12);
        assertEquals(20 * Math.log10(255), ImageError.psnr(ImageError.STEP), 1e-12);
    }

    @Test
    void sizesMustAgree() {
        assertThrows(IllegalArgumentException.class, () -> ImageError.of(filled(2, 2, 0), filled(2, 3, 0)));
    }

    @Test
    void worstWindowFindsTheHotSpot() {
        int w = 20, h = 10;
        double[] err = new double[w * h];
        for (int y = 6; y < 9; y++) {
            for (int x = 13; x < 16; x++) {
                err[y * w + x] = 1;
            }
        }
        int[] at = Plots.worstWindow(err, w, h, 3);
        assertEquals(13, at[0]);
        assertEquals(6, at[1]);
    }
}
