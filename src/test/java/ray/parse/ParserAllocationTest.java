package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.material.Diffuse;
import ray.surface.Triangle;

/**
 * A large scene is read without garbage per line: the words and values of a plain line are read where
 * they stand (no String per line or word, no list per vector, no parser object per line), so reading a
 * triangle allocates little beyond the objects the scene keeps. Measured as the bytes this thread
 * allocates (a count, not a time), against building the same triangles by hand.
 */
class ParserAllocationTest {

    private static final int TRIANGLES = 4000;

    private static byte[] plainScene() {
        StringBuilder sb = new StringBuilder("Width 4\nHeight 3\n\nCamera Camera\nVector3d eye [0 0 5]\n\n"
                + "Material Diffuse red\nVector3d diffuseColor [1 0 0]\n\n");
        for (int i = 0; i < TRIANGLES; i++) {
            sb.append("Surface Triangle\n")
              .append("Vector3d v0 [").append(i).append(" 0 0]\n")
              .append("Vector3d v1 [").append(i).append(".5 0 -0.5]\n")
              .append("Vector3d v2 [").append(i).append(" 1 0.25]\n")
              .append("ref material red\n\n");
        }
        return sb.toString().getBytes(StandardCharsets.US_ASCII);
    }

    /** The same scene's triangles, made and added as the parser does, without reading anything. */
    private static Scene byHand(Diffuse red) {
        Scene s = new Scene();
        for (int i = 0; i < TRIANGLES; i++) {
            Triangle t = new Triangle();
            t.v0 = new Vector3d(i, 0, 0);
            t.v1 = new Vector3d(i + 0.5, 0, -0.5);
            t.v2 = new Vector3d(i, 1, 0.25);
            t.material = red;
            t.init();
            s.surfaces.add(t);
        }
        return s;
    }

    private static long allocated() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean()).getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    @Test
    void aPlainTriangleCostsLittleMoreThanTheObjectsKept() throws Exception {
        byte[] bytes = plainScene();
        Diffuse red = new Diffuse();
        long parsed = Long.MAX_VALUE, made = Long.MAX_VALUE;
        for (int round = 0; round < 3; round++) {     // the least of three: class loading and the JIT's own objects drop out
            long t0 = allocated();
            Scene s = Parser.parse(bytes, "plain.txt", new ArrayList<>());
            long t1 = allocated();
            Scene h = byHand(red);
            long t2 = allocated();
            assertEquals(TRIANGLES, s.surfaces.size());
            assertEquals(TRIANGLES, h.surfaces.size());
            parsed = Math.min(parsed, t1 - t0);
            made = Math.min(made, t2 - t1);
        }
        double extra = (double) (parsed - made) / TRIANGLES;
        System.out.printf("parse: %.0f bytes per triangle, by hand %.0f, extra %.0f%n", (double) parsed / TRIANGLES,
                (double) made / TRIANGLES, extra);
        // a String per line alone would be about 50 bytes a line, 250 a triangle; a String per word several times that
        assertTrue(extra < 100, "reading a triangle's five lines allocates " + extra + " bytes beyond the triangle itself");
    }
}
