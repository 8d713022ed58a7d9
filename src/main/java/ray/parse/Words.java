package ray.parse;

/**
 * The scene format's tokenizer: splits one line into at most three words, as ranges of the line's
 * chars, making no String. A comment starts at a {@code #} at the start of the line or after
 * whitespace; what is left is stripped; the first word runs to the first whitespace, the second to the
 * next, and the third is the rest of the line (a value such as {@code [1 2 3]}, kept whole). Whitespace
 * is {@link Character#isWhitespace}'s. One instance is reused for every line of a file.
 */
final class Words {

    /** The line's chars (the reader's array, valid until the next line). */
    char[] line;
    /** The statement: the line without its comment, stripped: [start, end); empty when start == end. */
    int start, end;
    /** Whether the line is blank: whitespace only, no comment either (a blank line ends an object). */
    boolean blank;
    /** How many words (0 to 3), and each one's range; the third is the rest of the statement. */
    int count;
    int from0, to0, from1, to1, from2;

    /**
     * Splits chars [0, n) of {@code c}; false when nothing is left once the comment is dropped and the
     * line stripped (a blank or comment line). One pass: a comment can only start where a word would
     * (at the start or after whitespace), so it is looked for at each word's start and, in the rest of
     * the line, after each whitespace char.
     */
    boolean split(char[] c, int n) {
        line = c;
        int i = 0;
        while (i < n && isSpace(c[i])) i++;
        if (i == n || c[i] == '#') {          // blank, or a comment line
            blank = i == n;
            start = end = i;
            count = 0;
            return false;
        }
        blank = false;
        int s0 = i;
        while (i < n && (c[i] > ' ' && c[i] < '\u0080' || !isSpace(c[i]))) i++;
        int e0 = i;
        while (i < n && isSpace(c[i])) i++;
        start = from0 = s0;
        to0 = e0;
        if (i == n || c[i] == '#') {
            end = e0;
            count = 1;
            return true;
        }
        int s1 = i;
        while (i < n && (c[i] > ' ' && c[i] < '\u0080' || !isSpace(c[i]))) i++;
        int e1 = i;
        while (i < n && isSpace(c[i])) i++;
        from1 = s1;
        to1 = e1;
        if (i == n || c[i] == '#') {
            end = e1;
            count = 2;
            return true;
        }
        from2 = i;
        int cut = n;
        for (i++; i < n; i++) {                // the rest: only a '#' after whitespace ends it early
            if (c[i] == '#' && isSpace(c[i - 1])) {
                cut = i;
                break;
            }
        }
        while (isSpace(c[cut - 1])) cut--;     // stops at the rest's first char, which is not whitespace
        end = cut;
        count = 3;
        return true;
    }

    /** {@link #space}, small enough for the JIT's first tier to inline: only a rare char is asked of {@link #space}. */
    static boolean isSpace(char x) {
        return x == ' ' || (x < ' ' || x >= '\u0080') && space(x);
    }

    /** The statement as a String (for a message or a global's value). */
    String statement() {
        return new String(line, start, end - start);
    }

    String first() {
        return new String(line, from0, to0 - from0);
    }

    String second() {
        return new String(line, from1, to1 - from1);
    }

    /** The statement after its first word: a global's value. */
    String afterFirst() {
        return new String(line, from1, end - from1);
    }

    /** The third word: the rest of the statement. */
    String rest() {
        return new String(line, from2, end - from2);
    }

    /** Whether the first word is {@code s}. */
    boolean firstIs(char[] s) {
        return same(line, from0, to0, s);
    }

    /** Whether the rest of the statement, from the third word on, is one word (it has no whitespace). */
    boolean restIsOneWord() {
        for (int i = from2; i < end; i++) {
            if (isSpace(line[i])) {
                return false;
            }
        }
        return true;
    }

    /** Whether chars [from, to) of {@code c} are those of {@code s}. */
    static boolean same(char[] c, int from, int to, char[] s) {
        if (to - from != s.length) {
            return false;
        }
        for (int i = 0; i < s.length; i++) {
            if (c[from + i] != s[i]) {
                return false;
            }
        }
        return true;
    }

    /** {@link Character#isWhitespace}, answered without a call for ASCII (every char of a plain file). */
    static boolean space(char c) {
        if (c <= ' ') {
            return c == ' ' || (c >= '\t' && c <= '\r') || c >= '\u001c';
        }
        return c >= '\u0080' && Character.isWhitespace(c);
    }
}
