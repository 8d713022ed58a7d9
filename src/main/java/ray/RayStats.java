package ray;

/**
 * Rays counted by kind. Each render thread owns one (no sharing, no atomics on the hot path); the
 * renderer adds them up when the threads finish.
 */
public final class RayStats {
    public long camera;
    public long shadow;
    public long mirror;
    /** Rays refracted into or out of a dielectric. */
    public long refraction;
    /** Samples whose value was NaN or infinite and were replaced by black (should stay 0). */
    public long invalidSamples;

    public void add(RayStats o) {
        camera += o.camera;
        shadow += o.shadow;
        mirror += o.mirror;
        refraction += o.refraction;
        invalidSamples += o.invalidSamples;
    }

    public long total() {
        return camera + shadow + mirror + refraction;
    }

    @Override
    public String toString() {
        return grouped(camera) + " camera, " + grouped(shadow) + " shadow, " + grouped(mirror) + " mirror"
                + (refraction > 0 ? ", " + grouped(refraction) + " refraction" : "") + " rays";
    }

    /** {@code n} with commas between groups of three digits, as {@code %,d} in an English locale. */
    static String grouped(long n) {
        String s = Long.toString(Math.abs(n));
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < s.length(); i++) {
            if (i > 0 && (s.length() - i) % 3 == 0) {
                b.append(',');
            }
            b.append(s.charAt(i));
        }
        return (n < 0 ? "-" : "") + b;
    }
}
