package ray.spark;

import java.io.IOException;
import java.io.OutputStream;
import java.net.URI;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.UUID;
import org.apache.hadoop.conf.Configuration;
import org.apache.hadoop.fs.FileSystem;
import ray.render.Image;
import ray.render.PngEncoder;
import ray.io.OutputFile;
import ray.render.PngWriter;

/**
 * Where one scene's PNG goes, written only whole: a local file through the core's {@link PngWriter}
 * (checked before any task runs, a temporary file renamed into place), or a Hadoop file system path
 * ({@code hdfs://}, {@code s3a://}, {@code file:/} ...) written under a hidden temporary name in the
 * same folder and renamed, so a reader never sees a partial image.
 */
abstract class Output {

    /** The destination as printed in the summary line. */
    abstract String target();

    /** Writes the image (only whole). */
    abstract void commit(Image image) throws IOException;

    /** Gives up: nothing is left behind. */
    abstract void abandon();

    /** Whether {@code name} is a URI with a scheme (a Hadoop path), not a local file name. */
    static boolean isUri(String name) {
        return name.matches("[A-Za-z][A-Za-z0-9+.-]+:/.*");
    }

    /**
     * The PNG of {@code scene} in {@code dir} (null: beside the scene), prepared (checked) now; a local
     * image may not replace a file the scene reads ({@code reads}).
     */
    static Output prepare(Path scene, String dir, Configuration hadoop, java.util.Collection<Path> reads) throws IOException {
        String file = pngName(scene);
        if (dir != null && isUri(dir)) {
            return new Hadoop(new org.apache.hadoop.fs.Path(new org.apache.hadoop.fs.Path(URI.create(dir)), file), hadoop);
        }
        Path target = dir == null ? scene.resolveSibling(file) : Path.of(dir).resolve(file);
        OutputFile.Pending pending = PngWriter.prepare(target);
        pending.protect(reads);
        return new Local(target, pending);
    }

    /** a.txt -> a.png (another extension: the name + .png). */
    static String pngName(Path scene) {
        String n = scene.getFileName().toString();
        return (n.endsWith(".txt") ? n.substring(0, n.length() - 4) : n) + ".png";
    }

    /** Makes the output folder (local or Hadoop) when it is missing. */
    static void makeFolder(String dir, Configuration hadoop) throws IOException {
        if (isUri(dir)) {
            org.apache.hadoop.fs.Path p = new org.apache.hadoop.fs.Path(URI.create(dir));
            FileSystem fs = p.getFileSystem(hadoop);
            if (!fs.exists(p) && !fs.mkdirs(p)) {
                throw new IOException("cannot create the folder " + dir);
            }
        } else {
            Files.createDirectories(Path.of(dir));
        }
    }

    private static final class Local extends Output {
        private final Path target;
        private final OutputFile.Pending pending;

        Local(Path target, OutputFile.Pending pending) {
            this.target = target;
            this.pending = pending;
        }

        @Override
        String target() {
            return target.toString();
        }

        @Override
        void commit(Image image) throws IOException {
            pending.commit(PngWriter.png(image));
        }

        @Override
        void abandon() {
            pending.abandon();
        }
    }

    private static final class Hadoop extends Output {
        private final org.apache.hadoop.fs.Path target;
        private final FileSystem fs;

        Hadoop(org.apache.hadoop.fs.Path target, Configuration conf) throws IOException {
            this.target = target;
            this.fs = target.getFileSystem(conf);
            org.apache.hadoop.fs.Path parent = target.getParent();
            if (!fs.exists(parent)) {
                throw new IOException("no such folder: " + parent);
            }
            if (fs.exists(target) && fs.getFileStatus(target).isDirectory()) {
                throw new IOException("it is a folder");
            }
        }

        @Override
        String target() {
            return target.toString();
        }

        @Override
        void commit(Image image) throws IOException {
            org.apache.hadoop.fs.Path tmp = new org.apache.hadoop.fs.Path(target.getParent(), "." + target.getName() + "." + UUID.randomUUID() + ".tmp");
            try {
                try (OutputStream out = fs.create(tmp, false)) {
                    PngEncoder.write(image, out);
                }
                // HDFS's rename does not replace: the old image goes first (a reader sees the old, then none, then the new)
                if (fs.exists(target)) {
                    fs.delete(target, false);
                }
                if (!fs.rename(tmp, target)) {
                    throw new IOException("cannot rename " + tmp + " to " + target);
                }
            } finally {
                if (fs.exists(tmp)) {
                    fs.delete(tmp, false);
                }
            }
        }

        @Override
        void abandon() {
        }
    }
}
