package ray.parse;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.util.Random;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;

/**
 * The parser's fast number reading must give exactly what {@code Values.isDecimal},
 * {@code Double.parseDouble} and {@code Values.parseVector} give; any difference would change what a
 * scene means.
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

    /** The String and the byte forms both give parseDouble's bits; the byte form reads the number inside other bytes. */
    private static void assertBitIdentical(String s) {
        long expected = Double.doubleToRawLongBits(Double.parseDouble(s));
        assertEquals(expected, Double.doubleToRawLongBits(Tokens.parseDecimal(s)), s);
        byte[] b = ("x " + s + " y").getBytes(StandardCharsets.US_ASCII);
        assertEquals(true, Tokens.isDecimal(b, 2, 2 + s.length()), s);
        assertEquals(expected, Double.doubleToRawLongBits(Tokens.parseDecimal(b, 2, 2 + s.length())), s);
    }

    /** The byte form of isDecimal accepts exactly what Values.isDecimal accepts. */
    @Test
    void byteIsDecimalAgreesWithValuesIsDecimal() {
        Random r = new Random(7);
        for (int k = 0; k < 200_000; k++) {
            String s = randomString(r, 6);
            byte[] b = ("#" + s + "#").getBytes(StandardCharsets.UTF_8);
            if (b.length != s.length() + 2) {
                continue;                       // not ASCII: the byte path never sees it
            }
            assertEquals(Values.isDecimal(s), Tokens.isDecimal(b, 1, 1 + s.length()), () -> "'" + s + "'");
        }
    }

    /** Bit-for-bit equality with parseDouble, including -0, long mantissas and far exponents. */
    @Test
    void parseDecimalIsBitIdenticalToParseDouble() {
        Random r = new Random(2003);
        String[] fixed = {"0", "-0", "+0.0", "1", "-1.5", ".5", "5.", "0.1", "0.3", "1e22", "1e23", "9007199254740993",
            "123456789012345", "1234567890123456", "0.000000000000000000000001", "1.7976931348623157e308", "4.9e-324",
            "2.2250738585072014E-308", "1e-22", "1e-23", "999999999999999e22", "0.12345", "-12.345e-3", "00000000000000000001.5"};
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
            if (!Values.isDecimal(s)) {
                continue;
            }
            assertBitIdentical(s);
        }
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
            double[] v = canonicalVector(s);
            if (v == null) continue;
            taken++;
            // what the general path reads: the same three numbers, bit for bit
            Vector3d g = assertDoesNotThrow(() -> Values.parseVector(s, "v"), s);
            assertEquals(Double.doubleToRawLongBits(g.x), Double.doubleToRawLongBits(v[0]), s);
            assertEquals(Double.doubleToRawLongBits(g.y), Double.doubleToRawLongBits(v[1]), s);
            assertEquals(Double.doubleToRawLongBits(g.z), Double.doubleToRawLongBits(v[2]), s);
        }
        assertEquals(true, taken > 100, "some random vectors are plain");
        assertArrayEquals(new double[] {1, -2.5, 3e-3}, canonicalVector("[1 -2.5 3e-3]"));
        assertEquals(null, canonicalVector("[1, 2, 3]"));      // commas: the general path's job
        assertEquals(null, canonicalVector("[1 2 1e999]"));    // too large: the general path reports it
        assertEquals(null, canonicalVector("[ 1 2 3]"));       // untidy: the general path's job
        assertEquals(null, canonicalVector("[1 2 3 4]"));      // four numbers: the general path reports it
    }

    /** Tokens.canonicalVector of {@code s} written in the middle of other bytes, as in a line. */
    private static double[] canonicalVector(String s) {
        byte[] b = ("Vector3d v " + s + "").getBytes(StandardCharsets.US_ASCII);
        return Tokens.canonicalVector(b, 11, b.length);
    }
}
