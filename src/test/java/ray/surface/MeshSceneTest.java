package ray.surface;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;

/**
 * Meshes in whole scenes, rendered with shadows and a mirror: an OBJ mesh renders bit for bit as the
 * same triangles written as {@code Triangle} objects, a quad face as its two fan triangles, and
 * mistakes in a scene or in the OBJ file are one line naming the right file and line.
 */
class MeshSceneTest {

    static final String HEAD = """
            Width 40
            Height 30
            AmbientLight [0.1 0.1 0.1]
            Camera Camera
            Vector3d eye [0.3 1.2 5]
            Vector3d target [0 0 0]

            Light PointLight
            Vector3d position [3 5 4]
            Vector3d intensity [30 30 30]

            Material BlinnPhong white
            Vector3d diffuseColor [0.7 0.7 0.7]
            Vector3d specularColor [0.5 0.5 0.5]
            double exponent 30

            Material Diffuse floorMaterial
            Vector3d diffuseColor [0.3 0.6 0.3]

            Material Glazed mirror
            ref base floorMaterial
            double mirrorCoefficient 0.5

            Surface Triangle
            Vector3d v0 [-20 -1.2 -20]
            Vector3d v1 [-20 -1.2 20]
            Vector3d v2 [20 -1.2 20]
            ref material mirror

            Surface Triangle
            Vector3d v0 [-20 -1.2 -20]
            Vector3d v1 [20 -1.2 20]
            Vector3d v2 [20 -1.2 -20]
            ref material mirror

            """;

    @TempDir
    Path dir;
    private ObjWriter sphere;

