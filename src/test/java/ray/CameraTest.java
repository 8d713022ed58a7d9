package ray;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.parse.Parser;

/** The camera frame and primary rays, against scene-format.md's "Geometry conventions". */
class CameraTest {

    private static final double EPS = 1e-12;

    private static Camera camera(Vector3d eye, Vector3d target, Vector3d up, double yFOV, double aspect) {
        Camera c = new Camera();
        c.eye = eye;
        c.target = target;
        c.up = up;
        c.yFOV = yFOV;
        c.aspect = aspect;
        c.init();
        return c;
    }

    private static void assertVec(double x, double y, double z, Vector3d v, String what) {
        assertEquals(x, v.x, EPS, what + ".x in " + v);
        assertEquals(y, v.y, EPS, what + ".y in " + v);
        assertEquals(z, v.z, EPS, what + ".z in " + v);
    }

    private static void assertDirection(double x, double y, double z, Ray r, String what) {
        double len = Math.sqrt(x * x + y * y + z * z);
        assertEquals(1, r.direction.length(), EPS, what + ": unit direction");
        assertVec(x / len, y / len, z / len, r.direction, what);
    }

    /** Looking down -z with up = (0,1,1): w = +z, u = normalize(up x w) = +x, v = w x u = +y. */
    @Test
    void frameFromNonPerpendicularUp() {
        Camera c = camera(new Vector3d(0, 0, 5), new Vector3d(), new Vector3d(0, 1, 1), 45, 1);
        assertVec(0, 0, 1, c.w, "w");
        assertVec(1, 0, 0, c.u, "u");
        assertVec(0, 1, 0, c.v, "v");
    }

    /** Looking down -x with up = +z: w = +x, u = z x x = +y, v = x x y = +z. */
    @Test
    void frameLookingAlongNegativeX() {
        Camera c = camera(new Vector3d(2, 0, 0), new Vector3d(), new Vector3d(0, 0, 3), 45, 1);
        assertVec(1, 0, 0, c.w, "w");
        assertVec(0, 1, 0, c.u, "u");
        assertVec(0, 0, 1, c.v, "v");
    }

