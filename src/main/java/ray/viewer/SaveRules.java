package ray.viewer;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import ray.render.Image;
import ray.render.PngWriter;

/**
 * Saving the image shown as a PNG without losing a file: the suggested name is the scene's with
 * {@code .png} beside it, a name without {@code .png} gets it, an existing file is replaced only after
 * the user agreed, the scene file itself (the same file on disk, however the path is spelled) and
 * folders are never written over, and the PNG is written atomically by {@link PngWriter}.
 */
public final class SaveRules {

    /** What to do with a chosen target. */
    public enum Verdict {
        /** Nothing there: write. */
        WRITE,
        /** A file is there: ask before replacing it. */
        ASK_TO_REPLACE,
        /** Never write there (the scene file, a folder): {@link #refusal} says why. */
        REFUSE
    }

    private SaveRules() {
    }

    /** {@code dir/name.txt} -> {@code dir/name.png} (a name without {@code .txt} gets {@code .png} added). */
    public static Path suggestedTarget(Path scene) {
        return suggestedTarget(scene, false);
    }

    /**
     * As {@link #suggestedTarget(Path)}; the image of a stopped render is suggested as
     * {@code name-partial.png}, so it is not taken for (nor written over) the finished render.
     */
    public static Path suggestedTarget(Path scene, boolean partial) {
        Path abs = scene.toAbsolutePath();
        String name = abs.getFileName().toString();
        String base = name.toLowerCase(Locale.ROOT).endsWith(".txt") ? name.substring(0, name.length() - 4) : name;
        return abs.resolveSibling(base + (partial ? "-partial" : "") + ".png");
    }

    /** The chosen path with {@code .png} added unless its name already ends in it (any case). */
    public static Path withPngExtension(Path chosen) {
        String name = chosen.getFileName().toString();
        return name.toLowerCase(Locale.ROOT).endsWith(".png") ? chosen : chosen.resolveSibling(name + ".png");
    }

    public static Verdict check(Path target, Path scene) {
        return refusal(target, scene) != null ? Verdict.REFUSE
                : Files.exists(target) ? Verdict.ASK_TO_REPLACE : Verdict.WRITE;
    }

    /** Why {@code target} must not be written, or null if it may be. */
    public static String refusal(Path target, Path scene) {
        if (Files.isDirectory(target)) {
            return target + " is a folder";
        }
        if (scene != null && Files.exists(target) && Files.exists(scene)) {
            try {
                if (Files.isSameFile(target, scene)) {
                    return target + " is the scene file " + scene + "; choose another name";
                }
            } catch (IOException e) {
                return target + ": cannot tell whether it is the scene file (" + ErrorTexts.reason(e) + ")";
            }
        }
        return null;
    }

    /**
     * Writes {@code image} to {@code target} (atomically: a temporary file beside it, renamed over it).
     * Does not ask: {@link #check} first. A failure names {@code target} and the reason, never the
     * temporary file.
     */
    public static void save(Image image, Path target, Path scene) throws SaveException {
        String refused = refusal(target, scene);
        if (refused != null) {
            throw new SaveException("Not saved: " + refused);
        }
        try {
            PngWriter.write(image, target);
        } catch (IOException | RuntimeException e) {
            throw new SaveException("Cannot save " + target + ": " + ErrorTexts.reason(e));
        }
    }

    /** A save that did not happen; the message names the file the user chose and why. */
    public static final class SaveException extends Exception {
        private static final long serialVersionUID = 1L;

        SaveException(String message) {
            super(ray.Failures.oneLine(message), null, false, false);
        }
    }
}
