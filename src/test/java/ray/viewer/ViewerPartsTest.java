package ray.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.UUID;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The viewer's small pure parts: zoom steps, status texts, the file watch, recent files. */
class ViewerPartsTest {

    @Test
    void fitShrinksButStartsNoLargerThanOneToOne() {
        Zoom z = new Zoom();
        assertEquals(0.5, z.scale(800, 600, 400, 600));
        assertEquals(1.0, z.scale(100, 100, 400, 600), "a small image is shown 1:1 at first");
        z.fitToView();
        assertEquals(4.0, z.scale(100, 100, 400, 600), "Zoom to fit enlarges a small image");
    }

    @Test
    void zoomStepsPassThroughOneToOne() {
        Zoom z = new Zoom();
        z.in(0.6);
        assertEquals(Math.sqrt(0.5), z.scale(1, 1, 1, 1), 1e-12);
        z.in(z.scale(1, 1, 1, 1));
        assertEquals(1.0, z.scale(1, 1, 1, 1));
        z.in(1.0);
        z.out(z.scale(1, 1, 1, 1));
        assertEquals(1.0, z.scale(1, 1, 1, 1), "in then out returns to 1:1 exactly");
        z.in(Zoom.MAX);
        assertEquals(Zoom.MAX, z.scale(1, 1, 1, 1), "never beyond the largest step");
        z.out(Zoom.MIN);
        assertEquals(Zoom.MIN, z.scale(1, 1, 1, 1));
        z.actualSize();
        assertFalse(z.fit());
        assertEquals(1.0, z.scale(5000, 5000, 10, 10));
    }

    @Test
    void secondsReadWell() {
        assertEquals("0.42 s", StatusText.seconds(420_000_000L));
        assertEquals("12.3 s", StatusText.seconds(12_340_000_000L));
        assertEquals("2 min 05 s", StatusText.seconds(125_000_000_000L));
        assertEquals("99%", StatusText.percent(0.999));
    }

    @Test
    void watchSeesEachChangeOnce(@TempDir Path dir) throws IOException {
        Path f = Files.writeString(dir.resolve("s.txt"), "a");
        FileWatch w = new FileWatch();
        assertFalse(w.changed(), "nothing watched");
        w.watch(f);
        assertFalse(w.changed());
        Files.writeString(f, "ab");
        assertTrue(w.changed(), "size changed");
        assertFalse(w.changed(), "reported once");
        Files.setLastModifiedTime(f, FileTime.fromMillis(Files.getLastModifiedTime(f).toMillis() - 5000));
        assertTrue(w.changed(), "time changed, same size");
        Files.delete(f);
        assertTrue(w.changed(), "removed");
        Files.writeString(f, "xy");
        assertTrue(w.changed(), "back again");
    }

    @Test
    void recentFilesNewestFirstWithoutDuplicates(@TempDir Path dir) throws BackingStoreException, IOException {
        Preferences node = Preferences.userRoot().node("raytracer-test/" + UUID.randomUUID());
        try {
            RecentFiles r = new RecentFiles(node);
            for (int i = 0; i < RecentFiles.MAX + 3; i++) {
                r.add(Files.writeString(dir.resolve(i + ".txt"), ""));
            }
            r.add(dir.resolve("5.txt"));
            List<Path> l = new RecentFiles(node).list();          // read back as a new run would
            assertEquals(RecentFiles.MAX, l.size());
            assertEquals(dir.resolve("5.txt"), l.get(0));
            assertEquals(dir.resolve("10.txt"), l.get(1));
            assertEquals(1, l.stream().filter(p -> p.endsWith("5.txt")).count());
            r.remove(dir.resolve("5.txt"));
            assertEquals(dir.resolve("10.txt"), r.list().get(0));
        } finally {
            node.removeNode();
        }
    }
}
