package ray.render;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import ray.io.OutputFile;

/**
 * Writes an {@link Image} as a PNG file through {@link OutputFile} (its rules decide what may be
 * replaced: an existing file only if it is empty or a PNG, never a read-only one or an input) with the
 * bytes of {@link PngEncoder} (not ImageIO: see there why).
 */
public final class PngWriter {

    private PngWriter() {
    }

    /** Checks {@code target} before the render and reserves its temporary file ({@link OutputFile#prepare}). */
    public static OutputFile.Pending prepare(Path target) throws IOException {
        return OutputFile.prepare(target, OutputFile.Guard.PNG);
    }

    /** The encoder as the body {@link OutputFile.Pending#commit} writes. */
    public static OutputFile.Body png(Image image) {
        return new OutputFile.Body() {     // (not a lambda: linking one costs start-up time)
            @Override
            public void writeTo(OutputStream out) throws IOException {
                PngEncoder.write(image, out);
            }
        };
    }

    /** Writes {@code image} to {@code target}: prepared, committed, the temporary file always removed. */
    public static void write(Image image, Path target) throws IOException {
        OutputFile.write(target, OutputFile.Guard.PNG, png(image));
    }
}
