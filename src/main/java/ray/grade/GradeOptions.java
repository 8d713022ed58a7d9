package ray.grade;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import picocli.CommandLine.Option;

/**
 * How submissions are graded, for {@code raytracer grade} and {@code raytracer-spark grade} (a picocli
 * mixin): the test set, the sandbox, the scratch space.
 */
public final class GradeOptions {

    @Option(names = "--tests", paramLabel = "DIR", description = "a test set (a folder with rubric.txt); default: the course kit's grading/")
    public Path tests;

    @Option(names = "--sandbox", paramLabel = "MODE", description = "auto (bubblewrap where the submissions run, when it works there, "
            + "else none), bwrap (refuse to grade without it), or none (no isolation: trusted code only)")
    public String sandbox = "auto";

    @Option(names = "--work", paramLabel = "DIR", description = "scratch space for the child JVMs (default: the system's temporary folder)")
    public Path work;

    /**
     * The test set ({@code --tests}, else the course kit's), with {@code --sandbox} checked (not probed);
     * an IOException's message says in one line what is wrong.
     */
    public TestSet testSet() throws IOException {
        Sandbox.checkMode(sandbox);
        return TestSet.load(tests != null ? tests : GradeCommand.defaultTests());
    }

    /** The folder the graders' scratch folders go into: {@code work} (created) or the system's temporary folder. */
    public static Path scratch(Path work) throws IOException {
        return work != null ? Files.createDirectories(work) : Path.of(System.getProperty("java.io.tmpdir"));
    }
}
