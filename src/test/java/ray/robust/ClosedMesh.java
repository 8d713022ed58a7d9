package ray.robust;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import javax.vecmath.Vector3d;
import ray.surface.Triangle;

/**
 * A closed triangle mesh with outward winding ((v1 - v0) x (v2 - v0) points out), built so that every
 * shared vertex is one {@code Vector3d}: the triangles meeting at a vertex or an edge hold bit-identical
 * coordinates, as a mesh file's indexed vertices would give them.
 */
final class ClosedMesh {

    final List<Vector3d> vertices = new ArrayList<>();
    final List<int[]> faces = new ArrayList<>();

    /** A subdivided icosahedron projected onto the unit sphere ({@code levels} = 2: 320 faces). */
    static ClosedMesh icosphere(int levels) {
        ClosedMesh m = new ClosedMesh();
        double p = (1 + Math.sqrt(5)) / 2;
        double[][] v = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
            {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
        for (double[] x : v) {
            Vector3d u = new Vector3d(x[0], x[1], x[2]);
            u.normalize();
            m.vertices.add(u);
        }
        int[][] f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
            {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        for (int[] x : f) {
            m.addOutward(x[0], x[1], x[2]);
        }
        for (int l = 0; l < levels; l++) {
            m = m.subdivide();
        }
        return m;
    }

    /** The cube [-1, 1]^3 with each face cut into an n x n grid of quads (two triangles each). */
    static ClosedMesh cubeGrid(int n) {
        ClosedMesh m = new ClosedMesh();
        Map<Long, Integer> index = new HashMap<>();
        for (int axis = 0; axis < 3; axis++) {
            for (int side = 0; side <= n; side += n) {
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        int a = m.gridVertex(index, n, axis, side, i, j);
                        int b = m.gridVertex(index, n, axis, side, i + 1, j);
                        int c = m.gridVertex(index, n, axis, side, i + 1, j + 1);
                        int d = m.gridVertex(index, n, axis, side, i, j + 1);
                        m.addOutward(a, b, c);
                        m.addOutward(a, c, d);
                    }
                }
            }
        }
        return m;
    }

    private int gridVertex(Map<Long, Integer> index, int n, int axis, int side, int i, int j) {
        int[] g = new int[3];
        g[axis] = side;
        g[(axis + 1) % 3] = i;
        g[(axis + 2) % 3] = j;
        long key = ((long) g[0] * (n + 1) + g[1]) * (n + 1) + g[2];
        return index.computeIfAbsent(key, k -> {
            vertices.add(new Vector3d(2.0 * g[0] / n - 1, 2.0 * g[1] / n - 1, 2.0 * g[2] / n - 1));
            return vertices.size() - 1;
        });
    }

    /** Adds the face, swapped if needed so its normal points away from the origin (meshes are centred there). */
    private void addOutward(int a, int b, int c) {
        Vector3d n = normal(a, b, c), centroid = new Vector3d(vertices.get(a));
        centroid.add(vertices.get(b));
        centroid.add(vertices.get(c));
        faces.add(n.dot(centroid) > 0 ? new int[] {a, b, c} : new int[] {a, c, b});
    }

    Vector3d normal(int a, int b, int c) {
        Vector3d e = RobustSupport.sub(vertices.get(b), vertices.get(a));
        Vector3d f = RobustSupport.sub(vertices.get(c), vertices.get(a));
        Vector3d n = new Vector3d();
        n.cross(e, f);
        n.normalize();
        return n;
    }

    Vector3d faceNormal(int face) {
        int[] f = faces.get(face);
        return normal(f[0], f[1], f[2]);
    }

    private ClosedMesh subdivide() {
        ClosedMesh m = new ClosedMesh();
        for (Vector3d v : vertices) {
            m.vertices.add(new Vector3d(v));
        }
        Map<Long, Integer> mid = new HashMap<>();
        for (int[] f : faces) {
            int ab = m.midpoint(mid, f[0], f[1]), bc = m.midpoint(mid, f[1], f[2]), ca = m.midpoint(mid, f[2], f[0]);
            m.faces.add(new int[] {f[0], ab, ca});
            m.faces.add(new int[] {f[1], bc, ab});
            m.faces.add(new int[] {f[2], ca, bc});
            m.faces.add(new int[] {ab, bc, ca});
        }
        return m;
    }

    private int midpoint(Map<Long, Integer> mid, int a, int b) {
        long key = (long) Math.min(a, b) << 32 | Math.max(a, b);
        return mid.computeIfAbsent(key, k -> {
            Vector3d v = new Vector3d(vertices.get(a));
            v.add(vertices.get(b));
            v.normalize();
            vertices.add(v);
            return vertices.size() - 1;
        });
    }

    /** The mesh with every vertex mapped to {@code s * (kx x, ky y, kz z) + t} (one rounding per vertex). */
    ClosedMesh transformed(double s, Vector3d k, Vector3d t) {
        ClosedMesh m = new ClosedMesh();
        for (Vector3d v : vertices) {
            m.vertices.add(new Vector3d(s * (k.x * v.x) + t.x, s * (k.y * v.y) + t.y, s * (k.z * v.z) + t.z));
        }
        m.faces.addAll(faces);
        return m;
    }

    /** Edges as vertex pairs (a < b), each with the two faces that share it. */
    List<int[]> edges() {
        Map<Long, int[]> e = new HashMap<>();
        for (int fi = 0; fi < faces.size(); fi++) {
            int[] f = faces.get(fi);
            for (int i = 0; i < 3; i++) {
                int a = Math.min(f[i], f[(i + 1) % 3]), b = Math.max(f[i], f[(i + 1) % 3]);
                int[] rec = e.computeIfAbsent((long) a << 32 | b, k -> new int[] {a, b, -1, -1});
                rec[rec[2] < 0 ? 2 : 3] = fi;
            }
        }
        return new ArrayList<>(e.values());
    }

    /** For each vertex, the faces around it. */
    List<List<Integer>> facesAroundVertices() {
        List<List<Integer>> around = new ArrayList<>();
        for (int i = 0; i < vertices.size(); i++) {
            around.add(new ArrayList<>());
        }
        for (int fi = 0; fi < faces.size(); fi++) {
            for (int v : faces.get(fi)) {
                around.get(v).add(fi);
            }
        }
        return around;
    }

    /** One {@link Triangle} per face; shared vertices are copied from the same Vector3d. */
    List<Triangle> triangles() {
        List<Triangle> out = new ArrayList<>();
        for (int[] f : faces) {
            out.add(RobustSupport.triangle(vertices.get(f[0]), vertices.get(f[1]), vertices.get(f[2])));
        }
        return out;
    }
}
