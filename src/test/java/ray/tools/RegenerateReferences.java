package ray.tools;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import javax.imageio.ImageIO;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.PngWriter;
import ray.render.Renderer;

/**
 * {@code gradle regenerateReferences [-Pscenes=REGEX]}: re-renders {@code scenes/*.txt} (those whose
 * file name matches REGEX, e.g. {@code 'csg.*'}) and writes {@code reference-images/<scene>.png} only
 * where a pixel changed or the image is new, so {@code git status} shows exactly the images a change
 * altered. Run it only on purpose, after a change meant to alter images, and look at each one before
 * committing. A tool, not part of the product: it lives in the test sources.
 */
public final class RegenerateReferences {

    private RegenerateReferences() {
    }

    /** args: scenes folder, references folder, optional file-name regex. */
    public static void main(String[] args) throws IOException, SceneFormatException {
        Path scenes = Path.of(args.length > 0 ? args[0] : "scenes");
        Path refs = Path.of(args.length > 1 ? args[1] : "reference-images");
        Pattern filter = Pattern.compile(args.length > 2 && !args[2].isEmpty() ? args[2] : ".*");
        Files.createDirectories(refs);
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.list(scenes)) {
            s.filter(p -> p.toString().endsWith(".txt") && filter.matcher(p.getFileName().toString()).matches()).sorted()
                    .forEach(files::add);
        }
        int wrote = 0, same = 0;
        for (Path f : files) {
            Path target = refs.resolve(f.getFileName().toString().replaceAll("\\.txt$", ".png"));
            Image image = new Renderer(Parser.parse(f)).render();
            if (samePixels(image.toBufferedImage(), target)) {
                same++;
                continue;
            }
            PngWriter.write(image, target);
            System.out.println("wrote " + target);
            wrote++;
        }
        System.out.println(files.size() + " scenes: " + wrote + " written, " + same + " unchanged"
                + (wrote > 0 ? "; review the changes (git diff --stat " + refs + ") and look at them before committing" : ""));
    }

    /** True when {@code png} exists and holds exactly {@code image}'s 8-bit pixels. */
    static boolean samePixels(BufferedImage image, Path png) throws IOException {
        if (!Files.isRegularFile(png)) {
            return false;
        }
        BufferedImage old = ImageIO.read(png.toFile());
        if (old == null || old.getWidth() != image.getWidth() || old.getHeight() != image.getHeight()) {
            return false;
        }
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                if ((old.getRGB(x, y) & 0xFFFFFF) != (image.getRGB(x, y) & 0xFFFFFF)) {
                    return false;
                }
            }
        }
        return true;
    }
}
