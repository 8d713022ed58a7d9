package ray.surface;

import java.util.ArrayList;
import java.util.List;

/**
 * Test meshes written as OBJ text: a latitude-longitude sphere of quads with triangle fans at the
 * poles, outward counter-clockwise, with its fan triangles also as scene {@code Triangle} objects
 * holding exactly the same (float) coordinates.
 */
final class ObjWriter {

    final List<float[]> vertices = new ArrayList<>();
    final List<int[]> faces = new ArrayList<>();

    /** A sphere of {@code rings} latitude bands and {@code segments} longitude ones. */
    static ObjWriter uvSphere(int rings, int segments, float cx, float cy, float cz, float r) {
        ObjWriter w = new ObjWriter();
        w.vertices.add(new float[] {cx, cy + r, cz});                       // north pole: 0
        for (int i = 1; i < rings; i++) {
            double theta = Math.PI * i / rings;
            for (int j = 0; j < segments; j++) {
                double phi = 2 * Math.PI * j / segments;
                w.vertices.add(new float[] {cx + (float) (r * Math.sin(theta) * Math.cos(phi)), cy + (float) (r * Math.cos(theta)),
                    cz - (float) (r * Math.sin(theta) * Math.sin(phi))});
            }
        }
        w.vertices.add(new float[] {cx, cy - r, cz});                       // south pole
        int south = w.vertices.size() - 1;
        for (int j = 0; j < segments; j++) {
            int j1 = (j + 1) % segments;
            w.faces.add(new int[] {0, 1 + j, 1 + j1});
            for (int i = 1; i + 1 < rings; i++) {
                int a = 1 + (i - 1) * segments, b = 1 + i * segments;
                w.faces.add(new int[] {a + j, b + j, b + j1, a + j1});
            }
            int last = 1 + (rings - 2) * segments;
            w.faces.add(new int[] {last + j, south, last + j1});
        }
        return w;
    }

    /** The OBJ text; with {@code normals}, each vertex's normal is its direction from {@code centre}. */
    String obj(boolean normals, float cx, float cy, float cz) {
        StringBuilder b = new StringBuilder("# test sphere\n");
        for (float[] v : vertices) {
            b.append("v ").append(v[0]).append(' ').append(v[1]).append(' ').append(v[2]).append('\n');
        }
        if (normals) {
            for (float[] v : vertices) {
                b.append("vn ").append(v[0] - cx).append(' ').append(v[1] - cy).append(' ').append(v[2] - cz).append('\n');
            }
        }
        for (int[] f : faces) {
            b.append('f');
            for (int c : f) {
                b.append(' ').append(c + 1);
                if (normals) {
                    b.append("//").append(c + 1);
                }
            }
            b.append('\n');
        }
        return b.toString();
    }

    /** The same mesh with every face's corners in reverse order (facing inward). */
    ObjWriter reversed() {
        ObjWriter w = new ObjWriter();
        w.vertices.addAll(vertices);
        for (int[] f : faces) {
            int[] r = new int[f.length];
            for (int i = 0; i < f.length; i++) {
                r[i] = f[(f.length - i) % f.length];
            }
            w.faces.add(r);
        }
        return w;
    }

    /** The same faces, each fanned into triangles, as OBJ text of triangles only. */
    String objTriangles() {
        StringBuilder b = new StringBuilder();
        for (float[] v : vertices) {
            b.append("v ").append(v[0]).append(' ').append(v[1]).append(' ').append(v[2]).append('\n');
        }
        for (int[] f : faces) {
            for (int k = 1; k + 1 < f.length; k++) {
                b.append("f ").append(f[0] + 1).append(' ').append(f[k] + 1).append(' ').append(f[k + 1] + 1).append('\n');
            }
        }
        return b.toString();
    }

    /** The fan triangles as scene {@code Triangle} objects with {@code ref material <material>}. */
    String sceneTriangles(String material) {
        StringBuilder b = new StringBuilder();
        for (int[] f : faces) {
            for (int k = 1; k + 1 < f.length; k++) {
                b.append("Surface Triangle\n");
                vector(b, "v0", vertices.get(f[0]));
                vector(b, "v1", vertices.get(f[k]));
                vector(b, "v2", vertices.get(f[k + 1]));
                b.append("ref material ").append(material).append("\n\n");
            }
        }
        return b.toString();
    }

    /** The float's exact value as a decimal a double parses back to the same number. */
    private static void vector(StringBuilder b, String name, float[] v) {
        b.append("Vector3d ").append(name).append(" [").append((double) v[0]).append(' ').append((double) v[1]).append(' ')
                .append((double) v[2]).append("]\n");
    }
}