    @BeforeEach
    void makeSphere() {
        sphere = ObjWriter.uvSphere(9, 14, 0.1f, 0, -0.2f, 1.1f);
    }

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.writeString(p, text);
        return p;
    }

    private Scene parse(String text) throws SceneFormatException {
        return Parser.parse(text, dir.resolve("scene.txt").toString(), new ArrayList<>());
    }

    private double[] render(String text) throws SceneFormatException {
        Image img = new ray.render.Renderer(parse(text)).render();
        return img.rgb;
    }

    private static String mesh(String file, String extra) {
        return "Surface Mesh\nString file " + file + "\nref material white\n" + extra + "\n";
    }

    @Test
    void meshRendersAsTheSameTrianglesWrittenAsTriangles() throws Exception {
        write("flat.obj", sphere.obj(false, 0.1f, 0, -0.2f));
        write("normals.obj", sphere.obj(true, 0.1f, 0, -0.2f));
        double[] triangles = render(HEAD + sphere.sceneTriangles("white"));
        assertArrayEquals(triangles, render(HEAD + mesh("flat.obj", "")), "a file without vn, smooth by default");
        assertArrayEquals(triangles, render(HEAD + mesh("normals.obj", "int smooth 0\n")), "smooth 0 ignores vn");
        assertFalse(java.util.Arrays.equals(triangles, render(HEAD + mesh("normals.obj", ""))), "smooth normals change the shading");
    }

    @Test
    void quadFacesRenderAsTheirFanTriangles() throws Exception {
        write("quads.obj", sphere.obj(false, 0.1f, 0, -0.2f));
        write("fans.obj", sphere.objTriangles());
        assertTrue(Files.readString(dir.resolve("quads.obj")).lines().anyMatch(l -> l.startsWith("f ") && l.split(" ").length == 5));
        assertArrayEquals(render(HEAD + mesh("fans.obj", "")), render(HEAD + mesh("quads.obj", "")));
    }

    /**
     * From inside, a one-sided mesh's faces point away: camera rays pass through (it still shadows the
     * floor outside, as the same Triangles do); a two-sided mesh shows its lit inside.
     */
    @Test
    void twoSidedMeshIsSeenFromInside() throws Exception {
        write("s.obj", sphere.obj(false, 0.1f, 0, -0.2f));
        String inside = HEAD.replace("Vector3d eye [0.3 1.2 5]", "Vector3d eye [0.1 0.2 -0.1]");
        double[] oneSided = render(inside + mesh("s.obj", ""));
        assertArrayEquals(render(inside + sphere.sceneTriangles("white")), oneSided);
        assertFalse(java.util.Arrays.equals(oneSided, render(inside + mesh("s.obj", "int twoSided 1\n"))));
    }

    private String error(String text) {
        return assertThrows(SceneFormatException.class, () -> parse(text)).getMessage();
    }

    @Test
    void mistakesAreOneLineNamingTheFileAtFault() throws Exception {
        String scene = dir.resolve("scene.txt").toString();
        int line = (int) HEAD.lines().count() + 1;
        assertEquals(scene + ":" + line + ": Surface Mesh: cannot read the OBJ file " + dir.resolve("none.obj") + ": no such file",
                error(HEAD + mesh("none.obj", "")));
        write("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n");
        assertEquals(dir.resolve("bad.obj") + ":3: 'v 0 1' has 2 coordinates (expected 'v x y z') (read for the Surface Mesh at "
                + scene + ":" + line + ")", error(HEAD + mesh("bad.obj", "")));
        write("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
        assertEquals(dir.resolve("range.obj") + ":4: a face refers to vertex 4, but the file has 3 vertices (expected indices 1 to 3)"
                + " (read for the Surface Mesh at " + scene + ":" + line + ")", error(HEAD + mesh("range.obj", "")));
        write("empty.obj", "# nothing\nv 0 0 0\n");
        assertEquals(scene + ":" + line + ": Surface Mesh: the OBJ file " + dir.resolve("empty.obj")
                + " has no faces (expected at least one 'f' line)", error(HEAD + mesh("empty.obj", "")));
        assertEquals(scene + ":" + line + ": Surface Mesh: smooth is 2 (expected 0 for flat facets or 1 for smooth normals)",
                error(HEAD + mesh("empty.obj", "int smooth 2\n")));
        write("s.obj", sphere.obj(false, 0.1f, 0, -0.2f));
        String glass = "Material Dielectric glass\n\n";
        assertEquals(scene + ":" + (line + 2) + ": Surface Mesh: a Mesh with a DielectricMaterial must be closed: it is one-sided, and a"
                + " closed mesh needs 'int twoSided 1' (glass needs an inside)",
                error(HEAD + glass + mesh("s.obj", "").replace("white", "glass")));
        parse(HEAD + glass + mesh("s.obj", "int twoSided 1\n").replace("white", "glass"));
    }

    @Test
    void csgOperandMustBeAClosedTwoSidedMesh() throws Exception {
        write("s.obj", sphere.obj(false, 0.1f, 0, -0.2f));
        write("open.obj", sphere.objTriangles().replaceFirst("(?m)^f .*\n", ""));
        String ball = "Surface Sphere b\nVector3d center [3 0 0]\nref material white\n\n";
        String csg = "Surface CSG\nString operation difference\nref left m\nref right b\n\n";
        String scene = dir.resolve("scene.txt").toString();
        int line = (int) HEAD.lines().count() + 1 + 4 + 4;
        assertEquals(scene + ":" + line + ": Surface CSG: left operand Mesh is not a closed surface: it is one-sided,"
                + " and a closed mesh needs 'int twoSided 1' (expected Sphere, Box, Cylinder, Cone, Torus, CSG or a closed two-sided Mesh)",
                error(HEAD + mesh("s.obj", "").replace("Surface Mesh", "Surface Mesh m") + ball + csg));
        assertEquals(scene + ":" + (line + 1) + ": Surface CSG: left operand Mesh is not a closed surface: " + dir.resolve("open.obj")
                + ": the edge between vertices 1 and 3 belongs to one face only (a hole in the surface)"
                + " (expected Sphere, Box, Cylinder, Cone, Torus, CSG or a closed two-sided Mesh)",
                error(HEAD + mesh("open.obj", "int twoSided 1\n").replace("Surface Mesh", "Surface Mesh m") + ball + csg));
        // closed and two-sided: accepted, and the difference with a sphere it does not touch renders as the mesh
        assertArrayEquals(render(HEAD + mesh("s.obj", "int twoSided 1\n")),
                render(HEAD + mesh("s.obj", "int twoSided 1\n").replace("Surface Mesh", "Surface Mesh m") + ball + csg));
    }
}
