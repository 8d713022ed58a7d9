package ray.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Where each scene's image goes, by the command line's rules: beside the scene ({@code a.txt -> a.png});
 * {@code -o FILE.png} for one scene; {@code -o FOLDER} (an existing folder, or a name ending in
 * {@code /}) for any number of scenes; {@code -o -}, or the scene {@code -} (read from standard input),
 * to standard output. Also refuses, before anything is rendered, an image that would replace a scene
 * on the command line or another scene's image, deciding identity by the file itself (links followed);
 * what any existing file must be to be replaced is {@link ray.io.OutputFile}'s rule.
 */
final class Outputs {

    /** The scene argument that means standard input. */
    static final String STDIN = "-";

    /** A command line whose output rules cannot be met (exit status 2). */
    static final class UsageException extends Exception {
        UsageException(String message) {
            super(message);
        }
    }

    /** An image's destination: a file, or standard output when {@code path} is null. */
    record Target(Path path) {
        boolean stdout() {
            return path == null;
        }

        @Override
        public String toString() {
            return path == null ? "<stdout>" : path.toString();
        }
    }

    private final List<Path> scenes;
    private final Path folder;
    private final Target single;
    /** Real location of each image written so far -> the scene it was written for. */
    private final Map<Path, Path> written = new HashMap<>();

    private Outputs(List<Path> scenes, Path folder, Target single) {
        this.scenes = scenes;
        this.folder = folder;
        this.single = single;
    }

    static Outputs of(List<Path> scenes, String outputArg, boolean stdoutIsTerminal) throws UsageException {
        int fromStdin = 0;
        for (Path p : scenes) {   // a loop, not a stream: linking a stream's lambda costs start-up time
            fromStdin += isStdin(p) ? 1 : 0;
        }
        if (fromStdin > 1) {
            throw new UsageException("standard input ('-') can be read only once");
        }
        if (outputArg == null) {
            if (fromStdin == 1 && stdoutIsTerminal) {
                throw new UsageException("the scene '-' writes its PNG to standard output, which is a terminal; "
                        + "redirect it (> image.png) or give -o FILE.png");
            }
            return new Outputs(scenes, null, null);
        }
        String o = outputArg;
        Path output = Path.of(o);
        if (o.equals(STDIN)) {
            if (scenes.size() != 1) {
                throw new UsageException("-o - writes one image to standard output: give exactly one scene");
            }
            if (stdoutIsTerminal) {
                throw new UsageException("-o - would write a PNG to a terminal; redirect standard output (> image.png) or give -o FILE.png");
            }
            return new Outputs(scenes, null, new Target(null));
        }
        if (Files.isDirectory(output) || o.endsWith("/") || o.endsWith(java.io.File.separator)) {
            if (fromStdin == 1) {
                throw new UsageException("a scene read from standard input has no name to put in the folder " + output
                        + ": give -o FILE.png or -o -");
            }
            return new Outputs(scenes, output, null);
        }
        if (scenes.size() != 1) {
            throw new UsageException("--output names one file (" + output + ") but there are " + scenes.size()
                    + " scenes; give a folder to write each scene's PNG into");
        }
        return new Outputs(scenes, null, new Target(output));
    }

    static boolean isStdin(Path scene) {
        return scene.toString().equals(STDIN);
    }

    /**
     * The destination of {@code scene}'s image. Throws with the reason (to follow the scene's name)
     * when there is none: a scene read through /dev or /proc has no folder to put a PNG beside.
     */
    Target target(Path scene) throws IOException {
        if (single != null) {
            return single;
        }
        if (isStdin(scene)) {
            return new Target(null);
        }
        if (folder != null) {
            return new Target(folder.resolve(pngName(scene)));
        }
        String abs = scene.toAbsolutePath().normalize().toString();
        if (abs.startsWith("/dev/") || abs.startsWith("/proc/")) {
            throw new IOException("a PNG beside it would go into " + (abs.startsWith("/dev/") ? "/dev" : "/proc")
                    + "; name the image with -o FILE.png, or read the scene from standard input with '-'");
        }
        return new Target(scene.resolveSibling(pngName(scene)));
    }

    /** a.txt -> a.png (a name without .txt gets .png appended). */
    static String pngName(Path scene) {
        String name = scene.getFileName().toString();
        return (name.endsWith(".txt") ? name.substring(0, name.length() - 4) : name) + ".png";
    }

    /**
     * Throws with the reason if writing {@code png} would replace a scene file on this command line
     * (the same file on disk: through a link, a hard link or another spelling of its path) or the
     * image already written for another scene.
     */
    void checkIdentity(Path scene, Path png) throws IOException {
        if (Files.exists(png)) {
            for (Path s : scenes) {
                if (!isStdin(s) && Files.exists(s) && Files.isSameFile(png, s)) {
                    throw new IOException(s.equals(scene) ? "the image " + png + " would replace the scene file itself"
                            : "the image " + png + " would replace the scene file " + s + " given on the same command line");
                }
            }
        }
        Path key = realKey(png);
        Path earlier = written.get(key);
        if (earlier != null && !earlier.equals(scene)) {
            throw new IOException("the image " + png + " would replace the one just written for " + earlier);
        }
    }

    /** Remembers that {@code png} now holds {@code scene}'s image. */
    void wrote(Path scene, Path png) {
        written.put(realKey(png), scene);
    }

    /** The file's real path when it exists, else its real folder plus its name. */
    private static Path realKey(Path p) {
        try {
            if (Files.exists(p)) {
                return p.toRealPath();
            }
            Path abs = p.toAbsolutePath();
            Path dir = abs.getParent();
            return dir != null && Files.exists(dir) ? dir.toRealPath().resolve(abs.getFileName()) : abs.normalize();
        } catch (IOException e) {
            return p.toAbsolutePath().normalize();
        }
    }
}
