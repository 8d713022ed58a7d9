package ray.render;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * A small PNG encoder for 8-bit RGB images: IHDR, one IDAT, IEND, no interlacing, no colour
 * profile chunks (the scene format's PNG holds the linear values, clamped and rounded by
 * {@link Image#toByte}). Replaces ImageIO, whose first use costs about 0.1 s of class loading and
 * plugin discovery and whose encoder deflates at the slowest level.
 *
 * <p>Every row gets the Paeth filter (on rendered images within 1-3% of the size that trying all five
 * filters per row gives, at a fifth of the filtering time, which matters in a process that writes one
 * image and exits before the JIT has warmed up). The rows are cut into bands; each band is filtered
 * and deflated on its own, the bands shared between this thread and helper threads, and the raw
 * deflate streams (each ended on a byte boundary by a sync flush, the last one final) form one zlib
 * stream, written as one IDAT chunk per band, with one Adler-32 over all the data (combined from the
 * bands'): a standard PNG any decoder reads, slightly larger than one continuous stream because no
 * match crosses a band. No buffer ever holds the whole image's scanlines, so the image-size limit is
 * the renderer's (its RGB doubles), not the encoder's.
 */
public final class PngEncoder {

    /** Deflate level: 4 is within a few percent of 9's size here at a fraction of its time. */
    static final int LEVEL = 4;
    /** Rows per band filtered and deflated on its own. */
    static final int BAND_ROWS = 64;
    /** PNG filter type 4. */
    static final int PAETH = 4;

    private PngEncoder() {
    }

    /** The PNG file's bytes for {@code image} (small images: a byte array holds at most 2 GiB). */
    public static byte[] encode(Image image) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        write(image, out);
        return out.toByteArray();
    }

    /**
     * The largest array, in bytes, that encoding a {@code w} x {@code h} image allocates: one band's
     * scanlines (a filter byte and 3 bytes per pixel per row) and its deflated copy, at most a little
     * larger. Long arithmetic: the encoder never holds the whole image's scanlines, so no size the
     * image limit admits overflows an int here (see {@link ray.parse.Limits}).
     */
    public static long largestBuffer(long w, long h) {
        long band = Math.min(h, BAND_ROWS) * (3 * w + 1);
        return band + band / 1000 + 64 * 1024 + 64;       // deflate's worst case: +5 bytes per 16 KiB stored block
    }

    /**
     * Writes the PNG for {@code image} to {@code out}: IHDR, one IDAT per band (together one zlib
     * stream, which the PNG format allows to be split over IDAT chunks at any byte), IEND.
     */
    public static void write(Image image, OutputStream out) throws IOException {
        int w = image.width, h = image.height;
        if (w < 1 || h < 1) {
            throw new IllegalArgumentException("a PNG needs at least 1 x 1 pixels, not " + w + " x " + h);
        }
        int bands = (h + BAND_ROWS - 1) / BAND_ROWS;
        Bands work = new Bands(image, bands);
        int helpers = Math.min(bands, Runtime.getRuntime().availableProcessors()) - 1;
        Thread[] threads = new Thread[Math.max(0, helpers)];
        for (int i = 0; i < threads.length; i++) {
            threads[i] = new Thread(work, "png-" + i);
            threads[i].start();
        }
        work.run();
        try {
            for (Thread t : threads) {
                t.join();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while encoding the PNG", e);
        }
        if (work.failure != null) {
            throw new IOException("PNG encoding failed", work.failure);
        }
        out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
        byte[] ihdr = new byte[13];
        putInt(ihdr, 0, w);
        putInt(ihdr, 4, h);
        ihdr[8] = 8;      // bit depth
        ihdr[9] = 2;      // colour type: RGB
        // compression 0, filter method 0, no interlace
        chunk(out, "IHDR", ihdr);
        long adler = 1;
        for (int b = 0; b < bands; b++) {
            adler = b == 0 ? work.adlers[0] : adlerCombine(adler, work.adlers[b], work.lengths[b]);
        }
        // deflate, 32 KiB window; FLEVEL 1 (fast), FCHECK so that 0x785E is a multiple of 31
        byte[] zlibHeader = {0x78, 0x5E};
        byte[] trailer = new byte[4];
        putInt(trailer, 0, (int) adler);
        for (int b = 0; b < bands; b++) {
            chunk(out, "IDAT", b == 0 ? zlibHeader : null, work.parts[b], b == bands - 1 ? trailer : null);
            work.parts[b] = null;
        }
        chunk(out, "IEND", new byte[0]);
    }

    /** zlib's adler32_combine: the Adler-32 of A followed by B from those of A and B and B's length. */
    static long adlerCombine(long adler1, long adler2, long len2) {
        final long base = 65521;
        long rem = len2 % base;
        long sum1 = adler1 & 0xFFFF;
        long sum2 = rem * sum1 % base;
        sum1 += (adler2 & 0xFFFF) + base - 1;
        sum2 += ((adler1 >> 16) & 0xFFFF) + ((adler2 >> 16) & 0xFFFF) + base - rem;
        if (sum1 >= base) {
            sum1 -= base;
        }
        if (sum1 >= base) {
            sum1 -= base;
        }
        if (sum2 >= base << 1) {
            sum2 -= base << 1;
        }
        if (sum2 >= base) {
            sum2 -= base;
        }
        return sum1 | sum2 << 16;
    }

    /** The bands of one image, handed out to whichever thread asks next; each filtered in its own buffer. */
    private static final class Bands implements Runnable {
        final Image image;
        final byte[][] parts;
        final long[] adlers;
        final int[] lengths;
        final java.util.concurrent.atomic.AtomicInteger next = new java.util.concurrent.atomic.AtomicInteger();
        volatile Throwable failure;

        Bands(Image image, int bands) {
            this.image = image;
            this.parts = new byte[bands][];
            this.adlers = new long[bands];
            this.lengths = new int[bands];
        }

        @Override
        public void run() {
            try {
                int stride = 3 * image.width + 1;
                byte[] filtered = new byte[Math.min(image.height, BAND_ROWS) * stride];
                for (int b; (b = next.getAndIncrement()) < parts.length; ) {
                    int y0 = b * BAND_ROWS, y1 = Math.min(image.height, y0 + BAND_ROWS), n = (y1 - y0) * stride;
                    filterRows(image, y0, y1, filtered, 0);
                    Adler32 a = new Adler32();
                    a.update(filtered, 0, n);
                    adlers[b] = a.getValue();
                    lengths[b] = n;
                    parts[b] = deflate(filtered, 0, n, b == parts.length - 1);
                }
            } catch (RuntimeException | Error e) {
                failure = e;
            }
        }
    }

    private static byte[] deflate(byte[] data, int from, int to, boolean last) {
        Deflater d = new Deflater(LEVEL, true);
        try {
            d.setInput(data, from, to - from);
            if (last) {
                d.finish();
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream((to - from) / 2 + 64);
            byte[] buf = new byte[64 * 1024];
            while (true) {
                int n = d.deflate(buf, 0, buf.length, last ? Deflater.NO_FLUSH : Deflater.SYNC_FLUSH);
                out.write(buf, 0, n);
                if (last ? d.finished() : n < buf.length) {
                    break;
                }
            }
            return out.toByteArray();
        } finally {
            d.end();
        }
    }

    /** The image's rows as PNG scanlines: a filter byte, then the filtered RGB bytes. */
    static byte[] filterRows(Image image) {
        byte[] out = new byte[image.height * (3 * image.width + 1)];
        filterRows(image, 0, image.height, out, 0);
        return out;
    }

    /** Rows [y0, y1) as Paeth-filtered scanlines into {@code out}, row y0 at index {@code at}. */
    static void filterRows(Image image, int y0, int y1, byte[] out, int at) {
        int n = 3 * image.width;
        byte[] prev = new byte[n], cur = new byte[n];
        if (y0 > 0) {
            quantize(image, y0 - 1, prev);
        }
        for (int y = y0; y < y1; y++) {
            quantize(image, y, cur);
            int o = (y - y0) * (n + 1) + at;
            out[o] = PAETH;
            paeth(cur, prev, out, o + 1, n);
            byte[] t = prev;
            prev = cur;
            cur = t;
        }
    }

    private static void quantize(Image image, int y, byte[] row) {
        double[] rgb = image.rgb;
        for (int i = 0, src = 3 * y * image.width, n = row.length; i < n; i++) {
            row[i] = (byte) Image.toByte(rgb[src + i]);
        }
    }

    /** The Paeth residuals of row {@code cur} (previous row {@code prev}, 3 bytes per pixel). */
    private static void paeth(byte[] cur, byte[] prev, byte[] out, int o, int n) {
        for (int i = 0; i < 3 && i < n; i++) {          // the first pixel: a = c = 0, so the predictor is b
            out[o + i] = (byte) (cur[i] - prev[i]);
        }
        for (int i = 3; i < n; i++) {                    // no per-byte test for the first pixel, no Math.abs call
            int a = cur[i - 3] & 0xFF, b = prev[i] & 0xFF, c = prev[i - 3] & 0xFF;
            int pa = b - c, pb = a - c, pc = pa + pb;    // p - a, p - b and p - c for p = a + b - c
            pa = pa < 0 ? -pa : pa;
            pb = pb < 0 ? -pb : pb;
            pc = pc < 0 ? -pc : pc;
            int pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            out[o + i] = (byte) (cur[i] - pred);
        }
    }

    private static void chunk(OutputStream out, String type, byte[] data) throws IOException {
        chunk(out, type, null, data, null);
    }

    /** One chunk whose data is {@code head}, {@code data} and {@code tail} (either may be null). */
    private static void chunk(OutputStream out, String type, byte[] head, byte[] data, byte[] tail) throws IOException {
        int len = (head == null ? 0 : head.length) + data.length + (tail == null ? 0 : tail.length);
        byte[] start = new byte[8];
        putInt(start, 0, len);
        for (int i = 0; i < 4; i++) {
            start[4 + i] = (byte) type.charAt(i);
        }
        CRC32 crc = new CRC32();
        crc.update(start, 4, 4);
        out.write(start);
        for (byte[] piece : new byte[][] {head, data, tail}) {
            if (piece != null) {
                crc.update(piece, 0, piece.length);
                out.write(piece);
            }
        }
        byte[] end = new byte[4];
        putInt(end, 0, (int) crc.getValue());
        out.write(end);
    }

    private static void putInt(byte[] b, int o, int v) {
        b[o] = (byte) (v >>> 24);
        b[o + 1] = (byte) (v >>> 16);
        b[o + 2] = (byte) (v >>> 8);
        b[o + 3] = (byte) v;
    }
}
