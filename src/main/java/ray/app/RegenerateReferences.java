package ray.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.PngWriter;

/**
 * {@code gradle regenerateReferences}: re-renders every {@code scenes/*.txt} into
 * {@code reference-images/<scene>.png}. Run it only on purpose, after a change that is meant to alter
 * images, and review {@code git diff --stat reference-images} (and the images) before committing.
 */
public final class RegenerateReferences {

    private RegenerateReferences() {
    }

    public static void main(String[] args) throws IOException, SceneFormatException {
        Path scenes = Paths.get(args.length > 0 ? args[0] : "scenes");
        Path refs = Paths.get(args.length > 1 ? args[1] : "reference-images");
        Files.createDirectories(refs);
        List<Path> files = new ArrayList<>();
        try (Stream<Path> s = Files.list(scenes)) {
            s.filter(p -> p.toString().endsWith(".txt")).sorted().forEach(files::add);
        }
        for (Path f : files) {
            Scene scene = Parser.parse(f);
            String name = f.getFileName().toString().replaceAll("\\.txt$", ".png");
            PngWriter.write(new ray.render.Renderer(scene).render(), refs.resolve(name));
            System.out.println("wrote " + refs.resolve(name));
        }
        System.out.println("Review the changes (git diff --stat " + refs + ") before committing them.");
    }
}
