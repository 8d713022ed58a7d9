package ray.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;

/**
 * CSG in whole scenes, through the parser and the BVH, rendered with shadows and mirror rays:
 * degenerate set operations render bit for bit as the plain spheres, and mistakes are one line.
 */
class CSGSceneTest {

    /** Camera, lights, materials, a floor, and spheres a (red), b (glazed blue), c (green, far off). */
    static final String COMMON = """
            Width 48
            Height 36
            AmbientLight [0.1 0.1 0.1]
            Camera Camera
            Vector3d eye [0 1.5 6]
            Vector3d target [0 0 0]

            Light PointLight
            Vector3d position [3 5 4]
            Vector3d intensity [30 30 30]

            Material Diffuse red
            Vector3d ambientColor [0.2 0 0]
            Vector3d diffuseColor [0.8 0.1 0.1]

            Material BlinnPhong blueBase
            Vector3d diffuseColor [0.1 0.1 0.8]
            Vector3d specularColor [1 1 1]
            double exponent 40

            Material Glazed blue
            ref base blueBase
            double mirrorCoefficient 0.4

            Material Diffuse green
            Vector3d diffuseColor [0.1 0.8 0.1]

            Surface Triangle
            Vector3d v0 [-20 -1 -20]
            Vector3d v1 [-20 -1 20]
            Vector3d v2 [20 -1 20]
            ref material green

            Surface Triangle
            Vector3d v0 [-20 -1 -20]
            Vector3d v1 [20 -1 20]
            Vector3d v2 [20 -1 -20]
            ref material green

            Surface Sphere a
            Vector3d center [-1.1 0 0]
            double radius 1
            ref material red

            Surface Sphere b
            Vector3d center [1.2 0.2 -0.3]
            double radius 0.9
            ref material blue

            Surface Sphere c
            Vector3d center [0 4 -9]
            double radius 0.5
            ref material green

            """;

    static Scene parse(String text) throws SceneFormatException {
        List<String> warnings = new ArrayList<>();
        return Parser.parse(text, "scene.txt", warnings);
    }

    static Image render(String text) throws SceneFormatException {
        return new ray.render.Renderer(parse(text)).render();
    }

    /** The common scene with only the named spheres left in it. */
    private static String only(String... spheres) {
        String s = COMMON;
        for (String name : new String[] {"a", "b", "c"}) {
            if (!List.of(spheres).contains(name)) {
                s = cut(s, "Surface Sphere " + name + "\n");
            }
        }
        return s;
    }

    private static String cut(String s, String header) {
        int i = s.indexOf(header), j = s.indexOf("\n\n", i);
        return s.substring(0, i) + s.substring(j + 2);
    }

    private static String csg(String name, String op, String left, String right) {
        return "Surface CSG " + name + "\nString operation " + op + "\nref left " + left + "\nref right " + right + "\n\n";
    }

    @Test
    void unionOfDisjointSpheresRendersAsTheTwoSpheres() throws SceneFormatException {
        assertArrayEquals(render(only("a", "b")).rgb, render(only("a", "b") + csg("u", "union", "a", "b")).rgb);
    }

    /** Nested: (a union b) minus c, c far from both, is a union b. */
    @Test
    void nestedCsgRendersAsItsDegenerateCase() throws SceneFormatException {
        assertArrayEquals(render(only("a", "b")).rgb, render(COMMON + csg("u", "union", "a", "b") + csg("v", "difference", "u", "c")).rgb);
    }

    @Test
    void differenceWhoseRightMissesTheLeftRendersAsTheLeft() throws SceneFormatException {
        assertArrayEquals(render(only("a")).rgb, render(COMMON + csg("d", "difference", "a", "c") + csg("e", "difference", "b", "b")).rgb);
    }

    @Test
    void intersectionOfASphereWithItselfRendersAsTheSphere() throws SceneFormatException {
        assertArrayEquals(render(only("b")).rgb, render(only("b") + csg("i", "intersection", "b", "b")).rgb);
    }

    @Test
    void operandsAreNotRenderedOnTheirOwn() throws SceneFormatException {
        Scene s = parse(COMMON + csg("u", "union", "a", "b") + csg("v", "difference", "u", "c"));
        assertEquals(3, s.surfaces.size(), "two floor triangles and the outer CSG: " + s.surfaces);
        assertInstanceOf(CSG.class, s.surfaces.get(2));
    }

    /** The render plan's ray bound counts the operands' materials: b's mirror rays, though the CSG's own material is a's. */
    @Test
    void planCountsTheOperandsMaterials() throws SceneFormatException {
        Scene s = parse(only("a", "b") + csg("u", "union", "a", "b"));
        s.prepare();
        assertTrue(ray.plan.RenderPlan.derive(s, ray.plan.RenderPlan.NO_SKIPS).bound().get(ray.RayKind.MIRROR) > 0);
    }

    private static String error(String text) {
        return assertThrows(SceneFormatException.class, () -> parse(text)).getMessage();
    }

    @Test
    void mistakesAreOneLineNamingTheCsg() {
        int line = (int) COMMON.lines().count() + 1;
        assertEquals("scene.txt:" + line + ": Surface CSG: unknown operation 'xor' (expected union, intersection or difference)",
                error(COMMON + csg("x", "xor", "a", "b")));
        assertEquals("scene.txt:" + line + ": Surface CSG: right operand Triangle is not a closed surface "
                        + "(expected Sphere, Box, Cylinder, Cone, Torus, CSG or a closed two-sided Mesh)",
                error(COMMON.replace("Surface Triangle\nVector3d v0 [-20 -1 -20]\nVector3d v1 [20",
                        "Surface Triangle t\nVector3d v0 [-20 -1 -20]\nVector3d v1 [20") + csg("x", "union", "a", "t")));
        assertEquals("scene.txt:" + line + ": Surface CSG: no right operand (expected 'ref right <name>' naming a closed surface)",
                error(COMMON + "Surface CSG\nref left a\n\n"));
        String missing = error(COMMON + csg("x", "union", "a", "nothing"));
        assertFalse(missing.contains("\n"), missing);
        assertEquals(("scene.txt:" + (line + 3) + ": undefined object 'nothing'"), missing.substring(0, missing.indexOf(" in ")));
    }
}
