package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.app.MainBadInputTest.Run;

/**
 * Issue 17, sections 3 and 4: every input bounded before the work with a message naming the cause
 * (CSG trees, Glazed chains, the long-render gate, threads, the files a Mesh may read), and OBJ files
 * read exactly (a byte-order mark, tabs, indices beyond an int, numbers that are not plain decimals).
 * Each case in the render and, where it reads the scene, in --plan.
 */
class HostileResourceTest {

    @TempDir
    Path dir;

    static final String HEAD = MainBadInputTest.GOOD + "\nMaterial Diffuse white\n\n";

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    private Run render(Path scene) {
        return assertTimeoutPreemptively(Duration.ofSeconds(30), () -> MainBadInputTest.run("-q", "-j", "1", scene.toString()));
    }

    private Run plan(Path scene) {
        return assertTimeoutPreemptively(Duration.ofSeconds(30), () -> MainBadInputTest.run("--plan", scene.toString()));
    }

    private static boolean exec(String... cmd) {
        try {
            return new ProcessBuilder(cmd).redirectErrorStream(true).start().waitFor() == 0;
        } catch (IOException | InterruptedException e) {
            return false;
        }
    }

    private Path meshScene(String obj) throws IOException {
        write("m.obj", obj);
        return write("m.txt", HEAD + "Surface Mesh\nString file m.obj\nref material white\n");
    }

    // ---- 4. OBJ read exactly ----

    /** A byte-order mark before the first `v` must not lose that vertex (every index would shift by one). */
    @Test
    void objByteOrderMarkIsSkipped() throws IOException {
        Path s = meshScene("\uFEFFv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 4\n");
        Run r = render(s);
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
    }

    @Test
    void objTabsSeparateLikeSpaces() throws IOException {
        Run r = render(meshScene("v\t0 0 0\nv 1\t0 0\nv 0 1 0\nf\t1\t2\t3\n"));
        assertEquals(0, r.status(), r.err());
    }

    @Test
    void objIndexBeyondAnIntIsNamedAsWritten() throws IOException {
        Path s = meshScene("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n");
        for (Run r : List.of(render(s), plan(s))) {
            assertEquals(1, r.status());
            assertEquals(List.of(dir.resolve("m.obj") + ":4: 'f 1 2 99999999999' has the index 99999999999, beyond any file's vertices "
                    + "(expected indices from 1 to 2147483647, or negative ones counting back) (read for the Surface Mesh at "
                    + s + ":9)"), r.errLines());
        }
    }

