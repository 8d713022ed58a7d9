package ray.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/** Closedness from the topology: each edge in exactly two faces, run along in opposite directions. */
class MeshTopologyTest {

    /** The cube [0,1]^3: 8 corners, 12 outward triangles. */
    static final float[] CUBE = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
    static final int[] CUBE_FACES = {
        0, 2, 1, 0, 3, 2,   // z = 0, facing -z
        4, 5, 6, 4, 6, 7,   // z = 1
        0, 1, 5, 0, 5, 4,   // y = 0
        3, 7, 6, 3, 6, 2,   // y = 1
        0, 4, 7, 0, 7, 3,   // x = 0
        1, 2, 6, 1, 6, 5};  // x = 1

    @Test
    void cubeIsClosed() {
        assertNull(MeshTopology.openEdge(CUBE, CUBE_FACES));
    }

    @Test
    void missingFaceIsAHole() {
        int[] open = java.util.Arrays.copyOf(CUBE_FACES, 33);
        assertEquals("the edge between vertices 2 and 6 belongs to one face only (a hole in the surface)", MeshTopology.openEdge(CUBE, open));
    }

    @Test
    void flippedFaceIsInconsistent() {
        int[] f = CUBE_FACES.clone();
        f[1] = 1;       // first triangle 0 1 2 instead of 0 2 1
        f[2] = 2;
        assertEquals("the edge from vertex 1 to vertex 2 is run along the same way by two faces (faces wound inconsistently,"
                + " or more than two faces meet there)", MeshTopology.openEdge(CUBE, f));
    }

    @Test
    void verticesAtTheSamePositionAreWelded() {
        // each face of the cube with its own four corners (as exporters write them for flat normals)
        float[] pos = new float[6 * 4 * 3];
        int[] tri = new int[36];
        for (int face = 0; face < 6; face++) {
            int[] corners = new int[4];
            int n = 0;
            for (int k = 0; k < 6; k++) {
                int c = CUBE_FACES[6 * face + k];
                boolean seen = false;
                for (int j = 0; j < n; j++) {
                    seen |= corners[j] == c;
                }
                if (!seen) {
                    corners[n++] = c;
                }
            }
            for (int j = 0; j < 4; j++) {
                System.arraycopy(CUBE, 3 * corners[j], pos, 3 * (4 * face + j), 3);
            }
            for (int k = 0; k < 6; k++) {
                int c = CUBE_FACES[6 * face + k];
                for (int j = 0; j < 4; j++) {
                    if (corners[j] == c) {
                        tri[6 * face + k] = 4 * face + j;
                    }
                }
            }
        }
        pos[0] = -0.0f;    // -0 welds with 0
        assertNull(MeshTopology.openEdge(pos, tri));
        int[] w = MeshTopology.weld(pos);
        assertEquals(8, java.util.Arrays.stream(w).distinct().count());
    }

    @Test
    void weldKeepsTheLowestIndex() {
        assertArrayEquals(new int[] {0, 1, 0, 1}, MeshTopology.weld(new float[] {0, 0, 0, 1, 2, 3, -0f, 0, 0, 1, 2, 3}));
    }
}
