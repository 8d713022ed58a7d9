package ray.app;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Which JDKs a long render of a large scene gets the SIMD traversal on (JitPolicy.simdPays): the releases
 * it was measured to pay on and those between, only where the JDK has the Vector API's module.
 */
class JitPolicySimdTest {

    @Test
    void theMeasuredReleasesAndThoseBetweenGetItWhereTheModuleIs() {
        for (int feature = 17; feature <= 25; feature++) {
            assertTrue(JitPolicy.simdPays(feature, true), "JDK " + feature);
            assertFalse(JitPolicy.simdPays(feature, false), "JDK " + feature + " without the module");
        }
    }

    @Test
    void releasesNotMeasuredDoNot() {
        assertFalse(JitPolicy.simdPays(16, true));
        assertFalse(JitPolicy.simdPays(26, true), "a later release waits until it is measured");
        assertFalse(JitPolicy.simdPays(30, true));
    }
}
