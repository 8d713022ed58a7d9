package ray.parse;

/**
 * The scene format's decimal numbers, read in one pass: {@code [+-] digits [. digits] [e [+-] digits]}
 * (or starting with the point; no NaN, Infinity, hex or suffix), from a range of a line's chars
 * without making a String. A 15 MB scene has about a million numbers.
 */
final class Tokens {

    private Tokens() {
    }

    private static final double[] POW10 = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    /**
     * The decimal chars [from, to) of {@code s} write: exactly {@code Double.parseDouble}'s value, bit
     * for bit (infinite when it overflows), or NaN when they are not one of the format's decimals (a
     * decimal is never NaN). Numbers with at most 15 significant digits and a decimal exponent within
     * ±22 take Clinger's fast path: the digits and the power of ten are both exact doubles, so one IEEE
     * multiply or divide gives the correctly rounded result, as {@code parseDouble} does; anything
     * else, once its shape is checked, goes to {@code parseDouble}.
     */
    static double decimal(char[] s, int from, int to) {
        return read(s, from, to, DOUBLE);
    }

    /**
     * The decimal chars [from, to) of {@code s} (as {@link #isDecimal} accepts them) as a float: exactly
     * {@code Float.parseFloat}'s value, bit for bit. At most 7 significant digits (below 2^24) and a
     * decimal exponent within ±10 take Clinger's fast path in float arithmetic (both are exact floats:
     * one IEEE float multiply or divide rounds once, correctly); anything else goes to {@code parseFloat}.
     * NaN when they are not a decimal.
     */
    static float decimalFloat(char[] s, int from, int to) {
        return (float) read(s, from, to, FLOAT);     // a float's value, exact as a double
    }

    /** Whether chars [from, to) of {@code s} are one of the format's decimals (the shape alone: no value is worked out). */
    static boolean isDecimal(char[] s, int from, int to) {
        return !Double.isNaN(read(s, from, to, SHAPE));
    }

    private static final int SHAPE = 0, DOUBLE = 1, FLOAT = 2;

    private static final float[] POW10F = {1e0f, 1e1f, 1e2f, 1e3f, 1e4f, 1e5f, 1e6f, 1e7f, 1e8f, 1e9f, 1e10f};

    /** The one reader of all three: NaN when not a decimal; else the value as {@code value} asks, or 0 for the shape alone. */
    private static double read(char[] s, int from, int to, int value) {
        int i = from;
        boolean neg = false;
        if (i < to && (s[i] == '+' || s[i] == '-')) {
            neg = s[i] == '-';
            i++;
        }
        long m = 0;
        int digits = 0, significant = 0, exp = 0;
        boolean slow = false;
        for (; i < to && s[i] >= '0' && s[i] <= '9'; i++) {
            digits++;
            if (m != 0 || s[i] != '0') {
                if (++significant > 15) {
                    slow = true;
                }
                m = 10 * m + (s[i] - '0');     // only read when not slow: at most 15 digits, exact
            }
        }
        if (i < to && s[i] == '.') {
            for (i++; i < to && s[i] >= '0' && s[i] <= '9'; i++) {
                digits++;
                if (m != 0 || s[i] != '0') {
                    if (++significant > 15) {
                        slow = true;
                    }
                    m = 10 * m + (s[i] - '0');
                }
                exp--;
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        if (i < to && (s[i] == 'e' || s[i] == 'E')) {
            i++;
            boolean eneg = false;
            if (i < to && (s[i] == '+' || s[i] == '-')) {
                eneg = s[i] == '-';
                i++;
            }
            int e = 0, eDigits = 0;
            for (; i < to && s[i] >= '0' && s[i] <= '9'; i++) {
                if (++eDigits <= 4) {
                    e = 10 * e + (s[i] - '0');
                }
            }
            if (eDigits == 0) {
                return Double.NaN;
            }
            if (eDigits > 4) {
                slow = true;
            }
            exp += eneg ? -e : e;
        }
        if (i != to) {
            return Double.NaN;
        }
        if (value == SHAPE) {
            return 0;
        }
        if (value == FLOAT) {
            if (slow || significant > 7 || exp < -10 || exp > 10) {
                return m == 0 && !slow ? (neg ? -0.0 : 0.0) : Float.parseFloat(new String(s, from, to - from));
            }
            float f = m;    // exact: m < 10^7 < 2^24
            if (exp < 0) {
                f /= POW10F[-exp];
            } else if (exp > 0) {
                f *= POW10F[exp];
            }
            return neg ? -f : f;
        }
        if (slow || exp < -22 || exp > 22) {
            return m == 0 && !slow ? (neg ? -0.0 : 0.0) : Double.parseDouble(new String(s, from, to - from));
        }
        double v = m;   // exact: m < 10^15 < 2^53
        if (exp < 0) {
            v /= POW10[-exp];
        } else if (exp > 0) {
            v *= POW10[exp];
        }
        return neg ? -v : v;
    }
}
