package ray.parse;

import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import javax.vecmath.Vector3d;

/**
 * The values of a scene file: whole numbers, finite decimal numbers, {@code [x y z]} vectors, and the
 * quoting of what was found in messages. Nothing here uses a regular expression or recursion, so
 * the cost is linear in the (already bounded) line length.
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
        String expected = " (expected a decimal number such as 1.5 or -2e3)";
        if (isNonFiniteWord(s)) {
            throw new Problem(quote(s) + " is not a finite number for " + what + expected);
        }
        if (!isDecimal(s)) {
            throw new Problem(quote(s) + " is not a number for " + what + expected);
        }
        double d = Tokens.parseDecimal(s);
        if (!Double.isFinite(d)) {
            throw new Problem(quote(s) + " is too large for " + what + " (expected a finite number, at most about 1.8e308)");
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
        int i = 0, n = s.length();
        if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) i++;
        int digits = 0;
        while (i < n && isDigit(s.charAt(i))) { i++; digits++; }
        if (i < n && s.charAt(i) == '.') {
            i++;
            while (i < n && isDigit(s.charAt(i))) { i++; digits++; }
        }
        if (digits == 0) return false;
        if (i < n && (s.charAt(i) == 'e' || s.charAt(i) == 'E')) {
            i++;
            if (i < n && (s.charAt(i) == '+' || s.charAt(i) == '-')) i++;
            int e = 0;
            while (i < n && isDigit(s.charAt(i))) { i++; e++; }
            if (e == 0) return false;
        }
        return i == n;
    }

    private static boolean isDigit(char c) {
        return c >= '0' && c <= '9';
    }

    /** {@code [x y z]}: three finite numbers in brackets, separated by spaces or commas. */
    static Vector3d parseVector(String s, String what) throws Problem {
        String expected = " (expected [x y z], three numbers in brackets)";
        if (!s.startsWith("[")) {
            throw new Problem(malformed(s, what) + "missing '['" + expected);
        }
        if (s.length() < 2 || !s.endsWith("]")) {
            throw new Problem(malformed(s, what) + "missing ']'" + expected);
        }
        List<String> parts = new ArrayList<>(3);
        int i = 1, end = s.length() - 1;
        while (i < end) {
            while (i < end && separator(s.charAt(i))) i++;
            int start = i;
            while (i < end && !separator(s.charAt(i))) i++;
            if (i > start) {
                if (parts.size() == 3) {       // count the rest without keeping it
                    int more = 1;
                    while (i < end) {
                        while (i < end && separator(s.charAt(i))) i++;
                        if (i < end) more++;
                        while (i < end && !separator(s.charAt(i))) i++;
                    }
                    throw new Problem(malformed(s, what) + "found " + (3 + more) + " numbers" + expected);
                }
                parts.add(s.substring(start, i));
            }
        }
        if (parts.size() != 3) {
            throw new Problem(malformed(s, what) + "found " + parts.size() + (parts.size() == 1 ? " number" : " numbers") + expected);
        }
        double[] v = new double[3];
        for (int k = 0; k < 3; k++) {
            String p = parts.get(k);
            if (isNonFiniteWord(p)) {
                throw new Problem(malformed(s, what) + quote(p) + " is not a finite number" + expected);
            }
            if (!isDecimal(p)) {
                throw new Problem(malformed(s, what) + quote(p) + " is not a number" + expected);
            }
            v[k] = Tokens.parseDecimal(p);
            if (!Double.isFinite(v[k])) {
                throw new Problem(malformed(s, what) + quote(p) + " is too large (expected finite numbers, at most about 1.8e308)");
            }
        }
        return new Vector3d(v[0], v[1], v[2]);
    }

    /** The start of every message about a malformed vector (made only when one is reported). */
    private static String malformed(String s, String what) {
        return "malformed vector " + quote(s) + " for " + what + ": ";
    }

    private static boolean separator(char c) {
        return c == ',' || Character.isWhitespace(c);
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
