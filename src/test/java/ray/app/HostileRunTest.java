package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Set;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.app.MainBadInputTest.Run;
import ray.material.Material;
import ray.material.Term;

/**
 * Issue 17 (the third round of hostile input), in-process: files never replaced unless asked (links
 * resolved before deciding, inputs, modes, read-only files, the study's folder), user code failing in
 * --plan and --study, options that would do nothing, statuses and streams.
 */
class HostileRunTest {

    @TempDir
    Path dir;

    static final String GOOD = MainBadInputTest.GOOD;

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.createDirectories(p.getParent());
        return Files.writeString(p, text);
    }

    static Run run(InputStream in, OutputStream outBytes, String... args) {
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(outBytes, true, StandardCharsets.UTF_8);
        int status = Main.run(in, out, new PrintStream(err, true, StandardCharsets.UTF_8), args);
        return new Run(status, outBytes.toString(), err.toString(StandardCharsets.UTF_8));
    }

    // ---- 1. files ----

    /** `ln -s notes.txt a.png; raytracer a.txt`: the link is resolved, notes.txt is no PNG and is kept. */
    @Test
    void aLinkedImageNameNeverReplacesTheFileItNames() throws IOException {
        Path scene = write("a.txt", GOOD), notes = write("notes.txt", "my notes\n"), other = write("b.txt", GOOD);
        Files.createSymbolicLink(dir.resolve("a.png"), notes);
        Run r = MainBadInputTest.run("-q", scene.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(dir.resolve("a.png") + ": cannot write the image: " + notes.toRealPath() + " (where " + dir.resolve("a.png")
                + " leads) is not a PNG image; it is left as it is (remove it, or name another file)"), r.errLines());
        assertEquals("my notes\n", Files.readString(notes));

        Files.delete(dir.resolve("a.png"));
        Files.createSymbolicLink(dir.resolve("a.png"), other);     // a link to another scene, not on the command line
        assertEquals(1, MainBadInputTest.run("-q", scene.toString()).status());
        assertEquals(GOOD, Files.readString(other));
        assertEquals(List.of("a.png", "a.txt", "b.txt", "notes.txt"), MainBadInputTest.names(dir));
    }

    /** `-o model.obj m.txt` where m.txt reads model.obj: the model stays. */
    @Test
    void aFileTheSceneReadsIsNeverTheImage() throws IOException {
        String obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
        write("model.obj", obj);
        Path scene = write("m.txt", GOOD + "\nMaterial Diffuse white\n\nSurface Mesh\nString file model.obj\nref material white\n");
        Run r = MainBadInputTest.run("-q", "-o", dir.resolve("model.obj").toString(), scene.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.err().startsWith(dir.resolve("model.obj") + ": cannot write the image: "), r.err());
        assertEquals(obj, Files.readString(dir.resolve("model.obj")));
        assertEquals(List.of("m.txt", "model.obj"), MainBadInputTest.names(dir));
    }

    /** Replacing a PNG keeps its mode; a read-only PNG is refused, its bytes kept. */
    @Test
    void replacingKeepsTheModeAndReadOnlyImagesAreKept() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("posix"));
        Path scene = write("a.txt", GOOD), png = dir.resolve("a.png");
        Files.write(png, MainBadInputTest.oldPng());
        Files.setPosixFilePermissions(png, PosixFilePermissions.fromString("rw-------"));
        assertEquals(0, MainBadInputTest.run("-q", scene.toString()).status());
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(png)));
        assertFalse(java.util.Arrays.equals(MainBadInputTest.oldPng(), Files.readAllBytes(png)), "replaced");

        Files.write(png, MainBadInputTest.oldPng());
        Files.setPosixFilePermissions(png, PosixFilePermissions.fromString("r--r--r--"));
        Run r = MainBadInputTest.run("-q", scene.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(png + ": cannot write the image: it is read-only (mode 444); it is left as it is "
                + "(make it writable, or name another file)"), r.errLines());
        assertArrayEquals(MainBadInputTest.oldPng(), Files.readAllBytes(png));
        assertEquals(List.of("a.png", "a.txt"), MainBadInputTest.names(dir));
    }

    // ---- 6. arguments that cannot be meant ----

    @Test
    void optionsThatWouldDoNothingAreRefused() throws IOException {
        Path s = write("s.txt", GOOD);
        String[][] cases = {
            {"--plan", "--view", s.toString()}, {"--quick", s.toString()}, {"--report-dir", "r", s.toString()},
            {"--full-size", s.toString()}, {"--stats", "--plan", s.toString()}, {"--plan", "--study", s.toString()},
            {"--plan", "-o", "x.png", s.toString()}, {"--plan", "--allow-long", s.toString()},
            {"--study", "--sampler", "sobol", s.toString()}, {"-o", "", s.toString()}, {""},
            {s.toString(), s.toString()}, {s.toString(), dir.resolve(".").resolve("s.txt").toString()},
            {"--plan", s.toString(), s.toString()}, {"--plan", "-", "-"},
        };
        for (String[] c : cases) {
            Run r = MainBadInputTest.run(c);
            assertEquals(2, r.status(), String.join(" ", c) + ": " + r.err());
            assertEquals(1, r.errLines().size(), String.join(" ", c) + ": " + r.err());
            assertTrue(r.err().startsWith("raytracer: "), r.err());
        }
        assertEquals("raytracer: the scene " + s + " is given twice; give each scene once",
                MainBadInputTest.run(s.toString(), s.toString()).errLines().get(0));
        assertEquals("raytracer: an empty scene name ('') (expected a scene file, or '-' for standard input)",
                MainBadInputTest.run("").errLines().get(0));
        assertEquals("raytracer: --quick goes with --study", MainBadInputTest.run("--quick", s.toString()).errLines().get(0));
        assertEquals(List.of("s.txt"), MainBadInputTest.names(dir), "nothing rendered");
    }

    /** -q prints nothing but errors: no warning either. */
    @Test
    void quietPrintsNoWarnings() throws IOException {
        Path s = write("s.txt", GOOD + "\nMaterial Diffuse d\n\nSurface Triangle\nVector3d v0 [0 0 0]\nVector3d v1 [1 0 0]\n"
                + "Vector3d v2 [2 0 0]\nref material d\n");
        assertTrue(MainBadInputTest.run(s.toString()).err().contains("warning: zero-area triangle"), "the warning exists");
        Run r = MainBadInputTest.run("-q", s.toString());
        assertEquals(0, r.status());
        assertEquals("", r.err());
    }

    /** Control characters in a file name never reach the terminal raw, in the summary line too. */
    @Test
    void theSummaryLineShowsNoRawControlCharacters() throws IOException {
        Path s = write("e\u001b[2Jx\ny.txt", GOOD);
        Run r = MainBadInputTest.run(s.toString());
        assertEquals(0, r.status(), r.err());
        assertFalse(r.out().contains("\u001b"), r.out());
        assertEquals(1, r.out().lines().count(), r.out());
    }

    /** A plan whose output is lost (>/dev/full, a closed pipe) is a failure, with JSON as with text. */
    @Test
    void lostStandardOutputIsAFailure() throws IOException {
        Path s = write("s.txt", GOOD);
        OutputStream full = new OutputStream() {
            @Override
            public void write(int b) throws IOException {
                throw new IOException("No space left on device");
            }
        };
        for (String[] args : new String[][] {{"--plan", "--json", s.toString()}, {"--plan", s.toString()},
                {"--stats", "--json", "-o", dir.resolve("x.png").toString(), s.toString()}}) {
            Run r = run(InputStream.nullInputStream(), full, args);
            assertEquals(1, r.status(), String.join(" ", args));
            assertEquals(List.of("raytracer: cannot write to standard output (closed, or the disk is full); its output is lost"),
                    r.errLines());
        }
        // the image itself lost: one line naming the scene (there were two, the second repeating the first)
        Run png = run(InputStream.nullInputStream(), full, "-q", "-o", "-", s.toString());
        assertEquals(1, png.status());
        assertEquals(List.of(s + ": cannot write the image to standard output (closed, or the disk is full); the image is lost"),
                png.errLines());
    }

    /**
     * A name whose bytes were not UTF-8 reaches Java with U+FFFD: refused in one line with the way round
     * it (it was "no such file" for a scene, and an image was written under a name nobody typed).
     */
    @Test
    void aNameThatIsNotUtf8IsRefusedWithTheWayRoundIt() throws IOException {
        Path s = write("s.txt", GOOD);
        String message = "raytracer: the name '%s' is not valid UTF-8 (a name in another encoding, e.g. Latin-1), and Java cannot "
                + "open a file by such a name: rename the file (e.g. convmv -f latin1 -t utf8), or give it by redirection: "
                + "raytracer - < NAME reads a scene, raytracer -o - scene.txt > NAME writes an image";
        String scene = dir.resolve("caf\uFFFD.txt").toString(), png = dir.resolve("x\uFFFD.png").toString();
        for (String[] args : new String[][] {{scene}, {"--plan", scene}, {"-o", png, s.toString()}}) {
            Run r = run(InputStream.nullInputStream(), new ByteArrayOutputStream(), args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(List.of(message.formatted(args[args.length - 1].equals(scene) ? scene.replace('\uFFFD', '?')
                    : png.replace('\uFFFD', '?'))), r.errLines());
        }
        assertEquals(List.of("s.txt"), MainBadInputTest.names(dir), "nothing written");
        Files.writeString(dir.resolve("caf\uFFFD.txt"), GOOD);     // a name typed with U+FFFD itself, in UTF-8: an ordinary scene
        assertEquals(0, run(InputStream.nullInputStream(), new ByteArrayOutputStream(), "-q", scene).status());
    }

    /** `--plan -` reads standard input (a file named '-' in the folder is not read). */
    @Test
    void planReadsStandardInput() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        Run r = run(new ByteArrayInputStream(GOOD.getBytes(StandardCharsets.UTF_8)), out, "--plan", "--json", "-");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("{") && r.out().contains("<stdin>"), r.out());
    }

    /** `yes 'Width 10' | raytracer -o x.png -`: refused at line 2 as it is read, not after reading everything. */
    @Test
    void standardInputIsCheckedLineByLine() {
        InputStream endless = new InputStream() {
            private final byte[] line = "Width 10\n".getBytes(StandardCharsets.US_ASCII);
            private long i;

            @Override
            public int read() {
                if (i > 1L << 31) {
                    throw new AssertionError("read 2 GB: the scene was read whole before it was checked");
                }
                return line[(int) (i++ % line.length)];
            }
        };
        Run r = run(endless, new ByteArrayOutputStream(), "-o", dir.resolve("x.png").toString(), "-");
        assertEquals(1, r.status());
        assertEquals(List.of("<stdin>:2: Width is set twice (first at line 1; expected each setting once)"), r.errLines());
    }

    // ---- 2. user code in --plan and --study ----

    /** terms() throwing an Error: the plan says so in one line and plans the next scene. */
    public static class TermsError extends Material {
        @Override
        public Set<Term> terms() {
            throw new AssertionError("terms not written yet");
        }

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return new Vector3d();
        }
    }

    /** Its getMessage() throws too. */
    public static class TermsBadMessage extends TermsError {
        @Override
        public Set<Term> terms() {
            throw new RuntimeException() {
                @Override
                public String getMessage() {
                    throw new IllegalStateException("no message");
                }
            };
        }
    }

    /** shade() asserting: the study reports the scene in one line and studies the others. */
    public static class ShadeAsserts extends TermsError {
        @Override
        public Set<Term> terms() {
            return java.util.EnumSet.allOf(Term.class);
        }

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            throw new AssertionError("shade not written yet");
        }
    }

    private Path userScene(String name, String material) throws IOException {
        return write(name, GOOD + "\nMaterial ray.app.HostileRunTest$" + material + " m\n\nSurface Sphere\nref material m\n");
    }

    @Test
    void planReportsAUserClassFailureInOneLineAndGoesOn() throws IOException {
        Path a = userScene("a.txt", "TermsError"), b = userScene("b.txt", "TermsBadMessage"), good = write("good.txt", GOOD);
        Run r = MainBadInputTest.run("--plan", a.toString(), b.toString(), good.toString());
        assertEquals(1, r.status());
        assertEquals(2, r.errLines().size(), r.err());
        assertTrue(r.errLines().get(0).startsWith(a + ": cannot plan the scene: AssertionError (terms not written yet) at "
                + "ray.app.HostileRunTest$TermsError.terms("), r.err());
        assertTrue(r.errLines().get(1).startsWith(b + ": cannot plan the scene: "), r.err());
        assertTrue(r.errLines().get(1).contains("its getMessage() threw IllegalStateException"), r.err());
        assertTrue(r.out().contains(good.toString()), "the next scene is planned: " + r.out());
    }

    @Test
    void studyReportsAUserClassFailureInOneLineAndGoesOn() throws IOException {
        Path a = userScene("a.txt", "ShadeAsserts"), good = write("good.txt", GOOD);
        Path report = dir.resolve("site");
        Run r = MainBadInputTest.run("--study", "--quick", "--report-dir", report.toString(), a.toString(), good.toString());
        assertEquals(1, r.status());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.errLines().get(0).startsWith(a + ": rendering failed: AssertionError (shade not written yet) at "), r.err());
        assertTrue(Files.exists(report.resolve("index.html")) && Files.exists(report.resolve("good.csv")), "the rest is studied");
    }

    // ---- 1. the study's report folder ----

    @Test
    void theStudyNeverClobbersWhatItDidNotWrite() throws IOException {
        Path s = write("x/s.txt", GOOD), t = write("y/s.txt", GOOD.replace("[1 0 0]", "[0 1 0]"));
        Path site = dir.resolve("site"), precious = write("precious.txt", "precious\n");
        Files.createDirectories(site);
        Path index = Files.writeString(site.resolve("index.html"), "my own page\n");
        Run r = MainBadInputTest.run("--study", "--quick", "--report-dir", site.toString(), s.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(site.resolve("index.html") + ": it exists and was not written by a study (it is not in .raytracer-study); "
                + "it is left as it is (remove it, or choose another --report-dir)"), r.errLines());
        assertEquals("my own page\n", Files.readString(index));
        Files.delete(index);

        Files.createSymbolicLink(site.resolve("s.csv"), Path.of("../precious.txt"));
        r = MainBadInputTest.run("--study", "--quick", "--report-dir", site.toString(), s.toString());
        assertEquals(1, r.status());
        assertTrue(r.err().startsWith(site.resolve("s.csv") + ": it is a symbolic link"), r.err());
        assertEquals("precious\n", Files.readString(precious));
        Files.delete(site.resolve("s.csv"));

        // two scenes of one name: two reports; then again: the study replaces what it wrote itself
        for (int run = 0; run < 2; run++) {
            r = MainBadInputTest.run("--study", "--quick", "--report-dir", site.toString(), s.toString(), t.toString());
            assertEquals(0, r.status(), r.err());
            assertEquals("", r.err());
        }
        assertTrue(Files.exists(site.resolve("s.csv")) && Files.exists(site.resolve("y-s.csv")), MainBadInputTest.names(site).toString());
        assertTrue(Files.readString(site.resolve("index.html")).contains("y-s"));
    }

    /** A user's bounds() returning null is blamed on that method, not on the BVH's build. */
    public static class NullBox extends ray.surface.Surface {
        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            return false;
        }

        @Override
        public ray.accel.Aabb bounds() {
            return null;
        }
    }

    @Test
    void aNullBoxIsBlamedOnBounds() throws IOException {
        Path s = write("n.txt", GOOD + "\nMaterial Diffuse d\n\nSurface ray.app.HostileRunTest$NullBox\nref material d\n");
        Run r = MainBadInputTest.run("-q", s.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(s + ": rendering failed: NullBox.bounds() returned null (expected a box around the surface, or not to "
                + "override bounds() for a surface without one)"), r.errLines());    // not "at ray.accel.Bvh.build(...)": the class is to blame
    }
}
