package ray.parse;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The parser's regex-free helpers must give exactly what the regular expressions and
 * {@code Double.parseDouble} they replace give; any difference would change what a scene means.
 */
class TokensTest {

    private static final String ALPHABET = "ab, \t\u000B\f\r\u001F\u00A0#[]-+.e0123456789";

    private static String randomString(Random r, int maxLen) {
        int n = r.nextInt(maxLen + 1);
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < n; i++) {
            b.append(ALPHABET.charAt(r.nextInt(ALPHABET.length())));
        }
        return b.toString();
    }

    /** Guards the leading-empty, limit and trailing-empty rules of Pattern.split. */
    @Test
    void splitMatchesRegexSplitOnRandomStrings() {
        Random r = new Random(465);
        for (int k = 0; k < 200_000; k++) {
            String s = randomString(r, 12);
            for (int limit : new int[] {0, 1, 2, 3, -1}) {
                assertArrayEquals(s.split("\\s+", limit), Tokens.split(s, false, limit), () -> "'" + s + "' limit " + limit);
                assertArrayEquals(s.split("[\\s,]+", limit), Tokens.split(s, true, limit), () -> "'" + s + "' commas, limit " + limit);
            }
        }
    }

    @Test
    void splitOfTypicalLinesGivesTheirWords() {
        assertArrayEquals(new String[] {"Vector3d", "v0", "[1 2 3]"}, Tokens.split("Vector3d v0 [1 2 3]", false, 3));
        assertArrayEquals(new String[] {"1", "2", "3"}, Tokens.split("1,  2\t3", true, 0));
        assertArrayEquals(new String[] {"", "1"}, Tokens.split(",1,", true, 0));
        assertArrayEquals(new String[] {""}, Tokens.split("", true, 0));
    }

    @Test
    void isIntegerMatchesTheRegex() {
        Random r = new Random(7);
        for (int k = 0; k < 100_000; k++) {
            String s = randomString(r, 5);
            assertEquals(s.matches("[+-]?[0-9]+"), Tokens.isInteger(s), () -> "'" + s + "'");
        }
        assertEquals(false, Tokens.isInteger("\u0661"));   // an Arabic-Indic digit is not [0-9]
    }

    /** Bit-for-bit equality with parseDouble, including -0, long mantissas and far exponents. */
    @Test
    void parseDecimalIsBitIdenticalToParseDouble() {
        Random r = new Random(2003);
        String[] fixed = {"0", "-0", "+0.0", "1", "-1.5", ".5", "5.", "0.1", "0.3", "1e22", "1e23", "9007199254740993",
            "123456789012345", "1234567890123456", "0.000000000000000000000001", "1.7976931348623157e308", "4.9e-324",
            "2.2250738585072014E-308", "1e-22", "1e-23", "999999999999999e22", "0.12345", "-12.345e-3", "00000000000000000001.5"};
        for (String s : fixed) {
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)), Double.doubleToRawLongBits(Tokens.parseDecimal(s)), s);
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
            if (!Values.isDecimal(s)) {
                continue;
            }
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(s)), Double.doubleToRawLongBits(Tokens.parseDecimal(s)), s);
        }
    }

    /** The fast path may only take lines on which the general path would see the very same words. */
    @Test
    void canonicalWordsAgreeWithStripAndSplit() {
        Random r = new Random(11);
        String alphabet = "ab #\t[]1.";
        int taken = 0;
        for (int k = 0; k < 200_000; k++) {
            int n = r.nextInt(10);
            StringBuilder b = new StringBuilder();
            for (int i = 0; i < n; i++) b.append(alphabet.charAt(r.nextInt(alphabet.length())));
            String line = b.toString();
            String[] words = Tokens.canonicalWords(line);
            if (words == null) continue;
            taken++;
            assertEquals(-1, line.indexOf('#'), line);
            assertEquals(line.strip(), line, line);
            assertArrayEquals(line.split("\\s+", 3), words, line);
        }
        assertEquals(true, taken > 10_000, "the fast path should take most plain lines");
    }

    @Test
    void canonicalVectorReadsOnlyPlainVectorsAndReadsThemExactly() {
        Random r = new Random(12);
        String alphabet = "[] ,\t-.e0123456789";
        int taken = 0;
        for (int k = 0; k < 300_000; k++) {
            int n = 2 + r.nextInt(14);
            StringBuilder b = new StringBuilder("[");
            for (int i = 0; i < n; i++) b.append(alphabet.charAt(r.nextInt(alphabet.length())));
            b.append(']');
            String s = b.toString();
            double[] v = Tokens.canonicalVector(s);
            if (v == null) continue;
            taken++;
            String[] parts = s.substring(1, s.length() - 1).strip().split("[\\s,]+");
            assertEquals(3, parts.length, s);
            for (int i = 0; i < 3; i++) {
                assertEquals(true, Values.isDecimal(parts[i]), s);
                assertEquals(Double.doubleToRawLongBits(Double.parseDouble(parts[i])), Double.doubleToRawLongBits(v[i]), s);
            }
        }
        assertEquals(true, taken > 100, "some random vectors are plain");
        assertArrayEquals(new double[] {1, -2.5, 3e-3}, Tokens.canonicalVector("[1 -2.5 3e-3]"));
        assertEquals(null, Tokens.canonicalVector("[1, 2, 3]"));      // commas: the general path's job
        assertEquals(null, Tokens.canonicalVector("[1 2 1e999]"));    // too large: the general path reports it
    }
}
