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
 * deflate streams (each ended on a byte boundary by a sync flush, the last one final) are joined into
 * one zlib stream with one Adler-32 over all the data: a standard PNG any decoder reads, slightly
 * larger than one continuous stream because no match crosses a band.
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

    /** The PNG file's bytes for {@code image}. */
    public static byte[] encode(Image image) throws IOException {
        int w = image.width, h = image.height;
        int stride = 3 * w + 1;
        byte[] filtered = new byte[h * stride];
        int bands = (h + BAND_ROWS - 1) / BAND_ROWS;
        byte[][] parts = new byte[bands][];
        Bands work = new Bands(image, filtered, parts);
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
        Adler32 adler = new Adler32();
        adler.update(filtered, 0, filtered.length);
        int zlen = 2 + 4;
        for (byte[] p : parts) {
            zlen += p.length;
        }
        byte[] z = new byte[zlen];
        z[0] = 0x78;                 // deflate, 32 KiB window
        z[1] = 0x5E;                 // FLEVEL 1 (fast), FCHECK so that 0x785E is a multiple of 31
        int pos = 2;
        for (byte[] p : parts) {
            System.arraycopy(p, 0, z, pos, p.length);
            pos += p.length;
        }
        putInt(z, pos, (int) adler.getValue());

        ByteArrayOutputStream out = new ByteArrayOutputStream(zlen + 64);
        out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
        byte[] ihdr = new byte[13];
        putInt(ihdr, 0, w);
        putInt(ihdr, 4, h);
        ihdr[8] = 8;      // bit depth
        ihdr[9] = 2;      // colour type: RGB
        // compression 0, filter method 0, no interlace
        chunk(out, "IHDR", ihdr, ihdr.length);
        chunk(out, "IDAT", z, z.length);
        chunk(out, "IEND", new byte[0], 0);
        return out.toByteArray();
    }

    /** Writes the PNG for {@code image} to {@code out}. */
    public static void write(Image image, OutputStream out) throws IOException {
        if (image.width < 1 || image.height < 1) {
            throw new IllegalArgumentException("a PNG needs at least 1 x 1 pixels, not " + image.width + " x " + image.height);
        }
        out.write(encode(image));
    }

    /** The bands of one image, handed out to whichever thread asks next. */
    private static final class Bands implements Runnable {
        final Image image;
        final byte[] filtered;
        final byte[][] parts;
        final java.util.concurrent.atomic.AtomicInteger next = new java.util.concurrent.atomic.AtomicInteger();
        volatile Throwable failure;

        Bands(Image image, byte[] filtered, byte[][] parts) {
            this.image = image;
            this.filtered = filtered;
            this.parts = parts;
        }

        @Override
        public void run() {
            try {
                int stride = 3 * image.width + 1;
                for (int b; (b = next.getAndIncrement()) < parts.length; ) {
                    int y0 = b * BAND_ROWS, y1 = Math.min(image.height, y0 + BAND_ROWS);
                    filterRows(image, y0, y1, filtered);
                    parts[b] = deflate(filtered, y0 * stride, y1 * stride, b == parts.length - 1);
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
        filterRows(image, 0, image.height, out);
        return out;
    }

    /** Rows [y0, y1) as Paeth-filtered scanlines into {@code out}, at their place in the whole image's. */
    static void filterRows(Image image, int y0, int y1, byte[] out) {
        int n = 3 * image.width;
        byte[] prev = new byte[n], cur = new byte[n];
        if (y0 > 0) {
            quantize(image, y0 - 1, prev);
        }
        for (int y = y0; y < y1; y++) {
            quantize(image, y, cur);
            int o = y * (n + 1);
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
        for (int i = 0; i < n; i++) {
            int x = cur[i] & 0xFF;
            int a = i >= 3 ? cur[i - 3] & 0xFF : 0;
            int b = prev[i] & 0xFF;
            int c = i >= 3 ? prev[i - 3] & 0xFF : 0;
            int p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
            int pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
            out[o + i] = (byte) (x - pred);
        }
    }

    private static void chunk(OutputStream out, String type, byte[] data, int len) throws IOException {
        byte[] head = new byte[8];
        putInt(head, 0, len);
        for (int i = 0; i < 4; i++) {
            head[4 + i] = (byte) type.charAt(i);
        }
        CRC32 crc = new CRC32();
        crc.update(head, 4, 4);
        crc.update(data, 0, len);
        byte[] tail = new byte[4];
        putInt(tail, 0, (int) crc.getValue());
        out.write(head);
        out.write(data, 0, len);
        out.write(tail);
    }

    private static void putInt(byte[] b, int o, int v) {
        b[o] = (byte) (v >>> 24);
        b[o + 1] = (byte) (v >>> 16);
        b[o + 2] = (byte) (v >>> 8);
        b[o + 3] = (byte) v;
    }
}
