package ray.parse;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** OBJ reading: what is kept, fans, indices in every form, and one located line per mistake. */
class ObjFileTest {

    @TempDir
    Path dir;

    private ObjFile read(String text) throws IOException, SceneFormatException {
        Path p = dir.resolve("m.obj");
        Files.writeString(p, text);
        return ObjFile.read(p, "m.obj");
    }

    private String error(String text) throws IOException {
        Path p = dir.resolve("m.obj");
        Files.writeString(p, text);
        return assertThrows(SceneFormatException.class, () -> ObjFile.read(p, "m.obj")).getMessage();
    }

    @Test
    void quadIsSplitIntoAFan() throws Exception {
        ObjFile o = read("# a quad and a pentagon\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\n"
                + "f 1 2 3 4\nf 1 2 3 4 5\n");
        assertEquals(2, o.faces);
        assertArrayEquals(new int[] {0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3, 0, 3, 4}, o.triangles);
        assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, -1, 0.5f, 0}, o.positions);
        assertNull(o.cornerNormals);
    }

    @Test
    void everyCornerFormAndNegativeIndices() throws Exception {
        ObjFile o = read("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\nvn 0 0.6 0.8\n"
                + "f 1 2 3\nf 1/1 2/2 3/3\nf 1//1 2//2 3//1\nf 1/1/2 2/2/2 3/3/1\nf -3 -2 -1\nf -3//-1 -2//-2 -1//-1\n");
        assertEquals(6, o.triangleCount());
        for (int t = 0; t < 6; t++) {
            assertArrayEquals(new int[] {0, 1, 2}, java.util.Arrays.copyOfRange(o.triangles, 3 * t, 3 * t + 3), "triangle " + t);
        }
        assertArrayEquals(new int[] {-1, -1, -1, -1, -1, -1, 0, 1, 0, 1, 1, 0, -1, -1, -1, 1, 0, 1}, o.cornerNormals);
        assertArrayEquals(new float[] {0, 0, 1, 0, 0.6f, 0.8f}, o.normals);
    }

    @Test
    void otherStatementsAreIgnored() throws Exception {
        ObjFile o = read("mtllib m.mtl\no thing\ng a b\nusemtl red\ns 1\nv 0 0 0 1\nv 1 0 0\nv 0 1 0\nl 1 2\nf 1 2 3\n");
        assertEquals(1, o.triangleCount());
    }

    @Test
    void forwardReferencesAreAllowed() throws Exception {
        assertEquals(1, read("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n").triangleCount());
    }

    @Test
    void mistakesNameTheObjFileAndLine() throws IOException {
        String tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
        assertEquals("m.obj:2: 'v 1 2' has 2 coordinates (expected 'v x y z')", error("v 0 0 0\nv 1 2\n"));
        assertEquals("m.obj:2: cannot read 'v 1 2 x' (expected 'v x y z' with three finite decimal numbers)", error("v 0 0 0\nv 1 2 x\n"));
        assertEquals("m.obj:1: cannot read 'v' (expected 'v x y z' with three finite decimal numbers)", error("v\n"));
        assertEquals("m.obj:1: 'v 1e39 0 0' has a coordinate that is not a finite float (expected 'v x y z', each within +-3.4e38)",
                error("v 1e39 0 0\n"));
        assertEquals("m.obj:2: 'vn 0 1' has 2 coordinates (expected 'vn x y z')", error("v 0 0 0\nvn 0 1\n"));
        assertEquals("m.obj:1: 'vn 0 0 -0' has length 0 (expected 'vn x y z', a direction)", error("vn 0 0 -0\n"));
        assertEquals("m.obj:4: 'f 1 2' has 2 corners (expected a face of at least three: 'f v1 v2 v3 ...')", error(tri + "f 1 2\n"));
        assertEquals("m.obj:4: cannot read 'f 1 x 3' (expected 'f' and at least three corners, each v, v/vt, v//vn or v/vt/vn "
                + "with non-zero whole-number indices)", error(tri + "f 1 x 3\n"));
        assertEquals("m.obj:4: cannot read 'f 0 1 2' (expected 'f' and at least three corners, each v, v/vt, v//vn or v/vt/vn "
                + "with non-zero whole-number indices)", error(tri + "f 0 1 2\n"));
        assertEquals("m.obj:5: a face refers to vertex 9, but the file has 3 vertices (expected indices 1 to 3)",
                error(tri + "\nf 1 2 9\nf 1 2 3\n"));
        assertEquals("m.obj:4: 'f -1 -2 -4' refers to a vertex before the first (expected indices 1 to 3, or -1 to -3 counting back "
                + "from this line)", error(tri + "f -1 -2 -4\n"));
        assertEquals("m.obj:5: 'f 1//2 2//1 3//1' refers to normal 2, but 1 normal is given above it (expected 'vn' lines before the face)",
                error(tri + "vn 0 0 1\nf 1//2 2//1 3//1\n"));
        assertEquals("m.obj:4: 'f 1/1 2/1 3/1' refers to texture coordinate 1, but 0 are given above it (expected 'vt' lines before the face)",
                error(tri + "f 1/1 2/1 3/1\n"));
        assertEquals("m.obj:5: 'f 1//1 2 3' writes its corners differently (expected every corner as v, v/vt, v//vn or v/vt/vn alike)",
                error(tri + "vn 0 0 1\nf 1//1 2 3\n"));
        assertEquals("m.obj:2: binary data (byte 0x00), expected a text OBJ file", error("v 0 0 0\nv 0\0 0 0\n"));
    }

    @Test
    void unreadableFilesAreTheSceneLinesFault() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ObjFile.read(dir.resolve("none.obj"), "none.obj"));
        assertEquals("cannot read the OBJ file none.obj: no such file", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> ObjFile.read(dir, "folder"));
        assertEquals("cannot read the OBJ file folder: it is a directory (expected an OBJ file)", e.getMessage());
    }
}
