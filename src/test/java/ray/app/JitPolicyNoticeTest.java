package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.ByteArrayOutputStream;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * The JIT policy's filter of a long render's stderr (JitPolicy.NoticeFilter): the JVM's notice of the
 * incubator module is dropped when it is the first line, and every other byte passes as it came, however
 * the reads split it.
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
}
