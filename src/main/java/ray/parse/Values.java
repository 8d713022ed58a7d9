package ray.parse;

import java.math.BigInteger;
import java.util.Collection;
import javax.vecmath.Vector3d;

/**
 * The values of a scene file: whole numbers, finite decimal numbers, {@code [x y z]} vectors, and the
 * quoting of what was found in messages. Decimals and vectors are read from a range of a line's chars
 * (what {@link Words} found), making no String unless a message needs one; the String forms are for
 * globals and OBJ files. Nothing here uses a regular expression or recursion, so the cost is linear in
 * the (already bounded) line length.
 */
final class Values {

    /** Longest piece of the file quoted in a message; longer ones are cut with "...". */
    static final int QUOTE_MAX = 60;

    private Values() {
    }

    /** {@code s} in single quotes, cut to {@link #QUOTE_MAX} characters, invisible characters escaped. */
    static String quote(String s) {
        StringBuilder b = new StringBuilder(Math.min(s.length(), QUOTE_MAX) + 8).append('\'');
        int n = Math.min(s.length(), QUOTE_MAX);
        for (int i = 0; i < n; i++) {
            char c = s.charAt(i);
            if (c == '\t') {
                b.append("\\t");
            } else if (invisible(c)) {
                b.append(String.format("\\u%04X", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.append(s.length() > n ? "...'" : "'").toString();
    }

    static boolean invisible(char c) {
        if (c < 0x20 || c == 0x7f) {
            return true;
        }
        if (c < 0x80) {
            return false;
        }
        int t = Character.getType(c);
        return t == Character.CONTROL || t == Character.FORMAT || t == Character.SURROGATE || t == Character.UNASSIGNED
                || t == Character.PRIVATE_USE || Character.isWhitespace(c) || Character.isSpaceChar(c);
    }

    /** A whole number in [min, max]; {@code what} names the field or setting. */
    static long parseWhole(String s, String what, long min, long max) throws Problem {
        String expected = " (expected an integer from " + min + " to " + max + ")";
        if (!isWhole(s)) {
            throw new Problem(quote(s) + " is not a whole number for " + what + expected);
        }
        Long v = wholeValue(s);
        if (v == null || v < min || v > max) {
            throw new Problem(quote(s) + " is out of range for " + what + expected);
        }
        return v;
    }

    /** [+-] digits: what a whole number looks like, whatever its size. */
    static boolean isWhole(String s) {
        int i = s.startsWith("+") || s.startsWith("-") ? 1 : 0;
        if (i == s.length()) {
            return false;
        }
        for (; i < s.length(); i++) {
            if (!isDigit(s.charAt(i))) {
                return false;
            }
        }
        return true;
    }

    /** The value of a string that {@link #isWhole}, or null when it does not fit a long. */
    static Long wholeValue(String s) {
        int i = s.startsWith("+") || s.startsWith("-") ? 1 : 0;
        while (i < s.length() - 1 && s.charAt(i) == '0') {
            i++;
        }
        if (s.length() - i > 19) {        // more digits than any long: no need to convert
            return null;
        }
        BigInteger v = new BigInteger((s.startsWith("-") ? "-" : "") + s.substring(i));
        return v.bitLength() < 64 ? v.longValue() : null;
    }

    /** A finite decimal number; NaN, infinities, hex and overflow are refused. */
    static double parseDouble(String s, String what) throws Problem {
        return parseDouble(s.toCharArray(), 0, s.length(), what);
    }

    /** {@link #parseDouble(String, String)} of chars [from, to) of {@code c}. */
    static double parseDouble(char[] c, int from, int to, String what) throws Problem {
        String expected = " (expected a decimal number such as 1.5 or -2e3)";
        double d = Tokens.decimal(c, from, to);
        if (Double.isNaN(d)) {
            String s = new String(c, from, to - from);
            throw new Problem(quote(s) + (isNonFiniteWord(s) ? " is not a finite number for " : " is not a number for ") + what + expected);
        }
        if (!Double.isFinite(d)) {
            throw new Problem(quote(new String(c, from, to - from)) + " is too large for " + what
                    + " (expected a finite number, at most about 1.8e308)");
        }
        return d;
    }

    /** NaN, Infinity or inf in any case, with or without a sign: the usual ways to write a non-finite number. */
    static boolean isNonFiniteWord(String s) {
        String t = s.startsWith("+") || s.startsWith("-") ? s.substring(1) : s;
        return t.equalsIgnoreCase("nan") || t.equalsIgnoreCase("infinity") || t.equalsIgnoreCase("inf");
    }

    /** [+-] digits [. digits] [e [+-] digits], or starting with the point; no NaN, Infinity, hex or suffix. */
    static boolean isDecimal(String s) {
        return isDecimal(s.toCharArray(), 0, s.length());
    }

    /** {@link #isDecimal(String)} of chars [from, to) of {@code s}. */
    static boolean isDecimal(char[] s, int from, int to) {
        return Tokens.isDecimal(s, from, to);
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** {@code [x y z]}: three finite numbers in brackets, separated by spaces or commas. */
    static Vector3d parseVector(String s, String what) throws Problem {
        return parseVector(s.toCharArray(), 0, s.length(), what);
    }

    /** {@link #parseVector(String, String)} of chars [from, to) of {@code c}. */
    static Vector3d parseVector(char[] c, int from, int to, String what) throws Problem {
        String expected = " (expected [x y z], three numbers in brackets)";
        if (to == from || c[from] != '[') {
            throw new Problem(malformed(c, from, to, what) + "missing '['" + expected);
        }
        if (to - from < 2 || c[to - 1] != ']') {
            throw new Problem(malformed(c, from, to, what) + "missing ']'" + expected);
        }
        int x0 = 0, x1 = 0, y0 = 0, y1 = 0, z0 = 0, z1 = 0, parts = 0;
        int i = from + 1, end = to - 1;
        while (i < end) {      // separators: commas and whitespace (tested in line: the JIT's first tier inlines one level)
            while (i < end && (c[i] == ',' || Words.isSpace(c[i]))) i++;
            int start = i;
            // a number's chars (digits . - e) are above ',' and ASCII: no separator, told with two comparisons
            while (i < end && (c[i] > ',' && c[i] < '\u0080' || c[i] != ',' && !Words.isSpace(c[i]))) i++;
            if (i > start) {
                if (parts == 3) {       // count the rest without keeping it
                    int more = 1;
                    while (i < end) {
                        while (i < end && (c[i] == ',' || Words.isSpace(c[i]))) i++;
                        if (i < end) more++;
                        while (i < end && c[i] != ',' && !Words.isSpace(c[i])) i++;
                    }
                    throw new Problem(malformed(c, from, to, what) + "found " + (3 + more) + " numbers" + expected);
                }
                if (parts == 0) {
                    x0 = start;
                    x1 = i;
                } else if (parts == 1) {
                    y0 = start;
                    y1 = i;
                } else {
                    z0 = start;
                    z1 = i;
                }
                parts++;
            }
        }
        if (parts != 3) {
            throw new Problem(malformed(c, from, to, what) + "found " + parts + (parts == 1 ? " number" : " numbers") + expected);
        }
        double x = Tokens.decimal(c, x0, x1), y = Tokens.decimal(c, y0, y1), z = Tokens.decimal(c, z0, z1);
        if (Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z)) {     // NaN: not a decimal
            return new Vector3d(x, y, z);
        }
        // a number is wrong: the first one, in order, says what
        component(c, x0, x1, from, to, what, expected);
        component(c, y0, y1, from, to, what, expected);
        component(c, z0, z1, from, to, what, expected);
        throw new AssertionError("a vector component that is wrong was not reported");
    }

    /** One number [p0, p1) of the vector [from, to), or the Problem that it is not a finite decimal. */
    private static double component(char[] c, int p0, int p1, int from, int to, String what, String expected) throws Problem {
        double v = Tokens.decimal(c, p0, p1);
        if (Double.isNaN(v)) {
            String p = new String(c, p0, p1 - p0);
            throw new Problem(malformed(c, from, to, what) + quote(p) + (isNonFiniteWord(p) ? " is not a finite number" : " is not a number")
                    + expected);
        }
        if (!Double.isFinite(v)) {
            throw new Problem(malformed(c, from, to, what) + quote(new String(c, p0, p1 - p0))
                    + " is too large (expected finite numbers, at most about 1.8e308)");
        }
        return v;
    }

    /** The start of every message about a malformed vector (made only when one is reported). */
    private static String malformed(char[] c, int from, int to, String what) {
        return "malformed vector " + quote(new String(c, from, to - from)) + " for " + what + ": ";
    }

    /** The option equal to {@code s} but for case, as a "did you mean" hint ending in "; ", or "". */
    static String caseHint(String s, Collection<String> options) {
        for (String o : options) {
            if (o.equalsIgnoreCase(s) && !o.equals(s)) {
                return "did you mean '" + o + "'? names are case-sensitive; ";
            }
        }
        return "";
    }
}