    @Test
    void objNumbersArePlainDecimals() throws IOException {
        for (String v : List.of("0x1p0", "1f", "1d", "NaN", "1e", "+-1")) {
            Run r = render(meshScene("v " + v + " 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
            assertEquals(1, r.status(), v);
            assertTrue(r.err().startsWith(dir.resolve("m.obj") + ":1: cannot read 'v " + v + " 0 0' (expected 'v x y z' with three finite "
                    + "decimal numbers)"), v + ": " + r.err());
        }
    }

    // ---- 3. files a Mesh may read ----

    @Test
    void aMeshReadsOnlyRegularFilesInsideTheScenesFolder() throws IOException {
        for (String f : List.of("/etc/passwd", "../secret.obj", "sub/../../x.obj", "/dev/zero", "/proc/self/environ")) {
            Path s = write("m.txt", HEAD + "Surface Mesh\nString file " + f + "\nref material white\n");
            Run r = render(s);
            assertEquals(1, r.status(), f);
            assertEquals(List.of(s + ":9: Surface Mesh: the OBJ file '" + f + "' is outside the scene file's folder (expected a path "
                    + "relative to the scene file, inside its folder, e.g. 'String file models/bunny.obj')"), r.errLines(), f);
        }
        Path fifo = dir.resolve("pipe.obj");
        assumeTrue(exec("mkfifo", fifo.toString()), "mkfifo is needed");
        Path s = write("f.txt", HEAD + "Surface Mesh\nString file pipe.obj\nref material white\n");
        for (Run r : List.of(render(s), plan(s))) {
            assertEquals(1, r.status());
            assertEquals(List.of(s + ":9: Surface Mesh: cannot read the OBJ file " + fifo + ": not a regular file (a FIFO; expected an OBJ file)"),
                    r.errLines());
        }
        // the scene itself a FIFO: refused in --plan too, never waiting for a writer
        Path sceneFifo = dir.resolve("scene-pipe.txt");
        assumeTrue(exec("mkfifo", sceneFifo.toString()));
        Run r = plan(sceneFifo);
        assertEquals(1, r.status());
        assertEquals(List.of(sceneFifo + ": cannot read the scene: not a regular file (a FIFO); to read a scene from a pipe give '-' "
                + "and send it to standard input"), r.errLines());
    }

    // ---- 3. trees and chains bounded before the work ----

    /** CSGs sharing their operand level after level: refused at once (render and plan), not 2^40 work. */
    @Test
    void csgSharingOperandsIsRefusedAtOnce() throws IOException {
        StringBuilder b = new StringBuilder(HEAD).append("Surface Sphere c0\nref material white\n\n");
        for (int k = 1; k <= 40; k++) {
            b.append("Surface CSG c").append(k).append("\nString operation union\nref left c").append(k - 1)
                    .append("\nref right c").append(k - 1).append("\n\n");
        }
        Path s = write("dag.txt", b.toString());
        for (Run r : List.of(render(s), plan(s))) {
            assertEquals(1, r.status());
            assertEquals(1, r.errLines().size(), r.err());
            assertTrue(r.err().contains(": Surface CSG: this CSG tree would cost 4,608 operand tests per ray (9 levels, 512 leaves "
                    + "counting an operand each time it is used: one surface is both operands of a CSG, so each level doubles the cost), "
                    + "more than 4,096"), r.err());
        }
    }

    /**
     * A class of one's own whose operands() lead back to itself: refused where it is declared (every walk
     * of the scene's surfaces would be endless; it used to vanish from the scene, status 0).
     */
    @Test
    void operandsThatLeadBackToTheSurfaceAreRefused() throws IOException {
        Path s = write("self.txt", HEAD + "Surface SelfOperand\nref material white\n");
        for (Run r : List.of(render(s), plan(s))) {
            assertEquals(1, r.status());
            assertEquals(List.of(s + ":9: SelfOperand's operands lead back to itself (a cycle: expected operands() to return the "
                    + "surfaces it is built from, none of them built from it)"), r.errLines());
        }
    }

    /** A class of one's own sharing operands 60 levels deep (2^60 paths): the plan visits each surface once. */
    @Test
    void operandsSharedLevelAfterLevelArePlannedOnce() throws IOException {
        Path s = write("shared.txt", HEAD + "Surface SharedOperands\nref material white\n");
        Run plan = plan(s);
        assertEquals(0, plan.status(), plan.err());
        assertTrue(plan.out().contains("1 SharedOperands (of 1.2e+18 Sphere) in the BVH"), plan.out());
        assertEquals(0, render(s).status());
    }

    /** A left-deep chain of 10,000 unions: refused where it grows too costly, no StackOverflowError. */
    @Test
    void aDeepCsgChainIsRefusedNotOverflowed() throws IOException {
        StringBuilder b = new StringBuilder(HEAD).append("Surface Sphere c0\nref material white\n\n");
        for (int k = 1; k <= 10_000; k++) {
            b.append("Surface Sphere s").append(k).append("\nref material white\n\nSurface CSG c").append(k)
                    .append("\nString operation union\nref left c").append(k - 1).append("\nref right s").append(k).append("\n\n");
        }
        Path s = write("chain.txt", b.toString());
        Run r = plan(s);
        assertEquals(1, r.status());
        assertTrue(r.err().contains("Surface CSG: this CSG tree would cost") && !r.err().contains("StackOverflow"), r.err());
    }

    @Test
    void aLongGlazedChainIsRefused() throws IOException {
        StringBuilder b = new StringBuilder(HEAD);
        b.append("Material Glazed g0\nref base white\n\n");
        for (int k = 1; k < 5000; k++) {
            b.append("Material Glazed g").append(k).append("\nref base g").append(k - 1).append("\n\n");
        }
        b.append("Surface Sphere\nref material g4999\n");
        Path s = write("glazed.txt", b.toString());
        for (Run r : List.of(render(s), plan(s))) {
            assertEquals(1, r.status());
            assertEquals(1, r.errLines().size(), r.err());
            assertTrue(r.err().contains(": Material GlazedMaterial: a chain of more than 100 Glazed materials"), r.err());
        }
    }

    /** A bound that overflows a double is astronomical, never "unknown": refused, and said in years, not Long.MAX_VALUE days. */
    @Test
    void theLongRenderGateNeverOverflows() throws IOException {
        String glass = "MaxDepth 1000\nAASamples 64\n\nCamera Camera\nVector3d eye [0 0 0]\nVector3d target [0 0 -1]\n\n"
                + "Material DielectricMaterial g\ndouble refractiveIndex 1.5\n\nSurface Sphere\ndouble radius 10\nref material g\n";
        Path big = write("big.txt", "Width 4000\nHeight 4000\n" + glass), small = write("small.txt", "Width 8\nHeight 6\n" + glass);
        Run p = plan(big);
        assertEquals(0, p.status(), p.err());
        assertTrue(p.out().contains("a render would be refused"), p.out());
        Run r = render(small);
        assertEquals(1, r.status());
        assertTrue(r.err().startsWith(small + ": refused: this render may cast up to ") && r.err().contains("e+30")
                && r.err().contains("(limit 1e11; that many would take more than a million years on ")
                && !r.err().contains("9223372036854775807"), r.err());
    }

    @Test
    void threadsAreBounded() throws IOException {
        Path s = write("s.txt", MainBadInputTest.GOOD);
        Run r = MainBadInputTest.run("-j", "40000", s.toString());
        assertEquals(2, r.status());
        assertEquals(List.of("raytracer: --threads must be 1 to 1024, got 40000"), r.errLines());
        assertFalse(Files.exists(dir.resolve("s.png")));
    }

    /**
     * The pixel limit fits the sampler: an image the grid's budget admits is refused before anything is
     * allocated when the scene or the command line asks for a film (jittered, sobol) or the adaptive
     * sampler, with the sampler named.
     */
    @Test
    void thePixelLimitFitsTheSampler() throws IOException {
        long gridMax = Runtime.getRuntime().maxMemory() / 2 / ray.settings.PixelBudget.GRID_BYTES;
        int side = (int) Math.sqrt(gridMax * 0.9);      // admitted by the grid, not by a film
        String scene = "Width " + side + "\nHeight " + side + "\n\nCamera Camera\n";
        Path adaptive = write("adaptive.txt", "Sampler adaptive\n" + scene);
        Run r = MainBadInputTest.run("-q", adaptive.toString());
        assertEquals(1, r.status());
        assertTrue(r.err().startsWith(adaptive + ":2: Width " + side + " x Height " + side + " = ") && r.err().contains(" with the adaptive sampler "),
                r.err());
        Path grid = write("grid.txt", scene);
        for (String sampler : List.of("jittered", "sobol", "adaptive")) {
            Run o = MainBadInputTest.run("-q", "--sampler", sampler, grid.toString());
            assertEquals(1, o.status(), sampler);
            assertEquals(1, o.errLines().size(), o.err());
            assertTrue(o.err().startsWith(grid + ": Width " + side + " x Height " + side + " = ") && o.err().contains(" with the " + sampler
                    + " sampler (expected at most "), o.err());
        }
        assertEquals(0, plan(grid).status(), "the grid itself is admitted");
        assertFalse(Files.exists(dir.resolve("grid.png")));
    }
}
