package ray.parse;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import java.util.regex.Pattern;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The parser's number reading must accept exactly the scene format's decimals and give exactly what
 * {@code Double.parseDouble} gives; any difference would change what a scene means. Numbers are read
 * where they stand in a line, so every check reads them inside other chars.
 */
class TokensTest {

    /** The scene format's decimal, written as a regular expression: the oracle isDecimal is checked against. */
    private static final Pattern DECIMAL = Pattern.compile("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?");

    private static final String ALPHABET = "ab, \t\u000B\f\r\u001F\u00A0#[]-+.eE0123456789";

    private static String randomString(Random r, int maxLen) {
        int n = r.nextInt(maxLen + 1);
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < n; i++) {
            b.append(ALPHABET.charAt(r.nextInt(ALPHABET.length())));
        }
        return b.toString();
    }

    /** {@code s} inside other chars, as a number stands in a line: "x s y". */
    private static char[] inLine(String s) {
        return ("x " + s + " y").toCharArray();
    }

    private static void assertBitIdentical(String s) {
        long expected = Double.doubleToRawLongBits(Double.parseDouble(s));
        char[] c = inLine(s);
        assertEquals(true, Values.isDecimal(c, 2, 2 + s.length()), s);
        assertEquals(expected, Double.doubleToRawLongBits(Tokens.decimal(c, 2, 2 + s.length())), s);
    }

    @Test
    void isDecimalAcceptsExactlyTheFormatsDecimals() {
        Random r = new Random(7);
        for (int k = 0; k < 200_000; k++) {
            String s = randomString(r, 6);
            boolean expected = DECIMAL.matcher(s).matches();
            assertEquals(expected, Values.isDecimal(inLine(s), 2, 2 + s.length()), () -> "'" + s + "'");
            assertEquals(expected, Values.isDecimal(s), () -> "'" + s + "'");
            if (expected) {
                assertBitIdentical(s);
            } else {
                assertEquals(true, Double.isNaN(Tokens.decimal(inLine(s), 2, 2 + s.length())), s);
            }
        }
    }

    /** Bit-for-bit equality with parseDouble, including -0, long mantissas and far exponents. */
    @Test
    void parseDecimalIsBitIdenticalToParseDouble() {
        Random r = new Random(2003);
        String[] fixed = {"0", "-0", "+0.0", "1", "-1.5", ".5", "5.", "0.1", "0.3", "1e22", "1e23", "9007199254740993",
            "123456789012345", "1234567890123456", "0.000000000000000000000001", "1.7976931348623157e308", "4.9e-324",
            "2.2250738585072014E-308", "1e-22", "1e-23", "999999999999999e22", "0.12345", "-12.345e-3", "00000000000000000001.5",
            "0e99999", "-0e-400", "-0.0e-30", "1e99999", "-1e-99999", "1234567890123456789e-5", "0.0000000000000000000000000001234",
            "1e0022", "1e00022", "5.e-3", ".5E+2"};
        for (String s : fixed) {
            assertBitIdentical(s);
        }
        for (int k = 0; k < 300_000; k++) {
            StringBuilder b = new StringBuilder();
            if (r.nextInt(3) == 0) b.append(r.nextBoolean() ? '-' : '+');
            int intDigits = r.nextInt(10), fracDigits = r.nextInt(12);
            for (int i = 0; i < intDigits; i++) b.append((char) ('0' + r.nextInt(10)));
            if (fracDigits > 0 || intDigits == 0) {
                b.append('.');
                for (int i = 0; i < Math.max(1, fracDigits); i++) b.append((char) ('0' + r.nextInt(10)));
            }
            if (r.nextInt(4) == 0) {
                b.append(r.nextBoolean() ? 'e' : 'E');
                if (r.nextBoolean()) b.append(r.nextBoolean() ? '-' : '+');
                b.append(r.nextInt(40));
            }
            String s = b.toString();
            if (!DECIMAL.matcher(s).matches()) {
                continue;
            }
            assertBitIdentical(s);
        }
    }

    /**
     * A vector is three decimals in brackets, separated by any run of commas and whitespace: read
     * inside a line, it is each part's parseDouble, bit for bit; anything else is refused.
     */
    @Test
    void parseVectorReadsThreeDecimalsBetweenAnySeparators() {
        Random r = new Random(12);
        String alphabet = "[] ,\t-.e0123456789";
        int read = 0;
        for (int k = 0; k < 300_000; k++) {
            int n = 2 + r.nextInt(14);
            StringBuilder b = new StringBuilder("[");
            for (int i = 0; i < n; i++) b.append(alphabet.charAt(r.nextInt(alphabet.length())));
            b.append(']');
            String s = b.toString();
            String[] parts = java.util.Arrays.stream(s.substring(1, s.length() - 1).split("[\\s,]+"))
                    .filter(p -> !p.isEmpty()).toArray(String[]::new);
            boolean valid = parts.length == 3;
            for (int i = 0; valid && i < 3; i++) {
                valid = DECIMAL.matcher(parts[i]).matches() && Double.isFinite(Double.parseDouble(parts[i]));
            }
            char[] c = inLine(s);
            if (!valid) {
                assertThrows(Problem.class, () -> Values.parseVector(c, 2, 2 + s.length(), "v"), s);
                continue;
            }
            read++;
            Vector3d v = assertDoesNotThrow(() -> Values.parseVector(c, 2, 2 + s.length(), "v"), s);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(parts[0])), Double.doubleToRawLongBits(v.x), s);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(parts[1])), Double.doubleToRawLongBits(v.y), s);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(parts[2])), Double.doubleToRawLongBits(v.z), s);
        }
        assertEquals(true, read > 100, "some random vectors are valid: " + read);
    }
    /**
     * The OBJ reader's floats: {@code Tokens.decimalFloat} is {@code Float.parseFloat}, bit for bit, on its
     * fast path (at most 7 significant digits, exponent within ±10) and off it (rounding near halfway,
     * subnormals, overflow, long mantissas).
     */
    @Test
    void decimalFloatIsBitIdenticalToParseFloat() {
        Random r = new Random(2026);
        String[] fixed = {"0", "-0", "-0.000000", "+0.0", "1", "-1.5", ".5", "5.", "0.1", "0.3", "1.007818", "-0.006332",
            "16777216", "16777217", "9999999", "99999999", "0.0000001", "1e10", "1e11", "1e-10", "1e-11", "1e38", "3.4028235e38",
            "3.4028236e38", "1e39", "1.4e-45", "7e-46", "1e-50", "0e99", "-0e-99", "1.00000005960464477539", "33554431", "0.1e1"};
        for (String s : fixed) {
            assertFloatIdentical(s);
        }
        for (int k = 0; k < 300_000; k++) {
            StringBuilder b = new StringBuilder();
            if (r.nextInt(3) == 0) {
                b.append(r.nextBoolean() ? '-' : '+');
            }
            int digits = 1 + r.nextInt(r.nextBoolean() ? 8 : 20), point = r.nextInt(digits + 2) - 1;
            for (int i = 0; i < digits; i++) {
                if (i == point) {
                    b.append('.');
                }
                b.append((char) ('0' + (i == 0 && r.nextBoolean() ? 0 : r.nextInt(10))));
            }
            if (r.nextInt(4) == 0) {
                b.append('e').append(r.nextInt(100) - 50);
            }
            assertFloatIdentical(b.toString());
        }
    }

    private static void assertFloatIdentical(String s) {
        char[] c = inLine(s);
        assertEquals(Float.floatToRawIntBits(Float.parseFloat(s)), Float.floatToRawIntBits(Tokens.decimalFloat(c, 2, 2 + s.length())), s);
    }
}
