package ray.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The builder keeps boxes as {@link BvhBuilder#key}s so that its minima and maxima are int comparisons
 * (conditional moves) instead of float ones (branches). That is right only if keys order exactly as their
 * floats do and come back as the same floats: checked on every pair of a list of awkward floats (both
 * zeros, subnormals, the largest and smallest normals, infinities, neighbours one ulp apart) and on seeded
 * random floats of every sign and exponent. A mapping that forgot to flip a negative float's bits, or
 * flipped its sign bit too, or kept -0 below +0, fails here.
 */
class BvhKeyTest {

    private static final long SEED = 20261204L;

    private static final float[] AWKWARD = {
        0f, -0f, Float.MIN_VALUE, -Float.MIN_VALUE, Float.MIN_NORMAL, -Float.MIN_NORMAL,
        Math.nextDown(Float.MIN_NORMAL), -Math.nextDown(Float.MIN_NORMAL), 1f, -1f, Math.nextUp(1f), Math.nextDown(1f),
        -Math.nextUp(1f), -Math.nextDown(1f), 0.5f, -0.5f, 3.4e38f, -3.4e38f, Float.MAX_VALUE, -Float.MAX_VALUE,
        Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, 1e-30f, -1e-30f, 12f, -12f, 1.1f, -1.1f,
    };

    private static void checkPair(float a, float b) {
        int ka = BvhBuilder.key(a), kb = BvhBuilder.key(b);
        String what = a + " vs " + b;
        assertEquals(Float.compare(a == 0 ? 0f : a, b == 0 ? 0f : b) < 0, ka < kb, what + " (<)");
        assertEquals(a == b, ka == kb, what + " (==)");
        assertEquals(a > b, ka > kb, what + " (>)");
    }

    private static void checkRoundTrip(float a) {
        float back = BvhBuilder.unkey(BvhBuilder.key(a));
        // the same float, bit for bit, except that -0 comes back as +0 (the same value in every box test)
        assertEquals(Float.floatToRawIntBits(a == 0 ? 0f : a), Float.floatToRawIntBits(back), "round trip of " + a);
    }

    @Test
    void keysOrderAsTheirFloatsAndComeBack() {
        for (float a : AWKWARD) {
            checkRoundTrip(a);
            for (float b : AWKWARD) {
                checkPair(a, b);
            }
        }
        Random r = new Random(SEED);
        for (int i = 0; i < 200_000; i++) {
            float a = randomFloat(r), b = i % 4 == 0 ? (r.nextBoolean() ? Math.nextUp(a) : Math.nextDown(a)) : randomFloat(r);
            if (Float.isNaN(a) || Float.isNaN(b)) {
                continue;
            }
            checkRoundTrip(a);
            checkPair(a, b);
        }
    }

    /** A float of random sign, exponent and mantissa (NaN left to the caller to skip). */
    private static float randomFloat(Random r) {
        return Float.intBitsToFloat(r.nextInt());
    }

    @Test
    void bothZerosAreOneKeyBetweenTheSmallestOfEachSign() {
        assertEquals(0, BvhBuilder.key(0f));
        assertEquals(0, BvhBuilder.key(-0f));
        assertEquals(1, BvhBuilder.key(Float.MIN_VALUE));
        assertEquals(-2, BvhBuilder.key(-Float.MIN_VALUE));   // -1 would have been -0's: unused
    }
}
