package ray.material;

/**
 * The optics of a smooth interface between two clear media: Snell's law for the refracted direction,
 * and the fraction of light reflected (Fresnel), either Schlick's approximation (Shirley, Fundamentals
 * of Computer Graphics, 2nd ed., sect. 10.7; Schlick 1994) or the unpolarised Fresnel equations
 * (Hecht, Optics, 4th ed., sect. 4.6). Pure functions of numbers: no scene, no allocation.
 */
public final class Fresnel {

    private Fresnel() {
    }

    /**
     * The cosine of the refracted ray's angle to the normal, for light crossing from index n1 into n2
     * arriving at cosine {@code cosI} (in [0, 1]); NaN when Snell's law has no solution (total internal
     * reflection: {@code (n1/n2)^2 (1 - cosI^2) >= 1}).
     */
    public static double cosTransmitted(double eta, double cosI) {
        double sin2T = eta * eta * (1 - cosI * cosI);
        if (!(sin2T < 1)) {
            return Double.NaN;
        }
        return Math.sqrt(1 - sin2T);
    }

    /**
     * Schlick's reflectance R0 + (1 - R0)(1 - c)^5, R0 = ((n - 1) / (n + 1))^2, where {@code cosOutside}
     * is the cosine of the angle on the side of index 1 (the incident angle for a ray entering, the
     * refracted angle for one leaving), as in Shirley's book.
     */
    public static double schlick(double n, double cosOutside) {
        double r0 = (n - 1) / (n + 1);
        r0 *= r0;
        double m = 1 - cosOutside;
        double m2 = m * m;
        return r0 + (1 - r0) * (m2 * m2 * m);
    }

    /**
     * The unpolarised Fresnel reflectance (r_s^2 + r_p^2) / 2 for light going from index n1 to n2 at
     * incident cosine {@code cosI} and refracted cosine {@code cosT}.
     */
    public static double exact(double n1, double n2, double cosI, double cosT) {
        double a = n1 * cosI, b = n2 * cosT, c = n2 * cosI, d = n1 * cosT;
        double rs = (a - b) / (a + b);
        double rp = (c - d) / (c + d);
        double r = 0.5 * (rs * rs + rp * rp);
        return r == r ? r : 1;   // 0/0 only at grazing incidence with cosT = 0, where all light is reflected
    }

    /**
     * The transmittance of the same interface from the Fresnel transmission amplitudes, with the
     * beam-area and index factor {@code (n2 cosT) / (n1 cosI)}; equals 1 - {@link #exact} (energy), which
     * the tests check rather than assume.
     */
    public static double exactTransmittance(double n1, double n2, double cosI, double cosT) {
        double ts = 2 * n1 * cosI / (n1 * cosI + n2 * cosT);
        double tp = 2 * n1 * cosI / (n2 * cosI + n1 * cosT);
        return (n2 * cosT) / (n1 * cosI) * 0.5 * (ts * ts + tp * tp);
    }
}
