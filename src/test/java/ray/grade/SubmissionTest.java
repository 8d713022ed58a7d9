package ray.grade;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.zip.ZipEntry;
import java.util.zip.ZipOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading a hand-in: its .java files by file name, everything else left out with a note, nothing written. */
class SubmissionTest {

    @TempDir
    Path dir;

    @Test
    void aZipGivesItsJavaFilesByNameAndNotesTheRest() throws IOException {
        Path zip = dir.resolve("alice smith.zip");
        try (ZipOutputStream z = new ZipOutputStream(Files.newOutputStream(zip))) {
            put(z, "project/src/Sphere.java", "class Sphere {}");
            put(z, "../../escape/Triangle.java", "class Triangle {}");       // a path that climbs out: only the name counts
            put(z, "__MACOSX/project/._Sphere.java", "junk");
            put(z, "project/other/Sphere.java", "class Sphere { int second; }");
            put(z, "notes.txt", "hello");
            put(z, "project/bin/Sphere.class", "\u00ca\u00fe");
            put(z, "project/My-Class.java", "x");
        }
        Submission s = Submission.read(zip);
        assertEquals("alice_smith", s.name());
        assertEquals(Set.of("Sphere.java", "Triangle.java"), s.files().keySet());
        assertEquals("class Sphere {}", new String(s.files().get("Sphere.java"), StandardCharsets.UTF_8));
        String notes = String.join("\n", s.notes());
        assertTrue(notes.contains("project/other/Sphere.java: a second Sphere.java"), notes);
        assertTrue(notes.contains("notes.txt: not a .java file"), notes);
        assertTrue(notes.contains("My-Class.java: not a Java class file name"), notes);
        assertTrue(!Files.exists(dir.resolve("escape")) && !Files.exists(dir.getParent().resolve("escape")));
    }

    @Test
    void aFolderAndItsName() throws IOException {
        Path d = Files.createDirectories(dir.resolve("+cmd=HYPERLINK(1)"));
        Files.writeString(d.resolve("Scene.java"), "class Scene {}");
        Submission s = Submission.read(d);
        assertEquals("_+cmd_HYPERLINK_1_", s.name(), "a name a spreadsheet would run as a formula gets a prefix");
        assertEquals(Set.of("Scene.java"), s.files().keySet());
    }

    @Test
    void oversizedHandInsAreCut() throws IOException {
        Path d = Files.createDirectories(dir.resolve("big"));
        byte[] mb = new byte[3 << 20];
        Files.write(d.resolve("A.java"), mb);
        Files.write(d.resolve("B.java"), mb);
        Submission s = Submission.read(d);
        assertEquals(Set.of("A.java"), s.files().keySet());
        assertTrue(s.notes().get(0).contains("exceed 4 MB"), s.notes().toString());
    }

    @Test
    void anythingElseIsRefused() throws IOException {
        Path f = Files.writeString(dir.resolve("x.tar"), "x");
        assertThrows(IOException.class, () -> Submission.read(f));
        Path bad = Files.writeString(dir.resolve("bad.zip"), "not a zip");
        Submission s = Submission.read(bad);   // a zip stream over junk reads as empty
        assertTrue(s.files().isEmpty());
    }

    static void put(ZipOutputStream z, String name, String text) throws IOException {
        z.putNextEntry(new ZipEntry(name));
        OutputStream o = z;
        o.write(text.getBytes(StandardCharsets.ISO_8859_1));
        z.closeEntry();
    }
}
