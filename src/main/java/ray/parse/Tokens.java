package ray.parse;

import java.util.ArrayList;
import java.util.List;

/**
 * The parser's hot loops without regular expressions: a 15 MB scene has about three million tokens,
 * and {@code String.split("\\s+")} compiles a pattern on every call. Each method here gives exactly
 * the result of the regular-expression form it replaces (checked against it in the tests).
 */
final class Tokens {

    private Tokens() {
    }

    /** A character of the regex class {@code \s}: space, \t, \n, \x0B, \f, \r (not Unicode spaces). */
    static boolean isSpace(char c) {
        return c == ' ' || (c >= '\t' && c <= '\r');
    }

    /**
     * {@code s.split("\\s+", limit)} (with {@code commas}: {@code s.split("[\\s,]+", limit)}), with the
     * same leading-empty-token, limit and trailing-empty-token rules as {@link java.util.regex.Pattern#split}.
     */
    static String[] split(String s, boolean commas, int limit) {
        int n = s.length();
        List<String> parts = null;
        String[] few = new String[3];
        int count = 0, index = 0;
        boolean limited = limit > 0, matched = false;
        int i = 0;
        while (i < n) {
            char c = s.charAt(i);
            if (!(isSpace(c) || (commas && c == ','))) {
                i++;
                continue;
            }
            int start = i;
            while (i < n && (isSpace(s.charAt(i)) || (commas && s.charAt(i) == ','))) {
                i++;
            }
            // a delimiter run [start, i): a positive-width match
            matched = true;
            if (!limited || count < limit - 1) {
                String part = s.substring(index, start);
                if (count < few.length && parts == null) {
                    few[count] = part;
                } else {
                    if (parts == null) {
                        parts = new ArrayList<>(List.of(few).subList(0, count));
                    }
                    parts.add(part);
                }
                count++;
                index = i;
            } else if (count == limit - 1) {
                String part = s.substring(index, n);
                if (count < few.length && parts == null) {
                    few[count] = part;
                } else {
                    if (parts == null) {
                        parts = new ArrayList<>(List.of(few).subList(0, count));
                    }
                    parts.add(part);
                }
                count++;
                index = i;
            }
        }
        if (!matched) {
            return new String[] {s};
        }
        if (!limited || count < limit) {
            String part = s.substring(index, n);
            if (count < few.length && parts == null) {
                few[count] = part;
            } else {
                if (parts == null) {
                    parts = new ArrayList<>(List.of(few).subList(0, count));
                }
                parts.add(part);
            }
            count++;
        }
        String[] all = parts == null ? few : parts.toArray(new String[0]);
        int size = count;
        if (limit == 0) {
            while (size > 0 && all[size - 1].isEmpty()) {
                size--;
            }
        }
        if (all.length == size) {
            return all;
        }
        String[] out = new String[size];
        System.arraycopy(all, 0, out, 0, size);
        return out;
    }

    /** {@code s.matches("[+-]?[0-9]+")}. */
    static boolean isInteger(String s) {
        int i = 0, n = s.length();
        if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) {
            i++;
        }
        if (i == n) {
            return false;
        }
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (c < '0' || c > '9') {
                return false;
            }
        }
        return true;
    }

    private static final double[] POW10 = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

    /**
     * {@code Double.parseDouble(s)} for a string that {@link Parser#isDecimal} accepted, bit for bit.
     * Numbers with at most 15 significant digits and a decimal exponent within ±22 take Clinger's
     * fast path: the digits and the power of ten are both exact doubles, so one IEEE multiply or
     * divide gives the correctly rounded result, as {@code parseDouble} does. Anything else goes to
     * {@code parseDouble}.
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
}
