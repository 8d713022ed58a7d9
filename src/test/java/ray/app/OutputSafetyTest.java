package ray.app;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.app.MainBadInputTest.Run;

/**
 * Issue 11, classes 1, 3 (FIFO scene), 4 and 6: no output path, however it is spelled, replaces a scene
 * or anything that is not a regular file; an unwritable destination is reported before rendering,
 * naming the file asked for and the reason; temporary names stay short and stale ones are removed.
 */
class OutputSafetyTest {

    @TempDir
    Path dir;

    static final String GOOD = MainBadInputTest.GOOD;
    /** A scene whose (user-written) material throws when the render reaches it. */
    static final String THROWS_WHEN_RENDERED = GOOD + "\nMaterial ThrowingMaterial m\n\nSurface Sphere\nVector3d center [0 0 0]\nref material m\n";

    private static Run run(String... args) {
        return MainBadInputTest.run(args);
    }

    private Path write(String name, String text) throws IOException {
        Path p = dir.resolve(name);
        Files.createDirectories(p.getParent());
        Files.writeString(p, text);
        return p;
    }

    private static boolean exec(String... cmd) {
        try {
            return new ProcessBuilder(cmd).redirectErrorStream(true).start().waitFor() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    /** -o through a symbolic link to the scene's own folder names the scene itself: refused, scene intact. */
    @Test
    void outputThroughSymlinkedFolderOntoTheSceneIsRefused() throws IOException {
        Path scene = write("real/s.txt", GOOD);
        Path link = dir.resolve("link");
        Files.createSymbolicLink(link, dir.resolve("real"));
        Run r = run("-q", "-o", link.resolve("s.txt").toString(), scene.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(List.of(scene + ": the image " + link.resolve("s.txt") + " would replace the scene file itself"), r.errLines());
        assertEquals(GOOD, Files.readString(scene));
    }

    /** A hard link is the same file under another name. */
    @Test
    void outputOntoAHardLinkOfTheSceneIsRefused() throws IOException {
        Path scene = write("s.txt", GOOD);
        Path hard = dir.resolve("other.png");
        Files.createLink(hard, scene);
        Run r = run("-q", "-o", hard.toString(), scene.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.err().contains("would replace the scene file itself"), r.err());
        assertEquals(GOOD, Files.readString(scene));
    }

    /** raytracer a.txt a.png: a.txt's image would replace the scene a.png before it is read. */
    @Test
    void imageThatWouldReplaceAnotherSceneOnTheCommandLineIsRefused() throws IOException {
        Path a = write("a.txt", GOOD), other = write("a.png", GOOD);
        Run r = run("-q", a.toString(), other.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(List.of(a + ": the image " + other + " would replace the scene file " + other + " given on the same command line"),
                r.errLines());
        assertEquals(GOOD, Files.readString(other));
        assertTrue(Files.exists(dir.resolve("a.png.png")), "the second scene still renders");
    }

    /** Two scenes of the same name from two folders into one output folder: the second is refused. */
    @Test
    void twoScenesWritingOneImageInAFolderAreCaught() throws IOException {
        Path a = write("x/s.txt", GOOD), b = write("y/s.txt", GOOD);
        Path out = Files.createDirectory(dir.resolve("out"));
        Run r = run("-q", "-o", out.toString(), a.toString(), b.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(List.of(b + ": the image " + out.resolve("s.png") + " would replace the one just written for " + a), r.errLines());
    }

    /** -o FOLDER takes several scenes; a name ending in / is a folder even before it exists (then: no such folder). */
    @Test
    void outputFolderTakesSeveralScenes() throws IOException {
        Path a = write("a.txt", GOOD), b = write("sub/b.txt", GOOD);
        Path out = Files.createDirectory(dir.resolve("out"));
        Run r = run("-q", "-o", out.toString(), a.toString(), b.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals(List.of("a.png", "b.png"), MainBadInputTest.names(out));
        Run missing = run("-q", "-o", dir.resolve("nope") + "/", a.toString());
        assertEquals(1, missing.status());
        assertEquals(List.of(dir.resolve("nope/a.png") + ": cannot write the image: no such folder"), missing.errLines());
        assertFalse(Files.exists(dir.resolve("nope")), "a trailing / never turns into a file named like the folder");
    }

    /** -o onto a FIFO writes the PNG into it; the FIFO stays a FIFO. */
    @Test
    void outputOntoAFifoIsWrittenIntoNotReplaced() throws Exception {
        Path scene = write("a.txt", GOOD), fifo = dir.resolve("pipe");
        assumeTrue(exec("mkfifo", fifo.toString()), "mkfifo is needed");
        CompletableFuture<byte[]> reader = new CompletableFuture<>();
        Thread t = new Thread(() -> {
            try (InputStream in = Files.newInputStream(fifo)) {
                reader.complete(in.readAllBytes());
            } catch (IOException e) {
                reader.completeExceptionally(e);
            }
        });
        t.setDaemon(true);      // if the FIFO were replaced, this open would wait forever for a writer
        t.start();
        Run r = assertTimeoutPreemptively(Duration.ofSeconds(20), () -> run("-o", fifo.toString(), scene.toString()));
        assertEquals(0, r.status(), r.err());
        assertEquals(List.of(scene + ": writing the image into the FIFO " + fifo + " (waits until something reads it)"), r.errLines(),
                "says what it waits for");
        assertEquals("a FIFO", ray.io.OutputFile.kind(fifo), "still a FIFO");
        byte[] png = reader.get(20, java.util.concurrent.TimeUnit.SECONDS);
        assertEquals((byte) 0x89, png[0]);
        assertEquals('P', png[1]);
        assertFalse(Files.isRegularFile(fifo));
    }

    /** -o onto a character device (a private copy of /dev/null) writes into it; it stays a device. */
    @Test
    void outputOntoACharacterDeviceIsWrittenIntoNotReplaced() throws IOException {
        Path scene = write("a.txt", GOOD), dev = dir.resolve("null");
        assumeTrue(exec("mknod", dev.toString(), "c", "1", "3"), "mknod (root) is needed to make a device node");
        Run r = run("-q", "-o", dev.toString(), scene.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("a character device", ray.io.OutputFile.kind(dev));
    }

    /** A FIFO as the scene is refused at once, never waited on (there is no writer). */
    @Test
    void fifoAsTheSceneIsRefusedWithoutBlocking() throws IOException {
        Path fifo = dir.resolve("scene.txt");
        assumeTrue(exec("mkfifo", fifo.toString()), "mkfifo is needed");
        Run r = assertTimeoutPreemptively(Duration.ofSeconds(20), () -> run("-q", fifo.toString()));
        assertEquals(1, r.status());
        assertEquals(List.of(fifo + ": cannot read the scene: not a regular file (a FIFO); to read a scene from a pipe give '-' "
                + "and send it to standard input"), r.errLines());
        assertFalse(Files.exists(dir.resolve("scene.png")));
    }

    /** The folder is checked before the render: the message is about the output, not the scene's failing class. */
    @Test
    void missingOutputFolderIsReportedBeforeRendering() throws IOException {
        Path scene = write("a.txt", THROWS_WHEN_RENDERED);
        Path png = dir.resolve("no-such-folder/a.png");
        Run r = run("-q", "-o", png.toString(), scene.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(png + ": cannot write the image: no such folder"), r.errLines());
    }

    /** A folder the process may not write into: the reason is "permission denied". */
    @Test
    void unwritableOutputFolderIsReportedBeforeRendering() throws IOException {
        Path scene = write("a.txt", THROWS_WHEN_RENDERED);
        Path folder = Files.createDirectory(dir.resolve("locked"));
        boolean locked = folder.toFile().setWritable(false, false) && !Files.isWritable(folder);
        if (!locked) {           // root may write anywhere: /sys refuses new files even to root
            folder = Path.of("/sys");
            assumeTrue(Files.isDirectory(folder) && !exec("touch", "/sys/raytracer-probe"), "no folder this process cannot write");
        }
        Path png = folder.resolve("a.png");
        try {
            Run r = run("-q", "-o", png.toString(), scene.toString());
            assertEquals(1, r.status());
            assertEquals(List.of(png + ": cannot write the image: permission denied"), r.errLines());
        } finally {
            dir.resolve("locked").toFile().setWritable(true, false);
        }
    }

    /** A read-only file system (a tmpfs mounted read-only, where this test may mount one). */
    @Test
    void readOnlyFileSystemIsNamed() throws IOException {
        Path scene = write("a.txt", THROWS_WHEN_RENDERED);
        Path mnt = Files.createDirectory(dir.resolve("ro"));
        assumeTrue(exec("mount", "-t", "tmpfs", "-o", "ro,size=1m", "tmpfs", mnt.toString()), "mounting needs privileges");
        try {
            Path png = mnt.resolve("a.png");
            Run r = run("-q", "-o", png.toString(), scene.toString());
            assertEquals(1, r.status());
            assertEquals(List.of(png + ": cannot write the image: read-only file system"), r.errLines());
        } finally {
            exec("umount", mnt.toString());
        }
    }

    /** A legal 240-character scene name renders: the temporary name does not grow with it. */
    @Test
    void longestLegalNamesRender() throws IOException {
        String base = "s".repeat(240);
        Path scene = write(base + ".txt", GOOD);
        Run r = run("-q", scene.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.size(dir.resolve(base + ".png")) > 0);
        Path tooLong = dir.resolve("p".repeat(260) + ".png");
        Run r2 = run("-q", "-o", tooLong.toString(), scene.toString());
        assertEquals(1, r2.status());
        assertEquals(List.of(tooLong + ": cannot write the image: name too long (264 bytes, at most 255)"), r2.errLines());
    }

    /** A temporary file of a process that is gone (killed mid-write) is removed by the next write there. */
    @Test
    void staleTemporaryFilesOfDeadProcessesAreRemoved() throws Exception {
        Process p = new ProcessBuilder("true").start();
        long deadPid = p.pid();
        p.waitFor();
        assumeTrue(ProcessHandle.of(deadPid).isEmpty(), "the pid was reused at once");
        Path stale = write(".raytracer-" + deadPid + "-abc123.tmp", "half a PNG");
        Path live = write(".raytracer-" + ProcessHandle.current().pid() + "-def456.tmp", "being written");
        Path foreign = write(".raytracer-notes.tmp", "not ours");
        Path scene = write("a.txt", GOOD);
        Run r = run("-q", scene.toString());
        assertEquals(0, r.status(), r.err());
        assertFalse(Files.exists(stale, LinkOption.NOFOLLOW_LINKS), "stale temporary of a dead process removed");
        assertTrue(Files.exists(live), "a living process's temporary is kept");
        assertTrue(Files.exists(foreign), "a name not of our pattern is kept");
    }

    /** `-o other.txt scene.txt` (a slip of the fingers) never turns a text file into a PNG. */
    @Test
    void anExistingFileThatIsNotAPngIsNeverReplaced() throws IOException {
        Path scene = write("a.txt", GOOD), notes = write("notes.txt", "my notes\n"), empty = write("empty.txt", "");
        Run r = run("-q", "-o", notes.toString(), scene.toString());
        assertEquals(1, r.status());
        assertEquals(List.of(notes + ": cannot write the image: it is not a PNG image; it is left as it is (remove it, or name another file)"),
                r.errLines());
        assertEquals("my notes\n", Files.readString(notes));
        assertEquals(0, run("-q", "-o", empty.toString(), scene.toString()).status(), "an empty file may be replaced");
        assertEquals(0, run("-q", "-o", empty.toString(), scene.toString()).status(), "and then a PNG");
    }

    /** A scene named like an option, after --, is a scene (a name starting with @: CommandLineProcessTest). */
    @Test
    void dashNamesAfterDoubleDashAreScenes() throws IOException {
        Path dash = write("-d.txt", GOOD);
        Run d = run("-q", "--", dash.toString());
        assertEquals(0, d.status(), d.err());
        assertTrue(Files.size(dir.resolve("-d.png")) > 0);
    }

    /** A bad option: one line that points to --help, status 2. */
    @Test
    void badOptionIsOneLinePointingToHelp() {
        Run r = run("--no-such-option", "a.txt");
        assertEquals(2, r.status());
        assertEquals(List.of("raytracer: Unknown option: '--no-such-option' (see raytracer --help)"), r.errLines());
    }

    /** The scene in /dev (e.g. /dev/stdin redirected from a file) gets no PNG beside it in /dev. */
    @Test
    void sceneUnderDevWritesNothingThere() {
        Run r = run("-q", "/dev/null");
        assertEquals(1, r.status());
        assertEquals(1, r.errLines().size(), r.err());
        assertTrue(r.err().startsWith("/dev/null: "), r.err());
        assertFalse(Files.exists(Path.of("/dev/null.png")));
    }
}
