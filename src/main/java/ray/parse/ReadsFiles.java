package ray.parse;

import java.nio.file.Path;

/**
 * A scene object that reads files of its own (a Mesh's OBJ file), named relative to the scene file's
 * folder. The parser calls {@link #readFiles} right after the object's {@code init()}.
 */
public interface ReadsFiles {

    /**
     * Reads the object's files, resolving relative names against {@code folder} (the scene file's folder).
     * A file that cannot be read is an {@link IllegalArgumentException} (reported at the object's header);
     * a mistake inside the file is a {@link SceneFormatException} naming that file and its line.
     */
    void readFiles(Path folder) throws SceneFormatException;
}
