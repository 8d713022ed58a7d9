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
     * {@code Parser.isDecimal(s.substring(from, to))} without the substring: [+-] digits [. digits]
     * [e [+-] digits], or starting with the point; ASCII digits only.
     */
    static boolean isDecimal(String s, int from, int to) {
        int i = from;
        if (i < to && (s.charAt(i) == '+' || s.charAt(i) == '-')) i++;
        int digits = 0;
        while (i < to && isDigit(s.charAt(i))) { i++; digits++; }
        if (i < to && s.charAt(i) == '.') {
            i++;
            while (i < to && isDigit(s.charAt(i))) { i++; digits++; }
        }
        if (digits == 0) return false;
        if (i < to && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            i++;
            if (i < to && (s.charAt(i) == '+' || s.charAt(i) == '-')) i++;
            int e = 0;
            while (i < to && isDigit(s.charAt(i))) { i++; e++; }
            if (e == 0) return false;
        }
        return i == to;
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** {@link #parseDecimal(String, int, int)} of the whole string. */
    static double parseDecimal(String s) {
        return parseDecimal(s, 0, s.length());
    }

    /**
     * {@code Double.parseDouble(s.substring(from, to))}, bit for bit, for a range that
     * {@link #isDecimal} accepted. Numbers with at most 15 significant digits and a decimal exponent
     * within ±22 take Clinger's fast path: the digits and the power of ten are both exact doubles, so
     * one IEEE multiply or divide gives the correctly rounded result, as {@code parseDouble} does.
     * Anything else goes to {@code parseDouble}.
     */
    static double parseDecimal(String s, int from, int to) {
        int i = from, n = to;
        boolean neg = false;
        char c0 = s.charAt(from);
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
                    return Double.parseDouble(s.substring(from, to));
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
                        return Double.parseDouble(s.substring(from, to));
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
                return Double.parseDouble(s.substring(from, to));
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
                    return Double.parseDouble(s.substring(from, to));
                }
                v /= POW10[-exp];
            } else if (exp > 0) {
                if (exp > 22) {
                    return Double.parseDouble(s.substring(from, to));
                }
                v *= POW10[exp];
            }
        }
        return neg ? -v : v;
    }

    /** {@link #isDecimal(String, int, int)} on the bytes of an ASCII text. */
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

    /** {@link #parseDecimal(String, int, int)} on the bytes of an ASCII text (the same arithmetic). */
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

    /** {@link #canonicalVector(String)} of the bytes [from, to) of an ASCII text. */
    static double[] canonicalVector(byte[] s, int from, int to) {
        int n = to - from;
        if (n < 7 || s[from] != '[' || s[to - 1] != ']') {
            return null;
        }
        int a = -1, b = -1;
        for (int i = from + 1; i < to - 1; i++) {
            if (s[i] == ' ') {
                if (a < 0) {
                    a = i;
                } else if (b < 0) {
                    b = i;
                } else {
                    return null;
                }
            }
        }
        if (b < 0 || !isDecimal(s, from + 1, a) || !isDecimal(s, a + 1, b) || !isDecimal(s, b + 1, to - 1)) {
            return null;
        }
        double x = parseDecimal(s, from + 1, a), y = parseDecimal(s, a + 1, b), z = parseDecimal(s, b + 1, to - 1);
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            return null;
        }
        return new double[] {x, y, z};
    }

    /**
     * Splits a canonical line into {@code split(line, false, 3)}'s tokens, or returns null when the
     * line is not canonical: non-empty, printable ASCII and single spaces only, no '#', no space at
     * either end. For such a line {@code stripComment(line).strip()} is the line itself and the
     * regular split is just a cut at the first two spaces, so the parser's general path would see
     * exactly these tokens.
     */
    static String[] canonicalWords(String line) {
        int n = line.length();
        if (n == 0 || line.charAt(0) == ' ' || line.charAt(n - 1) == ' ') {
            return null;
        }
        int first = -1, second = -1;
        char prev = 'x';
        for (int i = 0; i < n; i++) {
            char c = line.charAt(i);
            if (c == ' ') {
                if (prev == ' ') {
                    return null;
                }
                if (first < 0) {
                    first = i;
                } else if (second < 0) {
                    second = i;
                }
            } else if (c < 0x21 || c > 0x7E || c == '#') {
                return null;
            }
            prev = c;
        }
        if (first < 0) {
            return new String[] {line};
        }
        if (second < 0) {
            return new String[] {line.substring(0, first), line.substring(first + 1)};
        }
        return new String[] {line.substring(0, first), line.substring(first + 1, second), line.substring(second + 1)};
    }

    /**
     * The three numbers of a canonical vector {@code [x y z]} (single spaces, no commas, no spaces
     * inside the brackets' ends, each a decimal that {@link #isDecimal} accepts), or null for anything
     * else, which the parser's general path then reads (and reports).
     */
    static double[] canonicalVector(String s) {
        int n = s.length();
        if (n < 7 || s.charAt(0) != '[' || s.charAt(n - 1) != ']') {
            return null;
        }
        int a = s.indexOf(' ', 1);
        if (a < 0) {
            return null;
        }
        int b = s.indexOf(' ', a + 1);
        if (b < 0 || s.indexOf(' ', b + 1) >= 0 || s.indexOf(',') >= 0) {
            return null;
        }
        if (!isDecimal(s, 1, a) || !isDecimal(s, a + 1, b) || !isDecimal(s, b + 1, n - 1)) {
            return null;
        }
        double x = parseDecimal(s, 1, a), y = parseDecimal(s, a + 1, b), z = parseDecimal(s, b + 1, n - 1);
        if (!Double.isFinite(x) || !Double.isFinite(y) || !Double.isFinite(z)) {
            return null;
        }
        return new double[] {x, y, z};
    }
}
