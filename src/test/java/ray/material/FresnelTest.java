package ray.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/** Snell's law and the two reflectance models, against values derived by hand and against each other. */
class FresnelTest {

    @Test
    void normalIncidenceGivesR0InBothModels() {
        double n = 1.5, r0 = 0.04;   // ((1.5 - 1) / (1.5 + 1))^2
        assertEquals(r0, Fresnel.schlick(n, 1), 1e-16);
        assertEquals(r0, Fresnel.exact(1, n, 1, 1), 1e-16);
        assertEquals(r0, Fresnel.exact(n, 1, 1, 1), 1e-16, "same from inside");
    }

    @Test
    void schlickAtGrazingIsOne() {
        assertEquals(1, Fresnel.schlick(1.5, 0), 0);
    }

    /** Brewster's angle tan(theta) = n2/n1: the p-polarised part vanishes, R = r_s^2 / 2. */
    @Test
    void exactAtBrewsterAngleIsHalfOfSPolarised() {
        double n = 1.5, thetaB = Math.atan(n);
        double cosI = Math.cos(thetaB), cosT = Fresnel.cosTransmitted(1 / n, cosI);
        double rs = (cosI - n * cosT) / (cosI + n * cosT);
        assertEquals(rs * rs / 2, Fresnel.exact(1, n, cosI, cosT), 1e-15);
        // at Brewster's angle the reflected and refracted rays are perpendicular: theta_i + theta_t = 90 deg
        assertEquals(Math.PI / 2, thetaB + Math.acos(cosT), 1e-12);
    }

    /** sin(theta_c) = 1/n: just past it there is no refracted ray, just before it there is one, grazing. */
    @Test
    void totalInternalReflectionStartsAtTheCriticalAngle() {
        double n = 1.5, critical = Math.asin(1 / n);
        assertTrue(Double.isNaN(Fresnel.cosTransmitted(n, Math.cos(critical + 1e-9))), "past the critical angle");
        double cosT = Fresnel.cosTransmitted(n, Math.cos(critical - 1e-9));
        assertTrue(cosT >= 0 && cosT < 1e-3, "just inside the critical angle the refracted ray grazes: cosT " + cosT);
        // the exact reflectance tends to 1 at the critical angle (continuity with TIR)
        assertEquals(1, Fresnel.exact(n, 1, Math.cos(critical - 1e-12), Fresnel.cosTransmitted(n, Math.cos(critical - 1e-12))), 1e-4);
        // from the optically thinner side there is never TIR
        assertTrue(Fresnel.cosTransmitted(1 / n, 0) > 0);
    }

    /**
     * Seeded property test: R from the reflection amplitudes plus T from the transmission amplitudes is 1
     * (energy), both in [0, 1], the same from either side of the interface (reciprocity), and Snell's
     * law n1 sin(theta_i) = n2 sin(theta_t) holds.
     */
    @Test
    void energyReciprocityAndSnellHoldForRandomAngles() {
        long seed = 20261201L;
        Random rnd = new Random(seed);
        for (int i = 0; i < 10_000; i++) {
            double n1 = 0.3 + 3 * rnd.nextDouble(), n2 = 0.3 + 3 * rnd.nextDouble();
            double cosI = rnd.nextDouble();
            double cosT = Fresnel.cosTransmitted(n1 / n2, cosI);
            String what = "seed " + seed + " case " + i + ": n1 " + n1 + " n2 " + n2 + " cosI " + cosI;
            if (Double.isNaN(cosT)) {
                assertTrue(n1 * Math.sqrt(1 - cosI * cosI) >= n2 * (1 - 1e-12), "TIR only past the critical angle: " + what);
                continue;
            }
            if (cosI < 1e-6) {
                continue;   // T's beam factor is 0/0 at grazing incidence
            }
            double r = Fresnel.exact(n1, n2, cosI, cosT), t = Fresnel.exactTransmittance(n1, n2, cosI, cosT);
            assertTrue(r >= 0 && r <= 1, "R in [0, 1]: " + what);
            assertEquals(1, r + t, 1e-12, "R + T = 1: " + what);
            assertEquals(r, Fresnel.exact(n2, n1, cosT, cosI), 1e-12, "reciprocity: " + what);
            double sinI = Math.sqrt(1 - cosI * cosI), sinT = Math.sqrt(1 - cosT * cosT);
            assertEquals(n1 * sinI, n2 * sinT, 1e-9 * Math.max(n1, n2), "Snell: " + what);
        }
    }
}
