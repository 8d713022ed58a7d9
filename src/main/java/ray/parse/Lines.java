package ray.parse;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;

/**
 * The lines of a scene file, from text or from a stream of UTF-8 bytes, checked before any costly
 * work: at most {@link Limits#MAX_LINE} characters a line (a longer line is refused without reading
 * the rest of it), no NUL or other control characters (binary data), valid UTF-8. Lines end at
 * {@code \n}, {@code \r\n} or {@code \r}; a leading byte-order mark is dropped. A stream is read as
 * it is parsed, so an endless or huge input costs at most one line of memory.
 *
 * <p>Every line, from text or from bytes, is handed on the same way: its chars in one reused array
 * ({@link #chars()}, {@link #length()}), with no String made for it. A plain ASCII line is widened
 * byte by byte as it is scanned for control characters; only a line with a byte above 0x7F goes
 * through the UTF-8 decoder.
 */
final class Lines {

    /** How far the start of the input is searched for a NUL byte, the mark of a binary file (as git and grep do). */
    static final int BINARY_SNIFF = 8000;
    /** The most bytes of a line kept: more than {@link Limits#MAX_LINE} chars of at most 3 bytes each. */
    private static final int LONGEST = 3 * Limits.MAX_LINE + 1;

    private final String file;
    // text source
    private final String text;
    private int pos;
    // byte source
    private final InputStream in;
    private final byte[] buf;
    private int bufPos, bufLen;
    private boolean eof;
    private CharsetDecoder utf8;
    /** The line last read: chars [0, len) of {@code chars} (reused from line to line). */
    private char[] chars = new char[256];
    private int len;

    private int line;

    private Lines(String file, String text, InputStream in) {
        this.file = file;
        this.text = text;
        this.in = in;
        this.buf = in == null ? null : new byte[1 << 16];
    }

    static Lines of(String text, String file) throws SceneFormatException {
        Lines l = new Lines(file, text, null);
        int nul = text.substring(0, Math.min(text.length(), BINARY_SNIFF)).indexOf('\0');
        if (nul >= 0) {
            throw l.binary(lineAt(text, nul), 0);
        }
        if (text.startsWith("\ufeff")) {
            l.pos = 1;
        }
        return l;
    }

    static Lines of(InputStream in, String file) throws SceneFormatException, IOException {
        Lines l = new Lines(file, null, in);
        l.utf8 = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        while (!l.eof && l.bufLen < BINARY_SNIFF) {
            l.fill();
        }
        if (l.bufLen >= 2 && ((l.buf[0] == (byte) 0xFF && l.buf[1] == (byte) 0xFE) || (l.buf[0] == (byte) 0xFE && l.buf[1] == (byte) 0xFF))) {
            throw new SceneFormatException(file, 1, "UTF-16 text (expected UTF-8: save the file as UTF-8)");
        }
        for (int i = 0; i < Math.min(l.bufLen, BINARY_SNIFF); i++) {
            if (l.buf[i] == 0) {
                throw l.binary(lineAt(new String(l.buf, 0, i, StandardCharsets.ISO_8859_1), i), 0);
            }
        }
        if (l.bufLen >= 3 && l.buf[0] == (byte) 0xEF && l.buf[1] == (byte) 0xBB && l.buf[2] == (byte) 0xBF) {
            l.bufPos = 3;
        }
        return l;
    }

    /** Number of the line last read (0 before the first). */
    int line() {
        return line;
    }

    /**
     * Reads the next line, checking it, and returns false at the end of the input. Its chars are then
     * {@link #chars()} [0, {@link #length()}), valid until the next call.
     */
    boolean advance() throws SceneFormatException, IOException {
        return text != null ? nextFromText() : nextFromBytes();
    }

    /** The chars of the line last read, without its terminator: [0, {@link #length()}). */
    char[] chars() {
        return chars;
    }

    /** How many of {@link #chars()} the line has. */
    int length() {
        return len;
    }

    /** Room for {@code n} chars in {@link #chars}, keeping those it holds. */
    private void room(int n) {
        if (n > chars.length) {
            chars = java.util.Arrays.copyOf(chars, Math.max(n, Math.min(2 * chars.length, LONGEST)));
        }
    }

    private boolean nextFromText() throws SceneFormatException {
        int n = text.length();
        if (pos >= n) {
            return false;
        }
        line++;
        int start = pos, i = pos;
        while (i < n) {
            char c = text.charAt(i);
            if (c == '\n' || c == '\r') {
                break;
            }
            if (i - start >= Limits.MAX_LINE) {
                throw tooLong();
            }
            if (control(c)) {
                throw c == 0 ? binary(line, 0) : controlCharacter(c);
            }
            i++;
        }
        len = i - start;
        room(len);
        text.getChars(start, i, chars, 0);
        pos = i < n && text.charAt(i) == '\r' && i + 1 < n && text.charAt(i + 1) == '\n' ? i + 2 : i + 1;
        return true;
    }

