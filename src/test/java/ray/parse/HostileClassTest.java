package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.Scene;

/**
 * Issue 17: a class whose file is there but cannot be loaded is named with its real cause (not
 * "unknown class"), and a camera far from the origin is not "the same point" as its target.
 */
class HostileClassTest {

    @TempDir
    Path dir;

    static final String HEAD = "Width 4\nHeight 3\n\nCamera Camera\n\n";

    private String failure(String text, ClassLoader loader) {
        return assertThrows(SceneFormatException.class, () -> Parser.parse(text, "s.txt", new ArrayList<>(), loader)).getMessage();
    }

    /** One javac run (it is slow to start): a class patched to a future class-file version, and one whose superclass is deleted. */
    @Test
    void aClassThatCannotBeLoadedIsNamedWithItsCause() throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assumeTrue(javac != null, "a JDK with javac is needed");
        Path a = Files.writeString(dir.resolve("NewShape.java"), "public class NewShape extends ray.surface.Sphere { }");
        Path b = Files.writeString(dir.resolve("Shapes.java"), "class Base extends ray.surface.Sphere { }\npublic class Shapes extends Base { }");
        assertEquals(0, javac.run(null, null, null, "-d", dir.toString(), "-cp", System.getProperty("java.class.path"), a.toString(), b.toString()));
        URLClassLoader loader = new URLClassLoader(new URL[] {dir.toUri().toURL()}, Parser.class.getClassLoader());
        Path cls = dir.resolve("NewShape.class");
        byte[] bytes = Files.readAllBytes(cls);
        bytes[6] = 0;
        bytes[7] = 99;         // class file major version 99: a Java from the future
        Files.write(cls, bytes);
        Files.delete(dir.resolve("Base.class"));

        String m = failure(HEAD + "Surface NewShape\n", loader);
        assertEquals(true, m.startsWith("s.txt:6: class 'NewShape' cannot be loaded: it was compiled for a newer Java than this one (Java "
                + Runtime.version().feature() + "): "), m);
        assertEquals(true, m.endsWith("(expected it recompiled, e.g. javac --release " + Runtime.version().feature() + ")"), m);
        assertEquals("s.txt:6: class 'Shapes' cannot be loaded: it needs the class Base, which is not on the class path (expected every "
                + "class it extends or uses compiled beside it)", failure(HEAD + "Surface Shapes\n", loader));
        // a name with no class file at all is still "unknown"
        String unknown = failure(HEAD + "Surface Nothing\n", loader);
        assertEquals(true, unknown.startsWith("s.txt:6: unknown Surface class 'Nothing'"), unknown);
    }

    @Test
    void aFarEyeIsNotTheSamePointAsItsTarget() throws SceneFormatException {
        Scene s = Parser.parse("Width 4\nHeight 3\n\nCamera Camera\nVector3d eye [1e308 1e308 1e308]\nVector3d target [0 0 0]\n"
                + "Vector3d up [0 1e308 0]\n", "s.txt", new ArrayList<>());
        assertEquals(1 / Math.sqrt(3), s.camera.w.x, 1e-15);
        String m = failure("Width 4\nHeight 3\n\nCamera Camera\nVector3d eye [1e308 0 0]\nVector3d target [-1e308 0 0]\n",
                Parser.class.getClassLoader());
        assertEquals("s.txt:4: Camera Camera: camera eye (1.0E308, 0.0, 0.0) and target (-1.0E308, 0.0, 0.0) are too far apart: "
                + "their difference overflows a double (expected coordinates within about +-8.9e307)", m);
    }

    /** Cylinder's and Cone's derived fields (frame, height) are not settable, nor listed as if they were. */
    @Test
    void derivedFieldsOfAxialSurfacesAreNotSettable() {
        for (String cls : new String[] {"Cylinder", "Cone"}) {
            String m = failure("Width 4\nHeight 3\n\nCamera Camera\n\nMaterial Diffuse d\n\nSurface " + cls + "\ndouble height 2\n"
                    + "ref material d\n", Parser.class.getClassLoader());
            assertEquals("s.txt:9: field 'height' of " + cls + " is private and cannot be set from a scene (expected one of: base, axis, "
                    + "radius, material)", m);
        }
    }
}
