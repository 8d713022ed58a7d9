package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The tokenizer splits a line as the scene format says, written here the plain way as the oracle: drop
 * a comment ('#' at the start or after whitespace), strip, then the first word, the second, and the
 * rest of the line; whitespace is Character.isWhitespace's, Unicode included.
 */
class WordsTest {

    @Test
    void spaceIsCharacterIsWhitespaceForEveryChar() {
        for (int c = 0; c <= Character.MAX_VALUE; c++) {
            assertEquals(Character.isWhitespace((char) c), Words.space((char) c), "U+" + Integer.toHexString(c));
        }
    }

    @Test
    void randomLinesSplitAsThePlainDefinitionSays() {
        String alphabet = "ab#[] ,\t\u000B\f\u001F\u00A0\u2003\u3000\u0085x1";
        Random r = new Random(23);
        Words w = new Words();
        for (int k = 0; k < 200_000; k++) {
            StringBuilder b = new StringBuilder();
            for (int i = 0, n = r.nextInt(12); i < n; i++) {
                b.append(alphabet.charAt(r.nextInt(alphabet.length())));
            }
            String line = b.toString();
            char[] chars = (line + "garbage past the end").toCharArray();
            boolean any = w.split(chars, line.length());
            List<String> expected = plainSplit(line);
            List<String> found = new ArrayList<>();
            if (any) {
                found.add(w.first());
                if (w.count > 1) found.add(w.second());
                if (w.count > 2) found.add(w.rest());
                assertEquals(plainStatement(line), w.statement(), line);
            }
            assertEquals(expected, found, () -> "'" + line + "'");
            assertEquals(line.isBlank(), w.blank, line);
        }
    }

    private static String plainStatement(String raw) {
        String s = raw;
        for (int i = 0; i < s.length(); i++) {
            if (s.charAt(i) == '#' && (i == 0 || Character.isWhitespace(s.charAt(i - 1)))) {
                s = s.substring(0, i);
                break;
            }
        }
        return s.strip();
    }

    private static List<String> plainSplit(String raw) {
        String s = plainStatement(raw);
        List<String> out = new ArrayList<>();
        if (s.isEmpty()) {
            return out;
        }
        int i = 0;
        while (out.size() < 2) {
            int start = i;
            while (i < s.length() && !Character.isWhitespace(s.charAt(i))) i++;
            out.add(s.substring(start, i));
            while (i < s.length() && Character.isWhitespace(s.charAt(i))) i++;
            if (i == s.length()) {
                return out;
            }
        }
        out.add(s.substring(i));
        return out;
    }
}
