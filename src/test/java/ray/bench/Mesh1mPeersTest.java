package ray.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The bench's translations of mesh1m for the peers ({@link Mesh1mPeers}), on a tiny mesh1m-like scene: the
 * area light as each peer's area light with n x n samples at our grid's cell centres, the OBJ's faces fanned
 * and its normals kept, and the files written once.
 */
class Mesh1mPeersTest {

    private static final String SCENE = """
            # a tiny mesh1m
            Width 64
            Height 32
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
            Vector3d edge1 [1 0 0]
            Vector3d edge2 [0 0 2]
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
            String file tiny.obj
            ref material clay
            int smooth 1

            Surface Triangle
            Vector3d v0 [-8 -1.1 -8]
            Vector3d v1 [-8 -1.1 8]
            Vector3d v2 [8 -1.1 8]
            ref material ground
            """;

    /** Two faces: a quad (fanned into two triangles) and a triangle; five vertices with normals. */
    private static final String OBJ = """
            v 0 0 0
            vn 0 0 1
            v 1 0 0
            vn 0 0 1
            v 1 1 0
            vn 0 0 1
            v 0 1 0
            vn 0 0 1
            v 0.5 2 0.25
            vn 0 0.6 0.8
            f 1//1 2//2 3//3 4//4
            f 4//4 3//3 5//5
            """;

    @Test
    void translatesTheAreaLightAndTheMeshForEachPeer(@TempDir Path dir) throws IOException {
        Path scene = dir.resolve("mesh1m.txt");
        Files.writeString(scene, SCENE);
        Files.writeString(dir.resolve("tiny.obj"), OBJ);
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        Mesh1mPeers.write(scene, new PrintStream(log, true, StandardCharsets.UTF_8));
        assertTrue(log.toString(StandardCharsets.UTF_8).contains("writing the peers' translations"));

        // POV: the lights from -axis/2 to +axis/2 inclusive, so axes of edge (n-1)/n put them at the cell centres
        String pov = Files.readString(Mesh1mPeers.dir(dir, "pov").resolve("mesh1m.pov"));
        assertTrue(pov.contains("light_source { <2,4,3> color rgb <1.5e+07,1.5e+07,1.5e+07> area_light <0.75,0,0>, <0,0,1.5>, 4, 4"
                + " area_illumination on fade_distance 0.001 fade_power 2 }"), pov);
        assertTrue(pov.contains("vertex_vectors { 5,\n<0,0,0>,\n<1,0,0>,\n<1,1,0>,\n<0,1,0>,\n<0.5,2,0.25> }"), pov);
        assertTrue(pov.contains("normal_vectors { 5,\n<0,0,1>,"), pov);
        assertTrue(pov.contains("face_indices { 3,\n<0,1,2>,\n<0,2,3>,\n<3,2,4> }\n  texture { T_clay }"), pov);
        assertTrue(pov.contains("finish { ambient rgb <1,1,1> diffuse 1 specular 0.3 roughness 0.025 }"), pov);
        assertTrue(pov.contains("mesh {\ntriangle{<-8,-1.1,-8>,<-8,-1.1,8>,<8,-1.1,8>}\ntexture { T_ground } }"), pov);
        assertTrue(Files.readString(Mesh1mPeers.dir(dir, "pov").resolve("mesh1m.ini")).contains("Width=64\nHeight=32\n"));

        // Sunflow: two triangles facing the scene, 8 samples each; radiance pi I / (A cos) at the target
        String sc = Files.readString(Mesh1mPeers.dir(dir, "sunflow").resolve("mesh1m.sc"));
        double cos = 4.1 / Math.sqrt(2 * 2 + 4.1 * 4.1 + 3 * 3);
        assertEquals(cos, Mesh1mPeers.cosToTarget(Mesh1mPeers.Scene.parse(SCENE)), 1e-12);
        String l = Mesh1mPeers.g(Math.PI * 30 / (2 * cos));
        assertTrue(sc.contains("type meshlight\n  name area\n  emit { \"sRGB linear\" " + l + " " + l + " " + l + " }\n  radiance 1\n"
                + "  samples 8\n  points 4\n    1.5 4 2\n    2.5 4 2\n    2.5 4 4\n    1.5 4 4\n  triangles 2\n    0 1 2\n    0 2 3\n"), sc);
        assertTrue(sc.contains("points 5\n    0 0 0\n"), sc);
        assertTrue(sc.contains("triangles 3\n    0 1 2\n    0 2 3\n    3 2 4\n  normals vertex\n    0 0 1\n"), sc);

        // Mitsuba: a rectangle emitter of radiance I / A facing down, sampled 4 x 4 by the bench's script
        Path mi = Mesh1mPeers.dir(dir, "mitsuba_llvm");
        String xml = Files.readString(mi.resolve("mesh1m.xml"));
        assertTrue(xml.contains("<integer name=\"area_samples\" value=\"4\"/>"), xml);
        assertTrue(xml.contains("<matrix value=\"0.5 0 0 2 0 0 -1 4 0 1 0 3 0 0 0 1\"/>"), xml);
        assertTrue(xml.contains("<rgb name=\"radiance\" value=\"15,15,15\"/>"), xml);
        assertTrue(xml.contains("value=\"../../tiny.obj\"/><boolean name=\"face_normals\" value=\"false\"/><ref id=\"clay\"/>"), xml);
        assertEquals("# generated by ray.bench.Mesh1mPeers\nv -8 -1.1 -8\nv -8 -1.1 8\nv 8 -1.1 8\nf 1 2 3\n",
                Files.readString(mi.resolve("mesh1m_ground.obj")));
        assertTrue(Files.readString(mi.resolve(Mesh1mPeers.MITSUBA_SCRIPT)).contains("area_samples"));

        // written once: a second call finds the stamp and writes nothing
        log.reset();
        Files.writeString(Mesh1mPeers.dir(dir, "pov").resolve("mesh1m.ini"), "kept");
        Mesh1mPeers.write(scene, new PrintStream(log, true, StandardCharsets.UTF_8));
        assertEquals("", log.toString(StandardCharsets.UTF_8));
        assertEquals("kept", Files.readString(Mesh1mPeers.dir(dir, "pov").resolve("mesh1m.ini")));
    }

    @Test
    void tachyonHasNoAreaLight() {
        assertEquals("no area lights", Peers.reason("tachyon", LongScenes.MESH1M));
        assertNull(Peers.reason("pov", LongScenes.MESH1M));
        assertNull(Peers.reason("tachyon", "classic"));
    }
}
