package ray.parse;

import java.util.Arrays;

/**
 * The fields set so far in the object being read, each with the line that set it (for "set twice"
 * errors). An object sets a handful of fields, so two small arrays scanned in order do it without a map
 * node or a boxed line number per field: a 100k-triangle mesh sets 400k fields, which as map entries
 * were 20 MB of garbage.
 */
final class FieldLines {

    private String[] names = new String[8];
    private int[] lines = new int[8];
    private int count;

    /** The line {@code name} was set on, or -1 when it was not; records {@code line} in that case. */
    int putIfAbsent(String name, int line) {
        int at = indexOf(name);
        if (at >= 0) {
            return lines[at];
        }
        if (count == names.length) {
            names = Arrays.copyOf(names, 2 * count);
            lines = Arrays.copyOf(lines, 2 * count);
        }
        names[count] = name;
        lines[count++] = line;
        return -1;
    }

    /** The line {@code name} was set on, or -1. */
    int lineOf(String name) {
        int at = indexOf(name);
        return at < 0 ? -1 : lines[at];
    }

    boolean contains(String name) {
        return indexOf(name) >= 0;
    }

    /** Forgets every field (a new object begins). */
    void clear() {
        Arrays.fill(names, 0, count, null);
        count = 0;
    }

    private int indexOf(String name) {
        for (int i = 0; i < count; i++) {
            if (names[i].equals(name)) {
                return i;
            }
        }
        return -1;
    }
}
