package ray.surface;

import java.util.Arrays;

/**
 * Whether a triangle mesh is closed: after welding vertices at exactly the same position, every edge
 * belongs to exactly two triangles that run along it in opposite directions (so the faces' winding is
 * consistent and the surface has no hole, no fold and no fin). Costs a sort of the 3 directed edges
 * per triangle; computed only when asked (a Mesh used as a CSG operand).
 */
final class MeshTopology {

    private MeshTopology() {
    }

    /** Null for a closed mesh; otherwise what is open, naming 1-based vertex numbers as in the file. */
    static String openEdge(float[] pos, int[] tri) {
        int[] weld = weld(pos);
        int n = tri.length / 3;
        long[] edges = new long[3 * n];
        int m = 0;
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                int a = weld[tri[3 * t + k]], b = weld[tri[3 * t + (k + 1) % 3]];
                if (a != b) {                   // a repeated corner: a zero-area triangle's empty edge
                    edges[m++] = (long) a << 32 | b;
                }
            }
        }
        edges = Arrays.copyOf(edges, m);
        Arrays.sort(edges);
        for (int i = 0; i < m; i++) {
            long e = edges[i];
            int a = (int) (e >>> 32), b = (int) e;
            if (i + 1 < m && edges[i + 1] == e) {
                return "the edge from vertex " + (a + 1) + " to vertex " + (b + 1) + " is run along the same way by two faces"
                        + " (faces wound inconsistently, or more than two faces meet there)";
            }
            if (Arrays.binarySearch(edges, (long) b << 32 | a) < 0) {
                return "the edge between vertices " + (a + 1) + " and " + (b + 1) + " belongs to one face only (a hole in the surface)";
            }
        }
        return null;
    }

    /**
     * For each vertex the lowest-numbered vertex at exactly the same position (-0 and 0 alike): an open
     * addressing table keyed by the coordinates' bits.
     */
    static int[] weld(float[] pos) {
        int nv = pos.length / 3;
        int[] weld = new int[nv];
        int size = Integer.highestOneBit(Math.max(2, 2 * nv - 1)) << 1;
        int[] table = new int[size];
        Arrays.fill(table, -1);
        for (int v = 0; v < nv; v++) {
            int x = bits(pos[3 * v]), y = bits(pos[3 * v + 1]), z = bits(pos[3 * v + 2]);
            int h = (x * 0x9E3779B1 + y) * 0x85EBCA77 + z;
            h ^= h >>> 15;
            int slot = h & (size - 1);
            while (true) {
                int u = table[slot];
                if (u < 0) {
                    table[slot] = v;
                    weld[v] = v;
                    break;
                }
                if (bits(pos[3 * u]) == x && bits(pos[3 * u + 1]) == y && bits(pos[3 * u + 2]) == z) {
                    weld[v] = u;
                    break;
                }
                slot = (slot + 1) & (size - 1);
            }
        }
        return weld;
    }

    private static int bits(float f) {
        return Float.floatToIntBits(f + 0.0f);   // -0 + 0 = +0
    }
}
