package ray.parse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.Writer;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Nested;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import ray.Camera;
import ray.Scene;
import ray.light.PointLight;
import ray.material.BlinnPhong;
import ray.material.Diffuse;
import ray.material.GlazedMaterial;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The scene parser: one test per mistake a user can make (each must be one located line naming what
 * was found and what was expected), one per built-in class, and the format's rules (comments,
 * globals, defaults, names, case).
 */
class ParserTest {

    /** Lines 1-7 of most test scenes: sizes, a camera and a material named red. Line 8 comes next. */
    static final String BASE = "Width 4\nHeight 3\n\nCamera Camera\n\nMaterial Diffuse red\n\n";
    static final int NEXT = 8;

    static Scene parse(String text) throws SceneFormatException {
        return Parser.parse(text, "t.txt", new ArrayList<>());
    }

    /** Parsing must fail at {@code line} of t.txt with a one-line message containing every fragment. */
    static SceneFormatException assertError(String text, int line, String... fragments) {
        SceneFormatException e = assertThrows(SceneFormatException.class, () -> parse(text));
        assertLocated(e, "t.txt", line, fragments);
        return e;
    }

    static void assertLocated(SceneFormatException e, String file, int line, String... fragments) {
        String m = e.getMessage();
        assertTrue(m.startsWith(file + ":" + line + ": "), () -> "expected prefix " + file + ":" + line + ": in: " + m);
        assertEquals(line, e.line(), m);
        assertEquals(file, e.file(), m);
        assertFalse(m.contains("\n") || m.contains("\r"), () -> "not one line: " + m);
        for (String f : fragments) {
            assertTrue(m.contains(f), () -> "'" + f + "' missing from: " + m);
        }
    }

    static String sphere(String... params) {
        return "Surface Sphere\n" + String.join("\n", params) + (params.length > 0 ? "\n" : "") + "ref material red\n";
    }

    // ---- classes ----

    @Nested
    class Classes {

        @Test
        void unknownClassNamesTheBuiltIns() {
            assertError(BASE + "Surface Sphear\nref material red\n", NEXT, "unknown Surface class 'Sphear'", "Sphere, Triangle");
        }

        @Test
        void jdkClassIsNotASurface() {
            assertError(BASE + "Surface java.lang.Runtime\n", NEXT, "'java.lang.Runtime' is not a Surface", "expected", "Sphere");
        }

        @Test
        void lightUnderSurfaceHeaderSaysWhatItIs() {
            assertError(BASE + "Surface PointLight\n", NEXT, "'PointLight' is a Light, not a Surface", "Sphere");
        }

        @Test
        void surfaceUnderMaterialHeaderSaysWhatItIs() {
            assertError(BASE + "Material Sphere m\n", NEXT, "'Sphere' is a Surface, not a Material", "Diffuse");
        }

        /** The subclass check must come before anything that initialises the class (runs its static block). */
        @Test
        void staticInitialiserOfANonSurfaceNeverRuns() throws Exception {
            assertNull(System.getProperty("raytracer.test.EvilNotASurface.initialised"), "initialised before the test");
            assertError(BASE + "Surface EvilNotASurface\ndouble radius 1\n", NEXT, "'EvilNotASurface' is not a Surface");
            assertError(BASE + "Light EvilNotASurface\n", NEXT, "'EvilNotASurface' is not a Light");
            assertNull(System.getProperty("raytracer.test.EvilNotASurface.initialised"), "the static initialiser ran");
        }

        /** Positive control for the test above: a real Surface of the user's is created, so its static block runs. */
        @Test
        void userSurfaceInDefaultPackageIsFoundAndInitialised() throws Exception {
            Scene s = parse(BASE + "Surface InitFlagSurface\nref material red\n");
            assertEquals("InitFlagSurface", s.surfaces.get(0).getClass().getName());
            assertEquals("true", System.getProperty("raytracer.test.InitFlagSurface.initialised"));
        }

        @Test
        void abstractBaseCannotBeCreated() {
            assertError(BASE + "Surface Surface\n", NEXT, "'Surface' is abstract", "Sphere");
        }

