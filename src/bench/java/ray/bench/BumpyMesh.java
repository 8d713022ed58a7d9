package ray.bench;

import java.io.BufferedWriter;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * A bumpy sphere of quads between latitude rings and triangles at the poles, facing outward, with
 * vertex normals, as a Wavefront OBJ file: the million-triangle mesh of the benchmark's {@code mesh1m}
 * scene and of {@code gradle meshLoad}. Deterministic: the same arguments write the same bytes.
 */
public final class BumpyMesh {

    private BumpyMesh() {
    }

    /** Rings and segments for about {@code quads} quads: 2 * quads triangles after fanning. */
    public static int[] grid(int quads) {
        int slices = (int) Math.round(Math.sqrt(2.0 * quads));
        return new int[] {slices, Math.max(2, quads / slices)};
    }

    /** Triangles of the mesh {@link #writeObj} writes: two per quad, one per pole segment. */
    public static long triangles(int slices, int stacks) {
        return 2L * slices * (stacks - 2) + 2L * slices;
    }

    /** Writes the sphere (unit radius, bumps of about 0.1) with {@code slices} segments and {@code stacks} rings. */
    public static void writeObj(Path p, int slices, int stacks) throws IOException {
        try (BufferedWriter w = Files.newBufferedWriter(p)) {
            w.write("v 0 1 0\nvn 0 1 0\n");
            for (int i = 1; i < stacks; i++) {
                double th = Math.PI * i / stacks;
                for (int j = 0; j < slices; j++) {
                    double ph = 2 * Math.PI * j / slices;
                    double r = 1 + 0.08 * Math.sin(7 * th) * Math.cos(5 * ph) + 0.03 * Math.sin(23 * th + 17 * ph);
                    double x = Math.sin(th) * Math.cos(ph), y = Math.cos(th), z = -Math.sin(th) * Math.sin(ph);
                    w.write(String.format(Locale.ROOT, "v %.6f %.6f %.6f\nvn %.4f %.4f %.4f\n", r * x, r * y, r * z, x, y, z));
                }
            }
            w.write("v 0 -1 0\nvn 0 -1 0\n");
            int south = 2 + (stacks - 1) * slices;
            for (int j = 0; j < slices; j++) {
                int j1 = (j + 1) % slices;
                w.write("f 1//1 " + (2 + j) + "//" + (2 + j) + " " + (2 + j1) + "//" + (2 + j1) + "\n");
                for (int i = 1; i + 1 < stacks; i++) {
                    int a = 2 + (i - 1) * slices, b = 2 + i * slices;
                    w.write("f " + (a + j) + "//" + (a + j) + " " + (b + j) + "//" + (b + j) + " " + (b + j1) + "//" + (b + j1)
                            + " " + (a + j1) + "//" + (a + j1) + "\n");
                }
                int last = 2 + (stacks - 2) * slices;
                w.write("f " + (last + j) + "//" + (last + j) + " " + south + "//" + south + " " + (last + j1) + "//"
                        + (last + j1) + "\n");
            }
        }
    }
}
