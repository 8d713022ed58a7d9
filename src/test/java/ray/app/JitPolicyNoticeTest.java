package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * The JIT policy's filter of a long render's stderr (JitPolicy.NoticeFilter): the JVM's notices of the
 * incubator module and of the compiler directives it read are dropped when they are the first lines, in
 * either order, and every other byte passes as it came, however the reads split it.
 */
class JitPolicyNoticeTest {

    private static final String NOTICE = "WARNING: Using incubator modules: jdk.incubator.vector\n";

    /** Reads {@code text} through the filter in reads of at most {@code chunk} bytes. */
    private static String filtered(String text, int chunk) throws InterruptedException {
        byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
        InputStream in = new InputStream() {
            private int at;

            @Override
            public int read() {
                return at < bytes.length ? bytes[at++] & 0xff : -1;
            }

            @Override
            public int read(byte[] b, int off, int len) {
                if (at == bytes.length) {
                    return -1;
                }
                int n = Math.min(Math.min(len, chunk), bytes.length - at);
                System.arraycopy(bytes, at, b, off, n);
                at += n;
                return n;
            }
        };
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        JitPolicy.NoticeFilter f = new JitPolicy.NoticeFilter(in, out);
        f.start();
        f.join();
        return out.toString(StandardCharsets.UTF_8);
    }

    @Test
    void theNoticeIsDroppedOnlyAsTheFirstLine() throws Exception {
        for (int chunk : new int[] {1, 2, 7, 8192}) {
            assertEquals("scene.txt: no such file\n", filtered(NOTICE + "scene.txt: no such file\n", chunk));
            assertEquals("\r[====    ] 40%", filtered(NOTICE + "\r[====    ] 40%", chunk), "a progress line, no newline");
            assertEquals("", filtered(NOTICE, chunk));
            assertEquals("", filtered("", chunk));
            assertEquals("other\n" + NOTICE, filtered("other\n" + NOTICE, chunk), "not the first line: kept");
            assertEquals("WARNING: Using incubator modules: jdk.incubator.foo\n",
                    filtered("WARNING: Using incubator modules: jdk.incubator.foo\n", chunk), "another module: kept");
            assertEquals("WARNING: Using", filtered("WARNING: Using", chunk), "a prefix at the end: kept");
            assertEquals("WARNING: Using incubator modules: jdk.incubator.vector and more\n",
                    filtered("WARNING: Using incubator modules: jdk.incubator.vector and more\n", chunk));
            assertEquals("café ✓\n", filtered(NOTICE + "café ✓\n", chunk), "bytes, not characters");
        }
    }

    private static final String DIRECTIVES = "1 compiler directives added\n";

    @Test
    void theDirectivesCountIsDroppedBeforeOrAfterTheModuleNotice() throws Exception {
        for (int chunk : new int[] {1, 3, 8192}) {
            assertEquals("scene.txt: no such file\n", filtered(DIRECTIVES + NOTICE + "scene.txt: no such file\n", chunk));
            assertEquals("\r[==  ] 20%", filtered(NOTICE + DIRECTIVES + "\r[==  ] 20%", chunk));
            assertEquals("x\n", filtered("12 compiler directives added\nx\n", chunk), "any count");
            assertEquals("", filtered(DIRECTIVES, chunk));
            assertEquals("other\n" + DIRECTIVES, filtered("other\n" + DIRECTIVES, chunk), "not among the first lines: kept");
            assertEquals(" compiler directives added\n", filtered(" compiler directives added\n", chunk), "no count: kept");
            assertEquals("123456 compiler directives added\n", filtered("123456 compiler directives added\n", chunk),
                    "a count no launcher's file gives: kept");
            assertEquals("1 compiler directives added and more\n", filtered("1 compiler directives added and more\n", chunk));
            assertEquals("1 compiler", filtered("1 compiler", chunk), "a beginning at the end: kept");
            assertEquals("42\n", filtered("42\n", chunk), "a number alone: kept");
            assertEquals("2 scenes\n" + NOTICE, filtered(DIRECTIVES + "2 scenes\n" + NOTICE, chunk),
                    "after another line the module's notice is kept");
        }
    }
}
