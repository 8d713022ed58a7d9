package ray.parse;

/**
 * The largest settings the parser accepts, so that an absurd scene is refused with a message before
 * anything is allocated (see {@code docs/bad-input.md}). The image-size limit follows the JVM's heap:
 * raise it with {@code -Xmx}, for the launcher {@code JAVA_OPTS=-Xmx16g raytracer big.txt} (or
 * {@code RAYTRACER_OPTS}). The other limits are constants here; change them and rebuild. The render
 * settings' ranges (AASamples up to 64, MaxDepth up to 1000, ...) are {@code ray.settings.RenderOption}'s.
 */
public final class Limits {

    /** Largest Width or Height. */
    public static final int MAX_SIDE = 1 << 16;
    /** Bytes the renderer needs per pixel: linear RGB doubles, the 8-bit image and the PNG encoder's copy. */
    public static final long BYTES_PER_PIXEL = ray.settings.PixelBudget.GRID_BYTES;
    /**
     * Most pixels one image can have whatever the heap: its RGB doubles live in one Java array (3 per
     * pixel, at most Integer.MAX_VALUE - 8 elements). Every other buffer is smaller: the PNG encoder
     * holds one band of rows at a time ({@code PngEncoder.largestBuffer}), never the whole image.
     */
    public static final long MAX_ARRAY_PIXELS = ray.settings.PixelBudget.MAX_ARRAY_PIXELS;
    /** Longest line a scene file may have, in characters. */
    public static final int MAX_LINE = 1 << 16;

    private Limits() {
    }

    /** The most pixels an image may have in this JVM: half the heap it may use, and what one array can index. */
    public static long maxPixels() {
        return Math.min(heapPixels(), MAX_ARRAY_PIXELS);
    }

    /**
     * The smallest -Xmx, in whole GiB, under which an image of {@code pixels} pixels is admitted (half
     * the heap at {@link #BYTES_PER_PIXEL}), with 1/16 more for the JVM's own use of the heap.
     */
    public static long heapGigabytesFor(long pixels) {
        long bytes = pixels * BYTES_PER_PIXEL * 2;
        bytes += bytes / 16;
        return (bytes + (1L << 30) - 1) >> 30;
    }

    /** The most pixels half of this JVM's maximum heap can hold. */
    static long heapPixels() {
        return Runtime.getRuntime().maxMemory() / 2 / BYTES_PER_PIXEL;
    }
}
