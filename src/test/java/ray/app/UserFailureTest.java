package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import ray.Failures;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.app.MainBadInputTest.Run;
import ray.material.Material;

/**
 * Issue 11, class 2: whatever a user's class throws while its scene renders (an Error, a linkage
 * error, a checked exception thrown sneakily, an exception whose getMessage() throws, a huge message)
 * gives one line naming the scene, the throwable's class and the method, and the next scene on the
 * command line still renders.
 */
class UserFailureTest {

    @TempDir
    Path dir;

    /** What each material's shade() throws, chosen by the material's name. */
    abstract static class Thrower extends Material {
        abstract Throwable what();

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            throw UserFailureTest.<RuntimeException>sneaky(what());
        }
    }

    @SuppressWarnings("unchecked")
    static <T extends Throwable> T sneaky(Throwable t) throws T {
        throw (T) t;
    }

    public static class Asserting extends Thrower {
        @Override
        Throwable what() {
            return new AssertionError("invariant broken");
        }
    }

    public static class MissingHelper extends Thrower {
        @Override
        Throwable what() {
            return new NoClassDefFoundError("MyHelper");
        }
    }

    public static class Internal extends Thrower {
        @Override
        Throwable what() {
            return new InternalError("deep trouble");
        }
    }

    public static class Checked extends Thrower {
        @Override
        Throwable what() {
            return new IOException("texture.png not found");
        }
    }

    public static class Plain extends Thrower {
        @Override
        Throwable what() {
            return new Throwable("a bare Throwable");
        }
    }

    public static class BadMessage extends Thrower {
        @Override
        Throwable what() {
            return new RuntimeException() {
                @Override
                public String getMessage() {
                    throw new IllegalStateException("getMessage failed");
                }
            };
        }
    }

    public static class Huge extends Thrower {
        @Override
        Throwable what() {
            return new IllegalStateException("x".repeat(1_000_000) + "\n" + "y".repeat(1000));
        }
    }

    /** Its first use in shade() runs a static initialiser that fails. */
    public static class InitFails extends Material {
        static final class Table {
            static final int[] VALUES = build();

            static int[] build() {
                throw new IllegalArgumentException("table size must be positive");
            }
        }

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return new Vector3d(Table.VALUES[0], 0, 0);
        }
    }

    public static class Overflows extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return shade(ray, record, scene);
        }
    }

    private Path scene(String material) throws IOException {
        Path p = dir.resolve(material + ".txt");
        Files.writeString(p, MainBadInputTest.GOOD + "\nMaterial ray.app.UserFailureTest$" + material
                + " m\n\nSurface Sphere\nVector3d center [0 0 0]\nref material m\n");
        return p;
    }

    private void assertFailsAloneInOneLine(String material, String... expectedParts) throws IOException {
        Path bad = scene(material), good = dir.resolve("good.txt");
        Files.writeString(good, MainBadInputTest.GOOD);
        // one thread: a failed static initialiser throws ExceptionInInitializerError once, then every other
        // thread gets NoClassDefFoundError ("Could not initialize class"): which one is reported would race
        Run r = MainBadInputTest.run("-q", "-j", "1", bad.toString(), good.toString());
        assertEquals(1, r.status(), material + ": " + r.err());
        assertEquals(1, r.errLines().size(), material + ": one line, no stack trace:\n" + r.err());
        String line = r.errLines().get(0);
        assertTrue(line.startsWith(bad + ": rendering failed: "), line);
        for (String part : expectedParts) {
            assertTrue(line.contains(part), material + ": '" + part + "' missing in: " + line);
        }
        assertTrue(line.length() < 600, material + ": a readable line, not " + line.length() + " characters");
        assertFalse(Files.exists(dir.resolve(material + ".png")));
        assertTrue(Files.size(dir.resolve("good.png")) > 0, material + ": the next scene still renders");
        Files.delete(dir.resolve("good.png"));
    }

    @Test
    void assertionError() throws IOException {
        assertFailsAloneInOneLine("Asserting", "AssertionError (invariant broken)", "UserFailureTest$Asserting.what(");
    }

    @Test
    void noClassDefFoundError() throws IOException {
        assertFailsAloneInOneLine("MissingHelper", "NoClassDefFoundError (MyHelper)", "UserFailureTest$MissingHelper.what(");
    }

    @Test
    void internalError() throws IOException {
        assertFailsAloneInOneLine("Internal", "InternalError (deep trouble)", "UserFailureTest$Internal.what(");
    }

    @Test
    void checkedExceptionThrownSneakily() throws IOException {
        assertFailsAloneInOneLine("Checked", "IOException (texture.png not found)", "UserFailureTest$Checked.what(");
    }

    @Test
    void bareThrowable() throws IOException {
        assertFailsAloneInOneLine("Plain", "Throwable (a bare Throwable)", "UserFailureTest$Plain.what(");
    }

    @Test
    void getMessageThatThrows() throws IOException {
        assertFailsAloneInOneLine("BadMessage", "UserFailureTest$BadMessage$1 (its getMessage() threw IllegalStateException)", "UserFailureTest$BadMessage.what(");
    }

    @Test
    void hugeMessageIsCut() throws IOException {
        assertFailsAloneInOneLine("Huge", "xxxxx... (1001001 characters)", "UserFailureTest$Huge.what(");
    }

    @Test
    void failingStaticInitialiser() throws IOException {
        assertFailsAloneInOneLine("InitFails", "ExceptionInInitializerError (caused by IllegalArgumentException: table size must be positive)", "InitFails.shade(");
    }

    @Test
    void stackOverflow() throws IOException {
        assertFailsAloneInOneLine("Overflows", "StackOverflowError", "Overflows.shade(");
    }

    @Test
    void failuresNeverPrintMoreThanOneLine() {
        Throwable noStack = new Error("no stack");
        noStack.setStackTrace(new StackTraceElement[0]);
        assertEquals("Error (no stack)", Failures.describe(noStack));
        assertEquals(List.of("a b"), List.of(Failures.message(new RuntimeException("a\u2028b"))));
    }
}
