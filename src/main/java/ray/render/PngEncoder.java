package ray.render;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.Future;
import java.util.zip.Adler32;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

/**
 * A small PNG encoder for 8-bit RGB images: IHDR, one IDAT, IEND, no interlacing, no colour
 * profile chunks (the scene format's PNG holds the linear values, clamped and rounded by
 * {@link Image#toByte}). Replaces ImageIO, whose first use costs about 0.1 s of class loading and
 * plugin discovery and whose encoder deflates at the slowest level.
 *
 * <p>Each row gets the PNG filter (None, Sub, Up, Average, Paeth) with the smallest sum of absolute
 * residuals, the usual libpng heuristic. The filtered rows are cut into bands, each band is
 * deflated on its own (in parallel for large images) and ended on a byte boundary (a sync flush), and the raw
 * deflate streams are joined into one zlib stream with one Adler-32 over all the data: a standard
 * PNG any decoder reads, slightly larger than one continuous stream because no match crosses a band.
 */
public final class PngEncoder {

    /** Deflate level: 4 is within a few percent of 9's size here at a fraction of its time. */
    static final int LEVEL = 4;
    /** Rows per band deflated on its own. */
    static final int BAND_ROWS = 64;

    private PngEncoder() {
    }

    /** The PNG file's bytes for {@code image}. */
    public static byte[] encode(Image image) throws IOException {
        int w = image.width, h = image.height;
        int stride = 3 * w + 1;
        byte[] filtered = filterRows(image);
        int bands = (h + BAND_ROWS - 1) / BAND_ROWS;
        byte[][] parts = new byte[bands][];
        if (bands > 1 && ForkJoinPool.getCommonPoolParallelism() > 0 && Runtime.getRuntime().availableProcessors() > 1) {
            List<Future<byte[]>> jobs = new ArrayList<>();
            for (int b = 0; b < bands; b++) {
                final int from = b * BAND_ROWS * stride, to = Math.min(h, (b + 1) * BAND_ROWS) * stride;
                final boolean last = b == bands - 1;
                jobs.add(ForkJoinPool.commonPool().submit(() -> deflate(filtered, from, to, last)));
            }
            try {
                for (int b = 0; b < bands; b++) {
                    parts[b] = jobs.get(b).get();
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while encoding the PNG", e);
            } catch (ExecutionException e) {
                throw new IOException("PNG encoding failed", e.getCause());
            }
        } else {
            for (int b = 0; b < bands; b++) {
                parts[b] = deflate(filtered, b * BAND_ROWS * stride, Math.min(h, (b + 1) * BAND_ROWS) * stride, b == bands - 1);
            }
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
        out.write(encode(image));
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
        int w = image.width, h = image.height, n = 3 * w;
        byte[] out = new byte[h * (n + 1)];
        byte[] prev = new byte[n], cur = new byte[n];
        byte[] trial = new byte[n];
        double[] rgb = image.rgb;
        for (int y = 0; y < h; y++) {
            for (int i = 0, src = 3 * y * w; i < n; i++) {
                cur[i] = (byte) Image.toByte(rgb[src + i]);
            }
            int o = y * (n + 1);
            int bestFilter = 0;
            long bestSum = Long.MAX_VALUE;
            for (int f = 0; f < 5; f++) {
                long sum = applyFilter(f, cur, prev, trial, n);
                if (sum < bestSum) {
                    bestSum = sum;
                    bestFilter = f;
                }
            }
            applyFilter(bestFilter, cur, prev, trial, n);
            out[o] = (byte) bestFilter;
            System.arraycopy(trial, 0, out, o + 1, n);
            byte[] t = prev;
            prev = cur;
            cur = t;
        }
        return out;
    }

    /** Writes filter {@code f} of row {@code cur} (previous row {@code prev}) into {@code out}; returns the sum of |residual|. */
    private static long applyFilter(int f, byte[] cur, byte[] prev, byte[] out, int n) {
        long sum = 0;
        for (int i = 0; i < n; i++) {
            int x = cur[i] & 0xFF;
            int a = i >= 3 ? cur[i - 3] & 0xFF : 0;
            int b = prev[i] & 0xFF;
            int c = i >= 3 ? prev[i - 3] & 0xFF : 0;
            int pred;
            switch (f) {
                case 0: pred = 0; break;
                case 1: pred = a; break;
                case 2: pred = b; break;
                case 3: pred = (a + b) >>> 1; break;
                default: {
                    int p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
                    pred = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
                }
            }
            byte r = (byte) (x - pred);
            out[i] = r;
            sum += Math.abs((int) r);
        }
        return sum;
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
