package ray.plan;

import ray.RayKind;

/**
 * An estimate (not a bound) of the rays a render will cast and of its time, from a pilot render of a
 * fraction of its pixels (the same view, samples, MaxDepth and plan, at a lower resolution): the pilot's
 * rays of each kind scaled by the pixels' ratio, and a time from those rays at {@link #RAYS_PER_THREAD_SECOND}.
 * How close it comes over the scenes in scenes/ is measured by {@code gradle planAccuracy} and stated
 * in docs/plan.md ({@link #ACCURACY}).
 */
public final class RayEstimate {

    /**
     * Rays per second one render thread casts and shades, fitted to the renders of scenes/ on an idle
     * two-core machine (C1 JIT, this project's launcher): from 1.2 M (CSG) to 6 M (mirrors) a thread-second
     * there, so the time is an estimate whatever the rays (docs/plan.md).
     */
    public static final double RAYS_PER_THREAD_SECOND = 4e6;
    /** Fixed cost of a render beyond its rays (parse, BVH, PNG; not the JVM's start), seconds, fitted with the rate. */
    public static final double OVERHEAD_SECONDS = 0.1;
    /** How the estimate compared with the real renders of scenes/ (docs/plan.md), said beside every time. */
    public static final String ACCURACY = "docs/plan.md";

    private final double[] rays;
    /** The share of the image's pixels the pilot rendered, and its wall seconds. */
    public final double fraction, pilotSeconds;

    public RayEstimate(double[] rays, double fraction, double pilotSeconds) {
        this.rays = rays.clone();
        this.fraction = fraction;
        this.pilotSeconds = pilotSeconds;
    }

    /** The estimated rays of kind {@code k}. */
    public double get(RayKind k) {
        return rays[k.ordinal()];
    }

    /** All kinds together. */
    public double total() {
        double t = 0;
        for (double r : rays) {
            t += r;
        }
        return t;
    }

    /** The estimated wall seconds of the render on {@code threads} threads. */
    public double seconds(int threads) {
        return seconds(total(), threads);
    }

    /** The estimated CPU seconds of the render, all threads together (what a busy machine does not stretch). */
    public double cpuSeconds() {
        return OVERHEAD_SECONDS + total() / RAYS_PER_THREAD_SECOND;
    }

    /** The estimated wall seconds of casting {@code rays} rays on {@code threads} threads. */
    public static double seconds(double rays, int threads) {
        return OVERHEAD_SECONDS + rays / (RAYS_PER_THREAD_SECOND * Math.max(1, threads));
    }

    /** "about 3 min" (a duration for people), or null past a million years. */
    public static String duration(double s) {
        double year = 365.25 * 86400;
        return s < 0.95 ? String.format(java.util.Locale.ROOT, "%.1f s", s) : s < 90 ? Math.round(s) + " s"
                : s < 5400 ? Math.round(s / 60) + " min" : s < 3 * 86400 ? Math.round(s / 3600) + " h"
                : s < 3 * year ? Math.round(s / 86400) + " days" : s < 1e6 * year ? Math.round(s / year) + " years" : null;
    }

    /** The one line a person reads: rays, time, how it was estimated and where its accuracy is stated. */
    public String line(int threads) {
        String pixels = fraction >= 1 ? "all the pixels" : "1/" + Math.round(1 / fraction) + " of the pixels";
        return "estimate (not a bound): about " + PlanReport.count(Math.round(total())) + " rays, about " + duration(seconds(threads))
                + " on " + threads + " thread" + (threads == 1 ? "" : "s") + " (a pilot render of " + pixels + " in "
                + String.format(java.util.Locale.ROOT, "%.2f s", pilotSeconds) + "; measured accuracy in " + ACCURACY + ")";
    }
}
