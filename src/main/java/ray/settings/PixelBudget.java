package ray.settings;

/**
 * How many pixels an image may have in this JVM, by sampler: the promise is to refuse an image before
 * anything is allocated for it, rather than die half-way with "out of memory". The grid sampler keeps
 * the linear RGB doubles and the 8-bit copies (32 bytes a pixel); the other samplers add a film (sums,
 * clamped means, variances, counts: 76 bytes a pixel), and the adaptive one its first pass (4 samples a
 * pixel kept), its work and mean images and the error probe's per-pixel arrays. Half the heap is the
 * budget (the rest is the scene, the BVH, the JVM's own).
 */
public final class PixelBudget {

    /** Bytes the grid sampler needs per pixel: linear RGB doubles, the 8-bit image and the PNG encoder's copy. */
    public static final long GRID_BYTES = 24 + 4 + 4;
    /** Jittered and sobol: the grid's, plus the film. */
    public static final long FILM_BYTES = GRID_BYTES + 76;
    /** Adaptive: the film's, plus its first pass (4 x 24), busy (8), mean (24) and the error probe's arrays (about 52). */
    public static final long ADAPTIVE_BYTES = FILM_BYTES + 96 + 8 + 24 + 52;
    /** Pixels one Java array of the linear RGB doubles can index, whatever the heap. */
    public static final long MAX_ARRAY_PIXELS = (Integer.MAX_VALUE - 8) / 3;

    private PixelBudget() {
    }

    /** Bytes a pixel costs with {@code sampler} (grid, jittered, sobol, adaptive; a null or unknown name: grid). */
    public static long bytesPerPixel(String sampler) {
        if (sampler == null) {
            return GRID_BYTES;
        }
        return switch (sampler) {
            case "jittered", "sobol" -> FILM_BYTES;
            case "adaptive" -> ADAPTIVE_BYTES;
            default -> GRID_BYTES;
        };
    }

    /** The most pixels an image may have in this JVM with {@code sampler}: half the heap, and what one array can index. */
    public static long maxPixels(String sampler) {
        return Math.min(Runtime.getRuntime().maxMemory() / 2 / bytesPerPixel(sampler), MAX_ARRAY_PIXELS);
    }

    /** The smallest -Xmx, in whole GiB, under which {@code pixels} are admitted with {@code sampler} (1/16 more for the JVM). */
    public static long heapGigabytesFor(long pixels, String sampler) {
        long bytes = pixels * bytesPerPixel(sampler) * 2;
        bytes += bytes / 16;
        return (bytes + (1L << 30) - 1) >> 30;
    }

    /**
     * Why a {@code width} x {@code height} image cannot be rendered with {@code sampler} in this JVM, or
     * null: "Width 20000 x Height 20000 = 400,000,000 pixels would need about 12,207 MiB (expected at most
     * ...; raise the heap, e.g. JAVA_OPTS=-Xmx26g)". The grid's words are the scene format's; another
     * sampler is named.
     */
    public static String refusal(int width, int height, String sampler) {
        long pixels = (long) width * height;
        long max = maxPixels(sampler);
        if (pixels <= max) {
            return null;
        }
        long bpp = bytesPerPixel(sampler);
        String with = bpp == GRID_BYTES ? "" : " with the " + sampler + " sampler";
        // no heap helps beyond what one array can index: advise -Xmx only where it would be enough
        String why = pixels > MAX_ARRAY_PIXELS
                ? String.format("at most %,d pixels, the most one image array holds whatever the heap", MAX_ARRAY_PIXELS)
                : String.format("at most %,d pixels, half of this JVM's %,d MiB heap at %d bytes a pixel; raise the heap, "
                        + "e.g. JAVA_OPTS=-Xmx%dg", max, Runtime.getRuntime().maxMemory() >> 20, bpp, heapGigabytesFor(pixels, sampler));
        return String.format("Width %d x Height %d = %,d pixels would need about %,d MiB%s (expected %s)",
                width, height, pixels, pixels * bpp >> 20, with, why);
    }
}
