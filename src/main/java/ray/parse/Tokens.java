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
        return read(s, from, to, true);
    }

    /** Whether chars [from, to) of {@code s} are one of the format's decimals (the shape alone: no value is worked out). */
    static boolean isDecimal(char[] s, int from, int to) {
        return !Double.isNaN(read(s, from, to, false));
    }

    /** The one reader of both: NaN when not a decimal; else the value, or 0 when {@code value} is false. */
    private static double read(char[] s, int from, int to, boolean value) {
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
        if (!value) {
            return 0;
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