    private boolean nextFromBytes() throws SceneFormatException, IOException {
        if (bufPos >= bufLen && !fill()) {
            return false;
        }
        line++;
        int len = 0, high = 0;
        byte[] buf = this.buf;
        while (true) {
            if (bufPos >= bufLen && !fill()) {
                break;
            }
            // the run of ordinary bytes up to the next special one, each widened to a char as it is
            // checked (a byte above 0x7F too: such a line is decoded as UTF-8 at its end)
            if (len == chars.length && len < LONGEST) {
                room(len + 1);
            }
            int p = bufPos, end = Math.min(bufLen, p + (Math.min(LONGEST, chars.length) - len));
            char[] out = chars;
            int l = len;
            while (p < end) {
                int u = buf[p] & 0xff;
                if (u < 0x20 || u == 0x7f) {
                    break;
                }
                high |= u;
                out[l++] = (char) u;
                p++;
            }
            if (p > bufPos) {
                len = l;
                bufPos = p;
                continue;
            }
            // one byte: a line end, a control character, or the one past the most a line may have
            byte b = buf[bufPos++];
            if (b == '\n') {
                break;
            }
            if (b == '\r') {
                if (bufPos < bufLen || fill()) {
                    if (buf[bufPos] == '\n') {
                        bufPos++;
                    }
                }
                break;
            }
            if (b >= 0 && control((char) b)) {
                throw b == 0 ? binary(line, b) : controlCharacter((char) b);
            }
            if (len == LONGEST) {     // a char is at most 3 bytes: already too long
                throw tooLong();
            }
            if (len == chars.length) {
                room(len + 1);
            }
            chars[len++] = (char) (b & 0xff);
            high |= b & 0xff;
        }
        this.len = len;
        if (high >= 0x80) {           // a byte above 0x7F: the line is UTF-8, decoded in place
            decode();
        }
        if (this.len > Limits.MAX_LINE) {
            throw tooLong();
        }
        return true;
    }

    /** Decodes the line's bytes (held one per char) as UTF-8 into {@link #chars}. */
    private void decode() throws SceneFormatException {
        byte[] raw = new byte[len];
        for (int i = 0; i < len; i++) {
            raw[i] = (byte) chars[i];
        }
        ByteBuffer bytes = ByteBuffer.wrap(raw);
        CharBuffer decoded = CharBuffer.wrap(chars, 0, len);    // UTF-8 never has more chars than bytes
        utf8.reset();
        CoderResult r = utf8.decode(bytes, decoded, true);
        if (!r.isError()) {
            r = utf8.flush(decoded);
        }
        if (r.isError()) {
            int bad = raw[bytes.position()] & 0xff;
            throw new SceneFormatException(file, line, String.format("not UTF-8 text (byte 0x%02X); expected a text scene file saved as UTF-8", bad));
        }
        len = decoded.position();
    }

    private boolean fill() throws IOException {
        if (eof) {
            return false;
        }
        if (bufPos > 0 && bufPos >= bufLen) {
            bufPos = 0;
            bufLen = 0;
        }
        if (bufLen == buf.length) {        // only while sniffing, with bufPos == 0
            return true;
        }
        int n = in.read(buf, bufLen, buf.length - bufLen);
        if (n < 0) {
            eof = true;
            return bufPos < bufLen;
        }
        bufLen += n;
        return true;
    }

    /** C0 control characters other than tab, form feed and vertical tab (line ends are handled by the caller). */
    private static boolean control(char c) {
        return (c < 0x20 && c != '\t' && c != '\f' && c != 0x0b) || c == 0x7f;
    }

    private static int lineAt(String s, int index) {
        int n = 1;
        for (int i = 0; i < index; i++) {
            char c = s.charAt(i);
            if (c == '\n' || (c == '\r' && (i + 1 >= s.length() || s.charAt(i + 1) != '\n'))) {
                n++;
            }
        }
        return n;
    }

    private SceneFormatException binary(int at, int b) {
        return new SceneFormatException(file, at, String.format("binary data (byte 0x%02X), expected a text scene file", b & 0xff));
    }

    private SceneFormatException controlCharacter(char c) {
        return new SceneFormatException(file, line, String.format("control character U+%04X in the text (expected a text scene file)", (int) c));
    }

    private SceneFormatException tooLong() {
        return new SceneFormatException(file, line, String.format("line is longer than %,d characters (expected at most %,d; is this a scene file?)",
                Limits.MAX_LINE, Limits.MAX_LINE));
    }
}