    /**
     * General position: eye - target = (2, 3, 6), |.| = 7, so w = (2, 3, 6) / 7. With up = (0, 1, 0.5):
     * up x w = (1*6 - 0.5*3, 0.5*2 - 0*6, 0*3 - 1*2) / 7 = (4.5, 1, -2) / 7, normalised by
     * sqrt(20.25 + 1 + 4) = sqrt(25.25); v = w x u.
     */
    @Test
    void frameInGeneralPositionIsOrthonormalAndRightHanded() {
        Camera c = camera(new Vector3d(3, 4, 7), new Vector3d(1, 1, 1), new Vector3d(0, 1, 0.5), 45, 1);
        assertVec(2.0 / 7, 3.0 / 7, 6.0 / 7, c.w, "w");
        double ul = Math.sqrt(25.25);
        assertVec(4.5 / ul, 1 / ul, -2 / ul, c.u, "u");
        // v = w x u, written out
        double[] w = {2.0 / 7, 3.0 / 7, 6.0 / 7}, u = {4.5 / ul, 1 / ul, -2 / ul};
        assertVec(w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0], c.v, "v");
        assertEquals(1, c.v.length(), EPS);
        assertEquals(0, c.u.dot(c.v), EPS);
        assertTrue(c.v.dot(c.up) > 0, "v leans toward up");
    }

    @Test
    void imageCentreRayPointsAtTarget() {
        Camera c = camera(new Vector3d(3, 4, 7), new Vector3d(1, 1, 1), new Vector3d(0, 1, 0.5), 60, 1.5);
        Ray r = c.getRayThrough(30, 20, 60, 40);
        assertVec(3, 4, 7, r.origin, "origin");
        assertDirection(-2, -3, -6, r, "centre ray");
        assertEquals(0, r.depth);
    }

    /**
     * yFOV 90: the plane at distance 1 spans tan(45) = 1 up and down, aspect 2 times that across.
     * The top-left corner (0, 0) is -w - 2u + v, the bottom-right (W, H) is -w + 2u - v.
     */
    @Test
    void cornersSpanTanHalfFovTimesAspect() {
        Camera c = camera(new Vector3d(0, 0, 5), new Vector3d(), new Vector3d(0, 1, 0), 90, 2);
        assertDirection(-2, 1, -1, c.getRayThrough(0, 0, 40, 20), "top-left");
        assertDirection(2, 1, -1, c.getRayThrough(40, 0, 40, 20), "top-right");
        assertDirection(-2, -1, -1, c.getRayThrough(0, 20, 40, 20), "bottom-left");
        assertDirection(2, -1, -1, c.getRayThrough(40, 20, 40, 20), "bottom-right");
    }

    /** yFOV 60: tan(30) = 1/sqrt(3) vertically at the top edge's middle. */
    @Test
    void topEdgeIsAtTanHalfFov() {
        Camera c = camera(new Vector3d(0, 0, 5), new Vector3d(), new Vector3d(0, 1, 0), 60, 1);
        assertDirection(0, 1 / Math.sqrt(3), -1, c.getRayThrough(5, 0, 10, 10), "top middle");
    }

    /** Row 0 is the up side and column 0 the -u side, so the PNG is not flipped or mirrored. */
    @Test
    void rowZeroIsUpAndColumnZeroIsLeft() {
        Camera c = camera(new Vector3d(2, 0, 0), new Vector3d(), new Vector3d(0, 0, 1), 45, 1);
        Ray top = c.getRayThrough(4.5, 0.5, 9, 9), bottom = c.getRayThrough(4.5, 8.5, 9, 9);
        Ray left = c.getRayThrough(0.5, 4.5, 9, 9), right = c.getRayThrough(8.5, 4.5, 9, 9);
        assertTrue(top.direction.z > 0 && bottom.direction.z < 0, "up is +z: top row looks up");
        assertTrue(left.direction.y < 0 && right.direction.y > 0, "u is +y: left column looks toward -y");
    }

    @Test
    void defaultAspectIsWidthOverHeightAfterParsing() throws Exception {
        Scene s = Parser.parse("Width 300\nHeight 100\n\nCamera Camera\nVector3d eye [0 0 5]\ndouble yFOV 90\n",
                "aspect.txt", new ArrayList<>());
        assertEquals(3.0, s.camera.aspect);
        // the top-right corner is then at 3 tan(45) across
        assertDirection(3, 1, -1, s.camera.getRayThrough(300, 0, 300, 100), "top-right");
    }

    @Test
    void explicitAspectIsKept() throws Exception {
        Scene s = Parser.parse("Width 300\nHeight 100\n\nCamera Camera\ndouble yFOV 90\ndouble aspect 1\n",
                "aspect.txt", new ArrayList<>());
        assertEquals(1.0, s.camera.aspect);
        assertDirection(1, 1, -1, s.camera.getRayThrough(300, 0, 300, 100), "top-right");
    }

    @Test
    void eyeEqualToTargetIsRejectedClearly() {
        Camera c = new Camera();
        c.eye = new Vector3d(1, 2, 3);
        c.target = new Vector3d(1, 2, 3);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, c::recalculate);
        assertTrue(e.getMessage().contains("eye") && e.getMessage().contains("target"), e.getMessage());
        assertThrows(IllegalArgumentException.class, c::init);
    }

    @Test
    void upParallelToViewDirectionIsRejectedClearly() {
        for (Vector3d up : new Vector3d[] {new Vector3d(0, 0, 2), new Vector3d(0, 0, -1), new Vector3d(0, 0, 0)}) {
            Camera c = new Camera();    // eye (0,0,5) looking at the origin: view along -z
            c.up = up;
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, c::recalculate, "up " + up);
            assertTrue(e.getMessage().contains("up") && e.getMessage().contains("parallel"), e.getMessage());
            assertThrows(IllegalArgumentException.class, c::init, "up " + up);
        }
    }
}
