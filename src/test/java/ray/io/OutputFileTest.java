package ray.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The rules every written file follows ({@link OutputFile}): links resolved before deciding, only an
 * accepted file replaced, read-only files and inputs kept, modes kept, a vanished temporary file named.
 */
class OutputFileTest {

    @TempDir
    Path dir;

    static final OutputFile.Body BYTES = out -> out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 1, 2});

    private static String text(Path p) throws IOException {
        return Files.readString(p, StandardCharsets.UTF_8);
    }

    private List<String> leftovers() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.startsWith(".raytracer-")).toList();
        }
    }

    /** The temporary files' pid (read from /proc/self where there is one) is this process's. */
    @Test
    void pidIsThisProcesssId() {
        assertEquals(ProcessHandle.current().pid(), OutputFile.pid());
        assertEquals(OutputFile.pid(), OutputFile.pid());
    }

    /** `ln -s notes.txt a.png`: the link is resolved, and notes.txt, not being a PNG, is kept. */
    @Test
    void aLinkToATextFileIsJudgedAsThatFileAndKept() throws IOException {
        Path notes = Files.writeString(dir.resolve("notes.txt"), "my notes\n");
        Path link = Files.createSymbolicLink(dir.resolve("a.png"), Path.of("notes.txt"));
        IOException e = assertThrows(IOException.class, () -> OutputFile.write(link, OutputFile.Guard.PNG, BYTES));
        assertEquals(notes.toRealPath() + " (where " + link + " leads) is not a PNG image; it is left as it is (remove it, or name another file)",
                e.getMessage());
        assertEquals("my notes\n", text(notes));
        assertTrue(Files.isSymbolicLink(link));
        assertEquals(List.of(), leftovers());
    }

    /** A PNG behind a link is replaced (the file the link names), an empty file too, a non-PNG of any extension not. */
    @Test
    void onlyAnEmptyFileOrAPngIsReplaced() throws IOException {
        Path png = dir.resolve("old.png");
        OutputFile.write(png, OutputFile.Guard.PNG, BYTES);
        Path link = Files.createSymbolicLink(dir.resolve("l.png"), png);
        OutputFile.write(link, OutputFile.Guard.PNG, BYTES);
        assertTrue(Files.isSymbolicLink(link), "the link stays, its file is replaced");
        Path empty = Files.createFile(dir.resolve("empty.png"));
        OutputFile.write(empty, OutputFile.Guard.PNG, BYTES);
        assertEquals(10, Files.size(empty));
        Path jpeg = Files.write(dir.resolve("photo.png"), new byte[] {(byte) 0xFF, (byte) 0xD8, (byte) 0xFF});
        IOException e = assertThrows(IOException.class, () -> OutputFile.write(jpeg, OutputFile.Guard.PNG, BYTES));
        assertEquals("it is not a PNG image; it is left as it is (remove it, or name another file)", e.getMessage());
        assertEquals(3, Files.size(jpeg));
    }

    /** Replacing keeps the old file's mode (600 stays 600); a read-only file (444) is refused, even where the rename would work. */
    @Test
    void modesAreKeptAndReadOnlyFilesRefused() throws IOException {
        assumeTrue(Files.getFileStore(dir).supportsFileAttributeView("posix"));
        Path png = dir.resolve("private.png");
        OutputFile.write(png, OutputFile.Guard.PNG, BYTES);
        Files.setPosixFilePermissions(png, PosixFilePermissions.fromString("rw-------"));
        OutputFile.write(png, OutputFile.Guard.PNG, out -> out.write(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 7}));
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(png)));
        assertEquals(9, Files.size(png), "replaced");

        Files.setPosixFilePermissions(png, PosixFilePermissions.fromString("r--r--r--"));
        IOException e = assertThrows(IOException.class, () -> OutputFile.write(png, OutputFile.Guard.PNG, BYTES));
        assertEquals("it is read-only (mode 444); it is left as it is (make it writable, or name another file)", e.getMessage());
        assertEquals(9, Files.size(png), "kept");
        assertEquals(List.of(), leftovers());
    }

    /** A file the work reads is never replaced, spelled however (a link, another path). */
    @Test
    void anInputIsNeverReplaced() throws IOException {
        Path model = Files.createFile(dir.resolve("model.obj"));    // empty: the PNG rule alone would allow it
        OutputFile.Pending p = OutputFile.prepare(dir.resolve("model.obj"), OutputFile.Guard.PNG);
        try {
            Path link = Files.createSymbolicLink(dir.resolve("link.obj"), model);
            IOException e = assertThrows(IOException.class, () -> p.protect(List.of(dir.resolve("x.obj"), link)));
            assertEquals("it is " + link + ", a file the scene reads; it is left as it is (name another file)", e.getMessage());
        } finally {
            p.abandon();
        }
        assertEquals(0, Files.size(model));
        assertEquals(List.of(), leftovers());
    }

    /** The temporary file removed while the work runs: said so, not "no such folder". */
    @Test
    void aVanishedTemporaryFileIsNamedAsSuch() throws IOException {
        Path png = dir.resolve("a.png");
        OutputFile.Pending p = OutputFile.prepare(png, OutputFile.Guard.PNG);
        try {
            for (String n : leftovers()) {
                Files.delete(dir.resolve(n));
            }
            IOException e = assertThrows(IOException.class, () -> p.commit(BYTES));
            assertTrue(e.getMessage().matches("the temporary file \\.raytracer-\\d+-[0-9a-z]+\\.tmp was removed while the work ran "
                    + "\\(by another program\\?\\); nothing was written"), e.getMessage());
        } finally {
            p.abandon();
        }
        assertFalse(Files.exists(png));
    }

    /** With noLinks (the study's report folder), a link at the target is refused, not followed. */
    @Test
    void noLinksRefusesALink() throws IOException {
        Path precious = Files.writeString(dir.resolve("precious.txt"), "keep");
        Path link = Files.createSymbolicLink(dir.resolve("s.csv"), precious);
        OutputFile.Guard any = new OutputFile.Guard() {
            @Override
            public String mayReplace(Path real) {
                return null;
            }

            @Override
            public boolean noLinks() {
                return true;
            }
        };
        IOException e = assertThrows(IOException.class, () -> OutputFile.write(link, any, BYTES));
        assertEquals("it is a symbolic link (to " + precious + "); it is not followed and is left as it is (remove it)", e.getMessage());
        assertEquals("keep", text(precious));
    }
}
