package ray.parse;

import ray.Scene;

/**
 * Told by the parser before it reads a file an object of the scene names (a {@code Mesh}'s OBJ file), with
 * the scene as read so far and the file's size. The launcher's JIT policy ({@code ray.app.JitPolicy})
 * decides there whether a render is long, before a large file is read by a process that would then start
 * again under the other compiler and read it a second time. A listener may end the parse by throwing an
 * {@link Error} of its own class (not a LinkageError, AssertionError or VirtualMachineError, which the parser
 * reports as the object's failure), which leaves the parser unchanged
 * ({@link Parser#parse(java.nio.file.Path, java.util.List, BeforeFile)}).
 */
public interface BeforeFile {

    /**
     * Called before the file of {@code bytes} bytes (-1 when its size cannot be read) is read for the
     * object being ended; {@code sceneSoFar} holds the globals, lights and surfaces read before it.
     */
    void beforeFile(Scene sceneSoFar, long bytes);
}
