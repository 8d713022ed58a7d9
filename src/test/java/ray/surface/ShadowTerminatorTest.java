package ray.surface;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.parse.Parser;
import ray.render.Image;
import ray.render.Renderer;

/**
 * The shadow terminator of a smooth mesh, measured against the analytic sphere: a coarse latitude-
 * longitude sphere (8 x 12 facets) with its vertex normals, lit from the side so the terminator
 * crosses the disc the camera sees, and the same scene with a {@code Sphere}. Where the analytic sphere
 * is clearly lit, the mesh's pixel must not be much darker: without Hanika's lift (rays leaving from
 * the flat facet under a smooth normal) whole facets near the terminator shadow themselves into dark
 * stair steps.
 */
class ShadowTerminatorTest {

    static final String SCENE = """
            Width 160
            Height 160
            BGColor [0 0 1]
            Camera Camera
            Vector3d eye [0 0 4]
            Vector3d target [0 0 0]
            double yFOV 40
            Material Diffuse grey
            Vector3d diffuseColor [0.8 0.8 0.8]
            Light PointLight
            Vector3d position [40 10 8]
            Vector3d intensity [1700 1700 1700]
            """;

    @Test
    void aCoarseSmoothSphereHasNoDarkStepsNearTheTerminator(@TempDir Path dir) throws Exception {
        ObjWriter sphere = ObjWriter.uvSphere(8, 12, 0, 0, 0, 1);
        Files.writeString(dir.resolve("ball.obj"), sphere.obj(true, 0, 0, 0));
        Path meshScene = Files.writeString(dir.resolve("mesh.txt"), SCENE
                + "Surface Mesh\nString file ball.obj\nref material grey\n");
        Path analyticScene = Files.writeString(dir.resolve("analytic.txt"), SCENE
                + "Surface Sphere\ndouble radius 1\nref material grey\n");
        Image mesh = new Renderer(Parser.parse(meshScene)).render();
        Image analytic = new Renderer(Parser.parse(analyticScene)).render();

        int lit = 0, dark = 0;
        double worst = 0;
        for (int p = 0; p < mesh.width * mesh.height; p++) {
            int i = 3 * p;
            boolean onBoth = !(mesh.rgb[i] == 0 && mesh.rgb[i + 1] == 0 && mesh.rgb[i + 2] == 1)
                    && !(analytic.rgb[i] == 0 && analytic.rgb[i + 1] == 0 && analytic.rgb[i + 2] == 1);
            if (!onBoth || analytic.rgb[i] < 0.08) {
                continue;                               // the background, the silhouette's sliver, the unlit side
            }
            lit++;
            double ratio = mesh.rgb[i] / analytic.rgb[i];
            worst = Math.max(worst, 1 - ratio);
            if (ratio < 0.5) {
                dark++;
            }
        }
        System.out.printf("shadow terminator: %d of %d lit pixels under half the analytic value; worst %.0f%% darker%n",
                dark, lit, 100 * worst);
        assertTrue(lit > 3000, "the lit part is seen: " + lit);
        assertTrue(dark == 0, dark + " of " + lit + " lit pixels are under half the analytic sphere's value (shadow terminator)");
    }
}
