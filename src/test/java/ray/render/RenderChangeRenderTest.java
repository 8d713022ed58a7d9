package ray.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;
import ray.surface.Sphere;

/**
 * A program (the viewer, a student's driver) renders a scene, changes it and renders again: the second
 * image must be the changed scene's, exactly as if it had been built that way from the start. The
 * renderer prepares the scene on every render (BVH, camera frame, plan), so nothing of the first
 * render's state survives into the second.
 */
class RenderChangeRenderTest {

    private static final String SCENE = """
            Width 24
            Height 16
            BGColor [0.1 0.2 0.3]
            AmbientLight [0.1 0.1 0.1]

            Camera Camera
            Vector3d eye [0 0 6]
            Vector3d target [0 0 0]
            double yFOV 50

            Material Diffuse matte
            Vector3d ambientColor [0.2 0.2 0.2]
            Vector3d diffuseColor [0.3 0.6 0.3]

            Surface Sphere
            Vector3d center [CX 0 0]
            double radius 1
            ref material matte

            Light PointLight
            Vector3d position [3 4 5]
            Vector3d intensity [40 40 40]
            """;

    private static Scene parse(double cx) throws Exception {
        return Parser.parse(SCENE.replace("CX", Double.toString(cx)), "moving.txt", new ArrayList<>());
    }

    private static void assertSameImage(Image expected, Image actual, String what) {
        int differ = 0;
        for (int y = 0; y < expected.height; y++) {
            for (int x = 0; x < expected.width; x++) {
                if (!expected.get(x, y).equals(actual.get(x, y))) {
                    differ++;
                }
            }
        }
        assertEquals(0, differ, what + ": pixels that differ from the scene built that way");
    }

    @Test
    void movingASurfaceBetweenRendersRendersTheMovedSurface() throws Exception {
        Scene scene = parse(-1.5);
        Image before = new Renderer(scene).threads(1).render();
        ((Sphere) scene.surfaces.get(0)).center.set(1.5, 0, 0);
        Image after = new Renderer(scene).threads(1).render();
        assertSameImage(new Renderer(parse(1.5)).threads(1).render(), after, "sphere moved");
        int changed = 0;
        for (int y = 0; y < before.height; y++) {
            for (int x = 0; x < before.width; x++) {
                changed += before.get(x, y).equals(after.get(x, y)) ? 0 : 1;
            }
        }
        assertTrue(changed > 50, "the move is visible: " + changed + " pixels changed");
    }

    @Test
    void addingASurfaceAndMovingTheCameraBetweenRendersShowsBoth() throws Exception {
        Scene scene = parse(0);
        new Renderer(scene).threads(2).render();
        Sphere second = new Sphere();
        second.center = new Vector3d(0, 1.5, -1);
        second.radius = 0.7;
        second.material = scene.surfaces.get(0).material;
        scene.surfaces.add(second);
        scene.camera.eye.set(1, 1, 6);
        Image after = new Renderer(scene).threads(2).render();

        Scene built = parse(0);
        Sphere same = new Sphere();
        same.center = new Vector3d(0, 1.5, -1);
        same.radius = 0.7;
        same.material = built.surfaces.get(0).material;
        built.surfaces.add(same);
        built.camera.eye.set(1, 1, 6);
        assertSameImage(new Renderer(built).threads(2).render(), after, "sphere added, camera moved");
    }
}
