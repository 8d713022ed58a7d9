package ray.io;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.WeakHashMap;

/**
 * The files a piece of work reads, so that nothing the program writes can replace one of them
 * ({@link OutputFile.Pending#protect}). Reading a scene records the scene file and every file its
 * objects read (a Mesh's OBJ file): the reader calls {@link #read} on the thread that parses, between
 * {@link #begin} and {@link #end}, and the list is then kept with the scene ({@link #of}).
 */
public final class InputFiles {

    private static final ThreadLocal<List<Path>> RECORDING = new ThreadLocal<>();
    private static final Map<Object, List<Path>> BY_WORK = Collections.synchronizedMap(new WeakHashMap<>());

    private InputFiles() {
    }

    /** Starts recording on this thread; returns what was being recorded before (for {@link #end}). */
    public static List<Path> begin() {
        List<Path> outer = RECORDING.get();
        RECORDING.set(new ArrayList<>());
        return outer;
    }

    /** Records that {@code file} is read by the work being recorded on this thread (if any). */
    public static void read(Path file) {
        List<Path> r = RECORDING.get();
        if (r != null) {
            r.add(file);
        }
    }

    /** Stops recording, keeps the files with {@code work} (when not null) and restores {@code outer}. */
    public static List<Path> end(Object work, List<Path> outer) {
        List<Path> r = RECORDING.get();
        List<Path> files = r == null ? List.of() : List.copyOf(r);
        if (outer == null) {
            RECORDING.remove();
        } else {
            RECORDING.set(outer);
            outer.addAll(files);
        }
        if (work != null) {
            BY_WORK.put(work, files);
        }
        return files;
    }

    /** The files recorded for {@code work} (a parsed scene), or none. */
    public static List<Path> of(Object work) {
        List<Path> r = BY_WORK.get(work);
        return r == null ? List.of() : r;
    }
}
