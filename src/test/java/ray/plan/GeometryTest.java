package ray.plan;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;

/** The plan names the geometry a scene uses: classes, a CSG's operands, a mesh's triangles, unbounded surfaces. */
class GeometryTest {

    private static String geometry(Scene s) {
        return PlanReport.of("t", s).effects().stream().filter(e -> e.name.equals("geometry")).findFirst().orElseThrow().why;
    }

    @Test
    void countsByClassAndNamesTheOperandsOfACsgAndTheUnboundedSurfaces() throws Exception {
        Scene s = Parser.parse("""
                Width 8
                Height 8
                Camera Camera
                Vector3d eye [0 0 5]

                Material Diffuse grey

                Surface Sphere a
                double radius 1
                ref material grey

                Surface Box b
                ref material grey

                Surface CSG
                String operation difference
                ref left a
                ref right b

                Surface Sphere
                Vector3d center [3 0 0]
                ref material grey

                Surface Sphere
                Vector3d center [-3 0 0]
                ref material grey

                Surface Plane
                ref material grey
                """, "g.txt", new ArrayList<>());
        assertEquals("1 CSG (of 1 Box, 1 Sphere), 2 Sphere in the BVH; 1 Plane tested against every ray (unbounded)", geometry(s));
    }

    @Test
    void aMeshSceneNamesItsTriangles() throws Exception {
        String g = geometry(Parser.parse(Path.of("scenes/mesh.txt")));
        assertTrue(g.matches(".*\\d+ Mesh \\([\\d,]+ primitives\\).*"), g);
    }

    @Test
    void aSceneWithoutSurfacesSaysSoAndTheEffectIsOff() throws Exception {
        Scene s = Parser.parse("Width 4\nHeight 4\nCamera Camera\nVector3d eye [0 0 5]\n", "e.txt", new ArrayList<>());
        assertEquals("no surfaces: every ray sees the background", geometry(s));
        assertTrue(PlanReport.of("t", s).effects().stream().noneMatch(e -> e.name.equals("geometry") && e.on));
    }
}
