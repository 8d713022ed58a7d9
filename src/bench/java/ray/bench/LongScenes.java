package ray.bench;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * The benchmark's generated long render, {@code mesh1m}: a bumpy sphere of about a million triangles
 * (an OBJ file read through {@code Surface Mesh}, smooth normals) on a ground quad, lit by an area light
 * of 4x4 samples, at 1920x1080: 2.1 M camera rays and up to 33 M shadow rays, where steady-state
 * traversal and shadow rays dominate and start-up does not. It is written into the bench's work
 * directory (58 MB of OBJ: never into the repository) and reused while its header line is unchanged.
 */
final class LongScenes {

    static final String MESH1M = "mesh1m";
    /** The scene's first line: a changed generator changes it, so an old file is written again. */
    private static final String HEADER = "# mesh1m v1: a bumpy sphere of 998,000 triangles, area light 4x4, 1920x1080 (ray.bench.LongScenes)";
    private static final int QUADS = 500_000;

    private LongScenes() {
    }

    /** The folder of the generated long renders (and of the peers' translations of mesh1m) in the bench's work directory. */
    static Path dir(Path work) {
        return work.resolve("scenes");
    }

    /** The mesh1m scene file in {@code dir}, written (with its OBJ) unless already there. */
    static Path mesh1m(Path dir, PrintStream out) throws IOException {
        Path scene = dir.resolve(MESH1M + ".txt"), obj = dir.resolve(MESH1M + ".obj");
        if (Files.isRegularFile(scene) && Files.isRegularFile(obj)
                && Files.readString(scene, StandardCharsets.UTF_8).startsWith(HEADER + "\n")) {
            return scene;
        }
        Files.createDirectories(dir);
        int[] g = BumpyMesh.grid(QUADS);
        out.println("- writing the long render " + scene + " and its OBJ mesh (" + BumpyMesh.triangles(g[0], g[1]) + " triangles)");
        Path tmp = dir.resolve(MESH1M + ".obj.tmp");
        BumpyMesh.writeObj(tmp, g[0], g[1]);
        Files.move(tmp, obj, StandardCopyOption.REPLACE_EXISTING);
        Files.writeString(scene, HEADER + "\n" + """
                Width 1920
                Height 1080
                AASamples 1
                BGColor [0.2 0.3 0.5]
                AmbientLight [0.1 0.1 0.1]

                Camera Camera
                Vector3d eye [0 0.5 3.1]
                Vector3d target [0 -0.1 0]
                Vector3d up [0 1 0]
                double yFOV 40

                Light AreaLight
                Vector3d position [2 4 3]
                Vector3d edge1 [1.5 0 0]
                Vector3d edge2 [0 0 1.5]
                Vector3d intensity [30 30 30]
                int samples 4

                Material Diffuse ground
                Vector3d ambientColor [0.5 0.5 0.5]
                Vector3d diffuseColor [0.6 0.6 0.6]

                Material BlinnPhong clay
                Vector3d ambientColor [0.7 0.5 0.4]
                Vector3d diffuseColor [0.7 0.5 0.4]
                Vector3d specularColor [0.3 0.3 0.3]
                double exponent 40

                Surface Mesh
                String file mesh1m.obj
                ref material clay
                int smooth 1

                Surface Triangle
                Vector3d v0 [-8 -1.1 -8]
                Vector3d v1 [-8 -1.1 8]
                Vector3d v2 [8 -1.1 8]
                ref material ground

                Surface Triangle
                Vector3d v0 [-8 -1.1 -8]
                Vector3d v1 [8 -1.1 8]
                Vector3d v2 [8 -1.1 -8]
                ref material ground
                """, StandardCharsets.UTF_8);
        return scene;
    }
}
