package ray.viewer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.render.Image;
import ray.render.PngEncoder;

/** Saving never loses a file: names, the replace question, the scene file, atomic writes, messages. */
class SaveRulesTest {

    @Test
    void suggestsThePngBesideTheScene(@TempDir Path dir) {
        assertEquals(dir.resolve("a.png"), SaveRules.suggestedTarget(dir.resolve("a.txt")));
        assertEquals(dir.resolve("B.png"), SaveRules.suggestedTarget(dir.resolve("B.TXT")));
        assertEquals(dir.resolve("scene.png"), SaveRules.suggestedTarget(dir.resolve("scene")));
        assertTrue(SaveRules.suggestedTarget(Path.of("rel.txt")).isAbsolute());
    }

    @Test
    void addsPngUnlessThere() {
        assertEquals(Path.of("d/x.png"), SaveRules.withPngExtension(Path.of("d/x")));
        assertEquals(Path.of("d/x.txt.png"), SaveRules.withPngExtension(Path.of("d/x.txt")));
        assertEquals(Path.of("d/x.PNG"), SaveRules.withPngExtension(Path.of("d/x.PNG")));
    }

    @Test
    void asksOnlyWhenAFileIsThere(@TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("s.txt"), "Width 1\n");
        assertEquals(SaveRules.Verdict.WRITE, SaveRules.check(dir.resolve("new.png"), scene));
        Path old = Files.writeString(dir.resolve("old.png"), "precious");
        assertEquals(SaveRules.Verdict.ASK_TO_REPLACE, SaveRules.check(old, scene));
    }

    @Test
    void neverTheSceneFileHoweverItIsSpelled(@TempDir Path dir) throws IOException {
        Path scene = Files.writeString(dir.resolve("s.txt"), "Width 1\n");
        Path link = Files.createSymbolicLink(dir.resolve("link.png"), scene);
        Path hard = Files.createLink(dir.resolve("hard.png"), scene);
        for (Path p : new Path[] {scene, dir.resolve(".").resolve("s.txt"), dir.resolve("sub/../s.txt"), link, hard}) {
            if (p.toString().contains("sub")) {
                Files.createDirectories(dir.resolve("sub"));
            }
            assertEquals(SaveRules.Verdict.REFUSE, SaveRules.check(p, scene), p.toString());
            SaveRules.SaveException e = assertThrows(SaveRules.SaveException.class, () -> SaveRules.save(new Image(2, 2), p, scene));
            assertTrue(e.getMessage().contains("is the scene file"), e.getMessage());
        }
        assertEquals("Width 1\n", Files.readString(scene), "the scene is untouched");
    }

    @Test
    void neverAFolder(@TempDir Path dir) throws IOException {
        Path folder = Files.createDirectory(dir.resolve("f.png"));
        assertEquals(SaveRules.Verdict.REFUSE, SaveRules.check(folder, null));
        assertTrue(Files.isDirectory(folder));
    }

    /** The save follows the command line's rules (ray.io.OutputFile): a file that is no PNG, or a read-only one, is kept. */
    @Test
    void aFileThatIsNoPngIsKeptEvenAfterAskingToReplace(@TempDir Path dir) throws IOException {
        Path notes = Files.writeString(dir.resolve("notes.txt"), "precious");
        Path link = Files.createSymbolicLink(dir.resolve("out.png"), notes);
        SaveRules.SaveException e = org.junit.jupiter.api.Assertions.assertThrows(SaveRules.SaveException.class,
                () -> SaveRules.save(new Image(3, 2), link, dir.resolve("s.txt")));
        assertEquals("Cannot save " + link + ": " + notes.toRealPath() + " (where " + link + " leads) is not a PNG image; it is left as it is "
                + "(remove it, or name another file)", e.getMessage());
        assertEquals("precious", Files.readString(notes));
    }

    @Test
    void writesTheShownImageAsTheCommandLineWould(@TempDir Path dir) throws IOException, SaveRules.SaveException {
        Image img = new Image(3, 2);
        img.set(0, 0, 1, 0.5, 0.25);
        img.set(2, 1, 0.1, 2.0, -1);
        Path old = Files.write(dir.resolve("out.png"), new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n', 1});
        SaveRules.save(img, old, dir.resolve("s.txt"));
        ByteArrayOutputStream expected = new ByteArrayOutputStream();
        PngEncoder.write(img, expected);
        assertArrayEquals(expected.toByteArray(), Files.readAllBytes(old));
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "no temporary file left beside it");
        }
    }

    @Test
    void failureNamesTheChosenFileAndTheReasonNotATemporaryFile(@TempDir Path dir) {
        Path target = dir.resolve("missing-folder").resolve("out.png");
        SaveRules.SaveException e = assertThrows(SaveRules.SaveException.class,
                () -> SaveRules.save(new Image(2, 2), target, dir.resolve("s.txt")));
        assertEquals("Cannot save " + target + ": no such folder", e.getMessage());
        assertFalse(e.getMessage().contains(".tmp"));
    }
}
