package ray;

/**
 * Rays counted by kind. Each render thread owns one (no sharing, no atomics on the hot path); the
 * renderer adds them up when the threads finish.
 */
public final class RayStats {
    public long camera;
    public long shadow;
    public long mirror;
    /** Samples whose value was NaN or infinite and were replaced by black (should stay 0). */
    public long invalidSamples;

    public void add(RayStats o) {
        camera += o.camera;
        shadow += o.shadow;
        mirror += o.mirror;
        invalidSamples += o.invalidSamples;
    }

    public long total() {
        return camera + shadow + mirror;
    }

    @Override
    public String toString() {
        return String.format("%,d camera, %,d shadow, %,d mirror rays", camera, shadow, mirror);
    }
}