        @Test
        void classNameThatIsNotANameIsRefused() {
            assertError(BASE + "Surface 3D-Sphere\n", NEXT, "'3D-Sphere' is not a class name", "Sphere");
        }

        @Test
        void glazedIsTheSameClassAsGlazedMaterial() throws Exception {
            Scene s = parse(BASE + "Material Glazed g\ndouble mirrorCoefficient 0.25\n\nMaterial GlazedMaterial h\n");
            assertSame(GlazedMaterial.class, s.materials.get(1).getClass());
            assertSame(GlazedMaterial.class, s.materials.get(2).getClass());
            assertEquals(0.25, ((GlazedMaterial) s.materials.get(1)).mirrorCoefficient);
        }

        /** As in the original course: a user's class in the default package is preferred over a built-in of the same name. */
        @Test
        void defaultPackageClassOverridesBuiltInOfSameName(@TempDir Path dir) throws Exception {
            JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
            assumeTrue(javac != null, "no Java compiler in this runtime");
            Path src = dir.resolve("Sphere.java");
            Files.writeString(src, "public class Sphere extends ray.surface.Surface {\n"
                    + "  public double size;\n"
                    + "  public boolean intersects(ray.Ray r, ray.IntersectionRecord h, ray.Scene s) { return false; }\n"
                    + "}\n");
            String cp = location(Surface.class) + java.io.File.pathSeparator + location(Vector3d.class);
            ByteArrayOutputStream diag = new ByteArrayOutputStream();
            int rc = javac.run(null, diag, diag, "--release", "17", "-proc:none", "-cp", cp, "-d", dir.toString(), src.toString());
            assertEquals(0, rc, diag.toString());
            try (URLClassLoader loader = new URLClassLoader(new URL[] {dir.toUri().toURL()}, Parser.class.getClassLoader())) {
                Scene s = Parser.parse(BASE + "Surface Sphere\ndouble size 2\nref material red\n", "t.txt", new ArrayList<>(), loader);
                Surface mine = s.surfaces.get(0);
                assertEquals("Sphere", mine.getClass().getName());
                assertSame(loader, mine.getClass().getClassLoader());
                assertEquals(2.0, mine.getClass().getField("size").getDouble(mine));
            }
        }

        private String location(Class<?> c) throws Exception {
            return Paths.get(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        }
    }

    // ---- fields and values ----

    @Nested
    class FieldsAndValues {

        @Test
        void privateFieldIsRefused() {
            assertError(BASE.replace("Camera Camera\n", "Camera Camera\ndouble halfHeight 1\n"), 5,
                    "field 'halfHeight' of Camera is private", "eye, target, up, yFOV, aspect");
        }

        @Test
        void staticFieldIsRefused() {
            assertError(BASE + "Surface FieldZooSurface\ndouble shared 1\n", NEXT + 1, "field 'shared' of FieldZooSurface is static", "label");
        }

        @Test
        void finalFieldIsRefused() {
            assertError(BASE + "Surface FieldZooSurface\ndouble fixed 2\n", NEXT + 1, "field 'fixed' of FieldZooSurface is final", "label");
        }

        @Test
        void nonexistentFieldListsTheSettableOnes() {
            assertError(BASE + sphere("double radus 2"), NEXT + 1, "Sphere has no field 'radus'", "center, radius, material");
        }

        @Test
        void fieldNamesAreCaseSensitive() {
            assertError(BASE + sphere("double Radius 2"), NEXT + 1, "Sphere has no field 'Radius'", "did you mean 'radius'");
        }

        @ParameterizedTest
        @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
            "int radius 2             | 'int radius' | radius of Sphere is a double | 'double radius",
            "Vector3d radius [1 1 1]  | 'Vector3d radius' | radius of Sphere is a double | 'double radius",
            "double center 1          | 'double center' | center of Sphere is a Vector3d | 'Vector3d center",
            "ref center red           | 'ref center' | center of Sphere is a Vector3d | 'Vector3d center",
            "String radius big        | 'String radius' | radius of Sphere is a double | 'double radius",
            "double material 1        | 'double material' | material of Sphere is a Material | 'ref material"})
        void typeKeywordMustFitTheField(String line, String found, String what, String expected) {
            assertError(BASE + "Surface Sphere\n" + line + "\n", NEXT + 1, found, what, expected);
        }

