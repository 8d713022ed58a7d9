package ray.viewer;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.logging.Level;
import java.util.logging.Logger;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;

/**
 * The scenes opened last, newest first, at most {@value #MAX}, kept in the user's preferences
 * ({@link Preferences}, so they survive a restart) as absolute paths. Files that no longer exist are
 * left out of the list and dropped from the store ({@link #prune}). A preferences store that cannot
 * be written only means the list is not remembered, so the JDK's own log lines about its store ("Created
 * user preferences directory" on the first run, "Prefs file removed in background", a failed flush) are
 * silenced: they would be the viewer's only lines on stderr that a user did not cause.
 */
final class RecentFiles {

    static final int MAX = 8;
    /** Held here: java.util.logging keeps loggers weakly, and a collected logger loses its level. */
    private static final Logger STORE_LOG = Logger.getLogger("java.util.prefs");

    static {
        STORE_LOG.setLevel(Level.OFF);
    }

    private final Preferences node;

    RecentFiles(Preferences node) {
        this.node = node;
    }

    /** The viewer's own node in the user's preferences. */
    static RecentFiles user() {
        return new RecentFiles(Preferences.userRoot().node("raytracer/viewer/recent"));
    }

    /** The remembered files that still exist, newest first; the missing ones are dropped from the store. */
    List<Path> list() {
        List<Path> all = stored(), out = new ArrayList<>();
        for (Path p : all) {
            if (Files.isRegularFile(p)) {
                out.add(p);
            }
        }
        if (out.size() != all.size()) {
            store(out);
        }
        return out;
    }

    /** Drops the files that no longer exist; returns how many. */
    int prune() {
        int before = stored().size();
        return before - list().size();
    }

    private List<Path> stored() {
        List<Path> out = new ArrayList<>();
        for (int i = 0; i < MAX; i++) {
            String p = node.get(Integer.toString(i), null);
            if (p == null) {
                break;
            }
            try {
                out.add(Path.of(p));
            } catch (java.nio.file.InvalidPathException e) {
                // written by another platform: skip it
            }
        }
        return out;
    }

    /** Puts {@code file} first (once), dropping the oldest beyond {@value #MAX}. */
    void add(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        List<Path> l = stored();
        l.remove(abs);
        l.add(0, abs);
        store(l);
    }

    void remove(Path file) {
        List<Path> l = list();
        l.remove(file.toAbsolutePath().normalize());
        store(l);
    }

    private void store(List<Path> l) {
        for (int i = 0; i < MAX; i++) {
            if (i < l.size()) {
                node.put(Integer.toString(i), l.get(i).toString());
            } else {
                node.remove(Integer.toString(i));
            }
        }
        try {
            node.flush();
        } catch (BackingStoreException | SecurityException e) {
            // not remembered across restarts; the list still works in this run
        }
    }
}
