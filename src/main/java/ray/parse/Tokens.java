package ray.parse;

/**
 * The parser's number reading, fast: a 15 MB scene has about a million numbers. Each method gives
 * exactly what the plain form it stands for gives ({@link Values#isDecimal}, {@code Double.parseDouble},
 * {@link Values#parseVector}; checked against them in the tests), on Strings for the general path and
 * on the bytes of an ASCII line for the parser's fast path.
 */
final class Tokens {

    private Tokens() {
    }

    private static final double[] POW10 = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    /**
     * {@code Double.parseDouble(s)}, bit for bit, for a string that {@link Values#isDecimal} accepted.
     * Numbers with at most 15 significant digits and a decimal exponent within ±22 take Clinger's fast path: the digits and the power of ten are both exact doubles, so
     * one IEEE multiply or divide gives the correctly rounded result, as {@code parseDouble} does.
     * Anything else goes to {@code parseDouble}.
     */
    static double parseDecimal(String s) {
        int i = 0, n = s.length();
        boolean neg = false;
        char c0 = s.charAt(0);
        if (c0 == '+' || c0 == '-') {
            neg = c0 == '-';
            i++;
        }
        long m = 0;
        int digits = 0, exp = 0;
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c < '0' || c > '9') {
                break;
            }
            if (m != 0 || c != '0') {
                if (++digits > 15) {
                    return Double.parseDouble(s);
                }
            }
            m = 10 * m + (c - '0');
        }
        if (i < n && s.charAt(i) == '.') {
            for (i++; i < n; i++) {
                char c = s.charAt(i);
                if (c < '0' || c > '9') {
                    break;
                }
                if (m != 0 || c != '0') {
                    if (++digits > 15) {
                        return Double.parseDouble(s);
                    }
                }
                m = 10 * m + (c - '0');
                exp--;
            }
        }
        if (i < n) {   // 'e' or 'E' with at least one digit (isDecimal checked the shape)
            i++;
            boolean eneg = false;
            char c = s.charAt(i);
            if (c == '+' || c == '-') {
                eneg = c == '-';
                i++;
            }
            if (n - i > 4) {
                return Double.parseDouble(s);
            }
            int e = 0;
            for (; i < n; i++) {
                e = 10 * e + (s.charAt(i) - '0');
            }
            exp += eneg ? -e : e;
        }
        double v = m;   // exact: m < 10^15 < 2^53
        if (m != 0) {
            if (exp < 0) {
                if (exp < -22) {
                    return Double.parseDouble(s);
                }
                v /= POW10[-exp];
            } else if (exp > 0) {
                if (exp > 22) {
                    return Double.parseDouble(s);
                }
                v *= POW10[exp];
            }
        }
        return neg ? -v : v;
    }

    /** {@code Values.isDecimal} of bytes [from, to) of an ASCII text, without making a String. */
    static boolean isDecimal(byte[] s, int from, int to) {
        int i = from;
        if (i < to && (s[i] == '+' || s[i] == '-')) i++;
        int digits = 0;
        while (i < to && s[i] >= '0' && s[i] <= '9') { i++; digits++; }
        if (i < to && s[i] == '.') {
            i++;
            while (i < to && s[i] >= '0' && s[i] <= '9') { i++; digits++; }
        }
        if (digits == 0) return false;
        if (i < to && (s[i] == 'e' || s[i] == 'E')) {
            i++;
            if (i < to && (s[i] == '+' || s[i] == '-')) i++;
            int e = 0;
            while (i < to && s[i] >= '0' && s[i] <= '9') { i++; e++; }
            if (e == 0) return false;
        }
        return i == to;
    }

    /** {@link #parseDecimal(String)} of bytes [from, to) of an ASCII text that {@link #isDecimal} accepted (the same arithmetic). */
    static double parseDecimal(byte[] s, int from, int to) {
        int i = from;
        boolean neg = false;
        if (s[from] == '+' || s[from] == '-') {
            neg = s[from] == '-';
            i++;
        }
        long m = 0;
        int digits = 0, exp = 0;
        for (; i < to && s[i] >= '0' && s[i] <= '9'; i++) {
            if ((m != 0 || s[i] != '0') && ++digits > 15) {
                return slowDecimal(s, from, to);
            }
            m = 10 * m + (s[i] - '0');
        }
        if (i < to && s[i] == '.') {
            for (i++; i < to && s[i] >= '0' && s[i] <= '9'; i++) {
                if ((m != 0 || s[i] != '0') && ++digits > 15) {
                    return slowDecimal(s, from, to);
                }
                m = 10 * m + (s[i] - '0');
                exp--;
            }
        }
        if (i < to) {   // 'e' or 'E' with at least one digit
            i++;
            boolean eneg = false;
            if (s[i] == '+' || s[i] == '-') {
                eneg = s[i] == '-';
                i++;
            }
            if (to - i > 4) {
                return slowDecimal(s, from, to);
            }
            int e = 0;
            for (; i < to; i++) {
                e = 10 * e + (s[i] - '0');
            }
            exp += eneg ? -e : e;
        }
        double v = m;
        if (m != 0) {
            if (exp < 0) {
                if (exp < -22) {
                    return slowDecimal(s, from, to);
                }
                v /= POW10[-exp];
            } else if (exp > 0) {
                if (exp > 22) {
                    return slowDecimal(s, from, to);
                }
                v *= POW10[exp];
            }
        }
        return neg ? -v : v;
    }

    private static double slowDecimal(byte[] s, int from, int to) {
        return Double.parseDouble(new String(s, from, to - from, java.nio.charset.StandardCharsets.ISO_8859_1));
    }

    /**
     * The three numbers of a plain vector {@code [x y z]} in bytes [from, to) of an ASCII text: single
     * spaces, no commas, nothing inside the brackets' ends, each number one that {@link #isDecimal}
     * accepts and finite. Null for anything else, which {@link Values#parseVector} then reads (and
     * reports); for a plain vector it gives exactly these numbers.
     */
    static double[] canonicalVector(byte[] s, int from, int to) {
        double[] out = new double[3];
        return canonicalVector(s, from, to, out) ? out : null;
    }

    /** {@link #canonicalVector(byte[], int, int)} into {@code out} (no allocation): false where that returns null. */
    static boolean canonicalVector(byte[] s, int from, int to, double[] out) {
        int n = to - from;
        if (n < 7 || s[from] != '[' || s[to - 1] != ']') {
            return false;
        }
        int a = -1, b = -1;
        for (int i = from + 1; i < to - 1; i++) {
            if (s[i] == ' ') {
                if (a < 0) {
                    a = i;
                } else if (b < 0) {
                    b = i;
                } else {
                    return false;
                }
            }
        }
        if (b < 0 || !isDecimal(s, from + 1, a) || !isDecimal(s, a + 1, b) || !isDecimal(s, b + 1, to - 1)) {
            return false;
        }
        double x = parseDecimal(s, from + 1, a), y = parseDecimal(s, a + 1, b), z = parseDecimal(s, b + 1, to - 1);
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            return false;
        }
        out[0] = x;
        out[1] = y;
        out[2] = z;
        return true;
    }
}