        @ParameterizedTest
        @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
            "[1 2]         | found 2 numbers",
            "[1 2 3 4]     | found 4 numbers",
            "[]            | found 0 numbers",
            "[1 2 x]       | 'x' is not a number",
            "1 2 3         | missing '['",
            "[1 2 3        | missing ']'",
            "(1 2 3)       | missing '['",
            "[1 2 3]]      | is not a number"})
        void malformedVectorSaysWhatIsWrong(String vector, String found) {
            assertError(BASE + sphere("Vector3d center " + vector), NEXT + 1,
                    "malformed vector '" + vector + "' for center", found, "expected [x y z]");
        }

        @ParameterizedTest
        @ValueSource(strings = {"NaN", "-NaN", "Infinity", "-Infinity", "inf", "1e999", "-1e400"})
        void nonFiniteDoubleIsRefused(String number) {
            assertError(BASE + sphere("double radius " + number), NEXT + 1, "'" + number + "'", "finite", "for radius");
        }

        @ParameterizedTest
        @ValueSource(strings = {"NaN", "Infinity", "1e999"})
        void nonFiniteVectorComponentIsRefused(String number) {
            assertError(BASE + sphere("Vector3d center [0 " + number + " 0]"), NEXT + 1, "'" + number + "'", "finite", "for center");
            assertError("BGColor [" + number + " 0 0]\n" + BASE, 1, "'" + number + "'", "finite", "for BGColor");
        }

        @ParameterizedTest
        @ValueSource(strings = {"1.5", "abc", "0x10", "1e3", "12345678901234567890", "--1", "1_000"})
        void badIntegerForAnIntField(String number) {
            assertError(BASE + "Surface FieldZooSurface\nint boxed " + number + "\n", NEXT + 1, "'" + number + "'", "boxed");
        }

        @Test
        void numbersThatLookOddButAreFine() throws Exception {
            Scene s = parse(BASE + sphere("Vector3d center [-0 +1.5e0 .5]", "double radius 2.") + "\nSurface FieldZooSurface\n"
                    + "int boxed -0\nint big 9000000000\ndouble small 1e-3\nString label hello world\nref material red\n");
            Sphere sp = (Sphere) s.surfaces.get(0);
            assertEquals(new Vector3d(0, 1.5, 0.5), sp.center);
            assertEquals(2.0, sp.radius);
            Surface zoo = s.surfaces.get(1);
            assertEquals(0, zoo.getClass().getField("boxed").get(zoo));
            assertEquals(9_000_000_000L, zoo.getClass().getField("big").getLong(zoo));
            assertEquals(1e-3f, zoo.getClass().getField("small").getFloat(zoo));
            assertEquals("hello world", zoo.getClass().getField("label").get(zoo));
        }

        @Test
        void repeatedFieldNamesTheFirstLine() {
            assertError(BASE + sphere("double radius 1", "double radius 2"), NEXT + 2, "field 'radius' is set twice", "first at line 9");
        }

        @Test
        void negativeRadiusIsReportedAtTheHeader() {
            assertError(BASE + sphere("double radius -1"), NEXT, "Sphere", "radius", "-1", "positive");
        }

        @Test
        void zeroRadiusIsRefusedToo() {
            assertError(BASE + sphere("double radius 0"), NEXT, "radius", "positive");
        }

        @Test
        void parameterWithoutValue() {
            assertError(BASE + sphere("double radius"), NEXT + 1, "'double radius' has no value", "expected 'double radius <number>'");
        }

        @Test
        void parameterLineMissingItsType() {
            assertError(BASE + sphere("radius 2"), NEXT + 1, "'radius 2'", "expected 'double radius 2'");
        }

        @Test
        void unknownTypeKeyword() {
            assertError(BASE + sphere("float radius 2"), NEXT + 1, "unknown parameter type 'float'", "int, double, String, ref or Vector3d");
        }
    }

    // ---- references and names ----

    @Nested
    class References {

        @Test
        void refToUndefinedObjectListsTheKnownNames() {
            assertError(BASE + "Surface Sphere\nref material blue\n", NEXT + 1, "undefined object 'blue'", "declared earlier", "red");
        }

        @Test
        void refToAnObjectOfTheWrongKind() {
            assertError(BASE + "Surface Sphere s1\nref material red\n\nSurface Sphere\nref material s1\n", NEXT + 4,
                    "'s1' is a Sphere", "needs a Material");
        }

        @Test
        void refToALaterObjectIsUndefined() {
            assertError(BASE + "Surface Sphere\nref material later\n\nMaterial Diffuse later\n", NEXT + 1, "undefined object 'later'", "earlier");
        }

        @Test
        void refToTheObjectBeingDefinedIsRefused() {
            assertError(BASE + "Material Glazed g\nref base g\n", NEXT + 1, "'g'", "itself");
        }

        @Test
        void refTakesOneName() {
            assertError(BASE + "Surface Sphere\nref material red blue\n", NEXT + 1, "'ref material' takes one object name", "'red blue'");
        }

        @Test
        void namesAreUniqueAcrossObjectTypes() {
            assertError(BASE + "Surface Sphere red\nref material red\n", NEXT, "the name 'red' is already used", "line 6");
        }

        @Test
        void namesAreCaseSensitive() throws Exception {
            assertError(BASE + "Surface Sphere\nref material Red\n", NEXT + 1, "undefined object 'Red'");
            Scene s = parse(BASE + "Material Diffuse Red\n\nSurface Sphere\nref material Red\n");
            assertSame(s.materials.get(1), s.surfaces.get(0).material);
            assertEquals(2, s.materials.size(), "'red' and 'Red' are two names");
        }

        @Test
        void surfaceWithoutMaterial() {
            assertError(BASE + "Surface Sphere\ndouble radius 1\n", NEXT, "Sphere has no material", "expected 'ref material <name>'");
        }
    }

    // ---- structure and globals ----

    @Nested
    class Structure {

        @Test
        void missingCameraIsReportedAtTheEnd() {
            assertError("Width 4\nHeight 3\n\nMaterial Diffuse red\n", 4, "no camera", "expected a 'Camera Camera' object");
        }

        @Test
        void secondCamera() {
            assertError(BASE + "Camera Camera\n", NEXT, "a second camera", "first at line 4");
        }

        @Test
        void missingWidth() {
            assertError("Height 3\n\nCamera Camera\n", 3, "no Width", "expected 'Width <pixels>'");
        }

        @Test
        void globalSetTwice() {
            assertError(BASE + "Width 5\n", NEXT, "Width is set twice", "first at line 1");
        }

        @ParameterizedTest
        @CsvSource(delimiter = '|', quoteCharacter = '"', value = {
            "Width 0            | 'Width 0' is out of range     | expected 1 to 65536",
            "Width -4           | 'Width -4' is out of range    | expected 1 to 65536",
            "Width 100000       | 'Width 100000' is out of range| expected 1 to 65536",
            "Width 99999999999  | 'Width 99999999999' is out of range | expected 1 to 65536",
            "Height 0           | 'Height 0' is out of range    | expected 1 to 65536",
            "AASamples 0        | 'AASamples 0' is out of range | expected 1 to 64",
            "AASamples -2       | 'AASamples -2' is out of range| expected 1 to 64",
            "AASamples 1000     | 'AASamples 1000' is out of range | expected 1 to 64",
            "MaxDepth -1        | 'MaxDepth -1' is out of range | expected 0 to 1000",
            "MaxDepth 100000    | 'MaxDepth 100000' is out of range | expected 0 to 1000",
            "Sampler halton     | 'Sampler halton' names no sampler | expected one of grid, jittered, sobol, adaptive",
            "Sampler Sobol      | did you mean 'sobol'?         | expected one of grid, jittered, sobol, adaptive",
            "Sampler            | 'Sampler' needs a value       | expected 'Sampler <name>'",
            "TargetError -1     | 'TargetError -1' is out of range | expected 0 to 255 8-bit steps",
            "TargetError 1e9    | 'TargetError 1e9' is out of range | expected 0 to 255 8-bit steps",
            "TargetError half   | 'half' is not a number for TargetError | expected a decimal number",
            "Width 4.5          | '4.5' is not a whole number   | Width",
            "Width              | 'Width' needs a value         | expected 'Width <pixels>'"})
        void globalOutOfRangeGivesTheLimits(String line, String found, String expected) {
            assertError(line + "\n" + BASE, 1, found, expected);   // fails at line 1, before any later line counts
        }

        /** A size within the per-side limits that no heap could hold is refused, without advising a heap. */
        @Test
        void imageTooLargeForAnyHeapNamesTheArrayLimit() {
            SceneFormatException e = assertError("Width 65536\nHeight 65536\n\nCamera Camera\n", 1,
                    "4,294,967,296 pixels", "at most", String.format("%,d", Limits.MAX_ARRAY_PIXELS), "whatever the heap");
            assertFalse(e.getMessage().contains("-Xmx"), "no heap would help: " + e.getMessage());
        }

        /** Too large for this heap but not for a larger one: the advised -Xmx is one that admits the image. */
        @Test
        void imageTooLargeForThisHeapAdvisesAHeapThatWouldDo() {
            long pixels = 20000L * 20000;
            assumeTrue(pixels > Limits.maxPixels() && pixels <= Limits.MAX_ARRAY_PIXELS, "needs a heap under 25 GiB");
            SceneFormatException e = assertError("Width 20000\nHeight 20000\n\nCamera Camera\n", 1,
                    "400,000,000 pixels", "at most", "-Xmx" + Limits.heapGigabytesFor(pixels) + "g");
            long admitted = (Limits.heapGigabytesFor(pixels) << 30) / 2 / Limits.BYTES_PER_PIXEL;
            assertTrue(admitted >= pixels, "the advised heap admits the image: " + admitted);
            assertTrue(((Limits.heapGigabytesFor(pixels) - 1) << 30) / 2 / Limits.BYTES_PER_PIXEL < pixels * 17 / 16,
                    "and is not much more than needed");
        }

        @Test
        void parameterLineAfterABlankLineIsOutsideTheObject() {
            assertError(BASE + "Surface Sphere\n\ndouble radius 1\n", NEXT + 2, "parameter line outside an object", "no blank line");
        }

        @Test
        void unknownKeywordHintsAtCase() {
            assertError(BASE + "surface Sphere\n", NEXT, "unknown keyword 'surface'", "did you mean 'Surface'", "Camera, Surface, Material, Light");
            assertError("width 4\n", 1, "unknown keyword 'width'", "did you mean 'Width'");
        }

        @Test
        void classNamesAreCaseSensitive() {
            assertError(BASE + "Surface sphere\n", NEXT, "unknown Surface class 'sphere'", "did you mean 'Sphere'");
        }

        @Test
        void headerWithoutClassName() {
            assertError(BASE + "Surface\n", NEXT, "'Surface' needs a class name", "expected 'Surface <ClassName> [name]'");
        }

        @Test
        void headerWithTooManyWords() {
            assertError(BASE + "Surface Sphere a b\n", NEXT, "too many words", "'Surface Sphere a b'", "expected 'Surface <ClassName> [name]'");
        }

        @Test
        void emptyFile() {
            assertError("", 1, "empty scene file", "expected");
        }

        @Test
        void fileOfCommentsAndBlanksIsEmpty() {
            assertError("# nothing\n\n   \n# here\n", 4, "empty scene file");
        }

        @Test
        void controlCharactersAreShownEscapedAndNeverBreakTheLine() {
            SceneFormatException e = assertError(BASE + "Surface Sph\u001bere\n", NEXT, "control character");
            assertFalse(e.getMessage().chars().anyMatch(c -> c < 0x20), e.getMessage());
        }

        @Test
        void longValuesAreShortenedInMessages() {
            String junk = "x".repeat(5000);
            SceneFormatException e = assertError(BASE + sphere("double radius " + junk), NEXT + 1, "is not a number");
            assertTrue(e.getMessage().length() < 400, () -> e.getMessage().length() + " characters");
        }
    }

    // ---- input that is not a scene at all ----

    @Nested
    class Input {

        @Test
        void binaryFileWithNulByte() {
            byte[] png = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(png, "t.txt", new ArrayList<>()));
            // \r\n ends line 1, \n ends line 2: the first NUL is on line 3
            assertLocated(e, "t.txt", 3, "binary data (byte 0x00)", "expected a text scene file");
        }

        @Test
        void nulByteIsReportedOnItsLine() {
            byte[] b = (BASE + "Surface Sph\0ere\n").getBytes(StandardCharsets.UTF_8);
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(b, "t.txt", new ArrayList<>()));
            assertLocated(e, "t.txt", NEXT, "binary", "0x00");
        }

        @Test
        void invalidUtf8IsReportedOnItsLine() {
            byte[] b = (BASE + "# caf\u00e9\n").getBytes(StandardCharsets.ISO_8859_1);
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(b, "t.txt", new ArrayList<>()));
            assertLocated(e, "t.txt", NEXT, "not UTF-8", "expected");
        }

        @Test
        void utf16FileIsRecognised() {
            byte[] b = ("\ufeff" + BASE).getBytes(StandardCharsets.UTF_16LE);
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(b, "t.txt", new ArrayList<>()));
            assertLocated(e, "t.txt", 1, "UTF-16", "UTF-8");
        }

        @Test
        void utf8ByteOrderMarkAndCrLfAreAccepted() throws Exception {
            byte[] b = ("\ufeff" + BASE + sphere("double radius 2")).replace("\n", "\r\n").getBytes(StandardCharsets.UTF_8);
            Scene s = Parser.parse(b, "t.txt", new ArrayList<>());
            assertEquals(2.0, ((Sphere) s.surfaces.get(0)).radius);
        }

        @Test
        void fiftyMegabyteSingleLineIsRefusedQuickly(@TempDir Path dir) throws IOException {
            Path f = dir.resolve("huge.txt");
            try (Writer w = Files.newBufferedWriter(f)) {
                char[] chunk = new char[1 << 20];
                java.util.Arrays.fill(chunk, '9');
                w.write("Width ");
                for (int i = 0; i < 50; i++) {
                    w.write(chunk);
                }
            }
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(f, new ArrayList<>()));
            assertLocated(e, f.toString(), 1, "line is longer than 65,536 characters", "expected");
        }

        @Test
        void longLineInTextIsRefusedToo() {
            assertError("Width 4\n# " + "#".repeat(Limits.MAX_LINE) + "\n", 2, "line is longer than 65,536 characters");
        }

        @Test
        void missingFile(@TempDir Path dir) {
            Path f = dir.resolve("nope.txt");
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(f, new ArrayList<>()));
            assertEquals(f + ": cannot read the scene: no such file", e.getMessage());
        }

        @Test
        void directoryInsteadOfAFile(@TempDir Path dir) {
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(dir, new ArrayList<>()));
            assertEquals(dir + ": cannot read the scene: it is a directory (expected a scene file)", e.getMessage());
        }

        @Test
        void endlessDeviceIsRefusedWithoutReadingItAll() {
            Path zero = Paths.get("/dev/zero");
            assumeTrue(Files.exists(zero));
            SceneFormatException e = assertThrows(SceneFormatException.class, () -> Parser.parse(zero, new ArrayList<>()));
            // refused before it is opened, in every mode (--plan, --study and the viewer read through here too)
            assertEquals("/dev/zero: cannot read the scene: not a regular file (a character device); to read a scene from a pipe "
                    + "give '-' and send it to standard input", e.getMessage());
        }
    }

    // ---- built-in classes: every contract field set and read back ----

    @Nested
    class BuiltIns {

        @Test
        void camera() throws Exception {
            Camera c = parse("Width 4\nHeight 3\n\nCamera Camera\nVector3d eye [1 2 3]\nVector3d target [4 5 7]\n"
                    + "Vector3d up [0 0 1]\ndouble yFOV 30\ndouble aspect 2.5\n").camera;
            assertEquals(new Vector3d(1, 2, 3), c.eye);
            assertEquals(new Vector3d(4, 5, 7), c.target);
            assertEquals(new Vector3d(0, 0, 1), c.up);
            assertEquals(30.0, c.yFOV);
            assertEquals(2.5, c.aspect);
        }

        @Test
        void diffuse() throws Exception {
            Diffuse d = (Diffuse) parse(BASE + "Material Diffuse d\nVector3d ambientColor [0.1 0.2 0.3]\n"
                    + "Vector3d diffuseColor [0.4 0.5 0.6]\n").materials.get(1);
            assertSame(Diffuse.class, d.getClass());
            assertEquals(new Vector3d(0.1, 0.2, 0.3), d.ambientColor);
            assertEquals(new Vector3d(0.4, 0.5, 0.6), d.diffuseColor);
        }

        @Test
        void blinnPhong() throws Exception {
            BlinnPhong b = (BlinnPhong) parse(BASE + "Material BlinnPhong b\nVector3d ambientColor [0.1 0.2 0.3]\n"
                    + "Vector3d diffuseColor [0.4 0.5 0.6]\nVector3d specularColor [0.7 0.8 0.9]\ndouble exponent 42\n").materials.get(1);
            assertEquals(new Vector3d(0.1, 0.2, 0.3), b.ambientColor);
            assertEquals(new Vector3d(0.4, 0.5, 0.6), b.diffuseColor);
            assertEquals(new Vector3d(0.7, 0.8, 0.9), b.specularColor);
            assertEquals(42.0, b.exponent);
        }

        @Test
        void glazedMaterial() throws Exception {
            Scene s = parse(BASE + "Material GlazedMaterial g\nref base red\ndouble mirrorCoefficient 0.8\n");
            GlazedMaterial g = (GlazedMaterial) s.materials.get(1);
            assertSame(s.materials.get(0), g.base);
            assertEquals(0.8, g.mirrorCoefficient);
        }

        @Test
        void sphere() throws Exception {
            Scene s = parse(BASE + "Surface Sphere\nVector3d center [1 -2 3]\ndouble radius 0.5\nref material red\n");
            Sphere sp = (Sphere) s.surfaces.get(0);
            assertEquals(new Vector3d(1, -2, 3), sp.center);
            assertEquals(0.5, sp.radius);
            assertSame(s.materials.get(0), sp.material);
        }

        @Test
        void triangle() throws Exception {
            Scene s = parse(BASE + "Surface Triangle\nVector3d v0 [1 0 0]\nVector3d v1 [0 1 0]\nVector3d v2 [0 0 1]\nref material red\n");
            Triangle t = (Triangle) s.surfaces.get(0);
            assertEquals(new Vector3d(1, 0, 0), t.v0);
            assertEquals(new Vector3d(0, 1, 0), t.v1);
            assertEquals(new Vector3d(0, 0, 1), t.v2);
            assertSame(s.materials.get(0), t.material);
        }

        @Test
        void pointLight() throws Exception {
            PointLight p = (PointLight) parse(BASE + "Light PointLight\nVector3d position [5 6 7]\nVector3d intensity [20 30 40]\n").lights.get(0);
            assertEquals(new Vector3d(5, 6, 7), p.position);
            assertEquals(new Vector3d(20, 30, 40), p.intensity);
        }

        @Test
        void globals() throws Exception {
            Scene s = parse("BGColor [0.1 0.2 0.3]\nAmbientLight [0.4 0.5 0.6]\nWidth 7\nHeight 5\nAASamples 3\nMaxDepth 2\n\nCamera Camera\n");
            assertEquals(new Vector3d(0.1, 0.2, 0.3), s.backgroundColor);
            assertEquals(new Vector3d(0.4, 0.5, 0.6), s.ambientLight);
            assertEquals(7, s.width);
            assertEquals(5, s.height);
            assertEquals(3, s.samplesPerPixel);
            assertEquals(2, s.maxDepth);
            assertEquals("grid", s.sampler, "the default sampler");
            Scene t = parse("Width 7\nHeight 5\nSampler adaptive\nTargetError 0.25\n\nCamera Camera\n");
            assertEquals("adaptive", t.sampler);
            assertEquals(0.25, t.targetError);
        }
    }

    // ---- the format's rules ----

    @Nested
    class Rules {

        @Test
        void defaults() throws Exception {
            Scene s = parse("Width 640\nHeight 480\n\nCamera Camera\n");
            assertEquals(640.0 / 480.0, s.camera.aspect, 1e-15);
            assertEquals(1, s.samplesPerPixel);
            assertEquals(10, s.maxDepth);
            assertEquals(new Vector3d(), s.backgroundColor);
            assertEquals(new Vector3d(), s.ambientLight);
        }

        @Test
        void commentsOnTheirOwnLineAndTrailing() throws Exception {
            Scene s = parse("# a scene\nWidth 4 # pixels\nHeight 3\n\nCamera Camera\n# still the camera: a comment line does not end an object\n"
                    + "double yFOV 30 # degrees\n\nMaterial Diffuse red\n\n" + sphere("   # indented comment", "double radius 2 #a comment"));
            assertEquals(30.0, s.camera.yFOV);
            assertEquals(4, s.width);
            assertEquals(1, s.surfaces.size());
        }

        @Test
        void hashInsideAWordIsNotAComment() {
            assertError(BASE + sphere("double radius 2#3"), NEXT + 1, "'2#3' is not a number");
        }

        @Test
        void globalsAnywhereOutsideObjects() throws Exception {
            Scene s = parse("Camera Camera\n\nMaterial Diffuse red\nWidth 8\n" + sphere() + "\nHeight 2\nAASamples 2\n");
            assertEquals(8, s.width);
            assertEquals(2, s.height);
            assertEquals(2, s.samplesPerPixel);
            assertEquals(1, s.surfaces.size());
            assertEquals(4.0, s.camera.aspect);
        }

        @Test
        void headerRightAfterAnObjectStartsTheNextOne() throws Exception {
            Scene s = parse("Width 4\nHeight 3\nCamera Camera\ndouble yFOV 50\nMaterial Diffuse red\n"
                    + "Surface Sphere\ndouble radius 2\nref material red\nSurface Sphere\nref material red\nLight PointLight\n");
            assertEquals(50.0, s.camera.yFOV);
            assertEquals(2, s.surfaces.size());
            assertEquals(2.0, ((Sphere) s.surfaces.get(0)).radius);
            assertEquals(1.0, ((Sphere) s.surfaces.get(1)).radius);
            assertEquals(1, s.lights.size());
        }

        @Test
        void vectorsMayUseCommasAndExtraSpace() throws Exception {
            Scene s = parse(BASE + sphere("Vector3d center [ 1, 2 ,3 ]"));
            assertEquals(new Vector3d(1, 2, 3), ((Sphere) s.surfaces.get(0)).center);
        }

        @Test
        void zeroAreaTrianglesGiveOneAggregatedWarning() throws Exception {
            List<String> warnings = new ArrayList<>();
            String flat = "Surface Triangle\nVector3d v0 [0 0 0]\nVector3d v1 [1 1 1]\nVector3d v2 [2 2 2]\nref material red\n\n";
            String point = "Surface Triangle\nVector3d v0 [1 1 1]\nVector3d v1 [1 1 1]\nVector3d v2 [1 1 1]\nref material red\n\n";
            Parser.parse(BASE + sphere() + "\n" + flat + point + flat, "t.txt", warnings);
            assertEquals(List.of("t.txt:11: warning: zero-area triangle, never hit (and 2 more)"), warnings);
        }

        @Test
        void noWarningsForAGoodScene() throws Exception {
            List<String> warnings = new ArrayList<>();
            Parser.parse(BASE + "Surface Triangle\nref material red\n", "t.txt", warnings);
            assertEquals(List.of(), warnings);
        }

        @Test
        void objectsInFileOrder() throws Exception {
            Scene s = parse(BASE + "Material Diffuse a\n\nMaterial BlinnPhong b\n\n" + sphere("double radius 1") + "\n" + sphere("double radius 2"));
            assertEquals(3, s.materials.size());
            assertInstanceOf(BlinnPhong.class, s.materials.get(2));
            assertEquals(1.0, ((Sphere) s.surfaces.get(0)).radius);
            assertEquals(2.0, ((Sphere) s.surfaces.get(1)).radius);
        }
    }
}
