package ray.app;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import ray.RayKind;
import ray.light.Light;
import ray.plan.CostGate;
import ray.plan.RenderPlan;

/**
 * Which JIT compiler a render should run under, decided from its render plan before the first ray
 * (docs/performance.md, "The JIT policy").
 *
 * <p>{@code bin/raytracer} starts the JVM with C1 only ({@code -XX:TieredStopAtLevel=1}): a render of a
 * second or two is over before C2 would have paid for its compilations, and full tiered compilation costs
 * such a render 1.5-2.5x the CPU time. A render of many seconds is the other way round: C2's code traces
 * 10-15% faster, which pays for its compilations (the launcher gives a long render at least four compiler
 * threads, so they land sooner: docs/performance.md, "Long renders: the JIT's warm-up"). A JVM's compilers
 * are fixed when it starts, so when the launcher allows it (it sets {@code RAYTRACER_RELAUNCH} to its own
 * path unless {@code RAYTRACER_JIT} or the user's JVM options choose the JIT) and the first scene of the
 * command line is long, this process runs the launcher again on the same command line with
 * {@code RAYTRACER_JIT=long} (full tiered compilation), passes its standard streams through and ends with
 * that process's exit status. Nothing has been printed or written by then; the cost is one more JVM start
 * and a second parse of the first scene (a few percent of a long render). A scene with large OBJ meshes is
 * judged before they are read ({@link #isLongBeforeFiles}, told by the parser through
 * {@link BeforeMeshes}), so that a long mesh render does not read its files twice. A long render of a large
 * scene also gets the JDK's Vector API, for the BVH's SIMD traversal ({@link #SIMD}); every long render
 * renders a few pixels spread over the image first, so C2 compiles from the whole image's profiles (the
 * launcher's {@code -Dray.render.warmUp=true}, {@code ray.render.Renderer#WARM_UP}).
 */
final class JitPolicy {

    /**
     * Expected rays (camera rays and the shadow rays of their first hits) from which a render is long.
     * Measured (docs/performance.md, session 30, after the long render's warm-up pixels cut C2's
     * recompilations), C2's CPU over C1's: the classic scene with 5x5 samples (23 M such rays) 1.40, 7x7
     * (45 M) 1.03, 8x8 (59 M) 1.03, 9x9 (75 M) 0.91 (0.97 with the relaunch's own JVM), mirrors at 9x9
     * (75 M) 0.80 with the relaunch; so from 7e7. (Session 26, before the warm-up: classic at 9x9 1.13,
     * classichd 0.94, and a threshold of 1e8.)
     */
    static final double LONG_RAYS = 7e7;
    /** The environment variable the launcher sets to its own path when this process may start it again. */
    static final String RELAUNCH = "RAYTRACER_RELAUNCH";

    private JitPolicy() {
    }

    /**
     * OBJ bytes from which a scene is judged before its meshes are read ({@link #isLongBeforeFiles}):
     * about 270,000 triangles with normals (mesh1m's file is 58 MB for 998,000).
     */
    static final long MESH_BYTES = 16L << 20;
    /**
     * Expected rays from which a scene with {@link #MESH_BYTES} of OBJ files is long. A ray costs a large
     * mesh several times what it costs the classic scene (a deeper tree), so C2 pays from fewer rays:
     * mesh1m (35 M such rays, 998,000 triangles) takes 0.9x the CPU under C2 (docs/performance.md).
     */
    static final double MESH_RAYS = 2e7;

    /** The launcher to start again for a long render, or null when this process may not. */
    static String launcher() {
        String l = System.getenv(RELAUNCH);
        return l == null || l.isEmpty() ? null : l;
    }

    /**
     * Camera rays and one shadow ray per light sample at each camera ray's hit: the work every render
     * of the scene does whatever its materials (mirror chains only add to it). A light that cannot say
     * how many shadow rays it casts counts as one.
     */
    static double expectedRays(RenderPlan plan) {
        return plan.bound().get(RayKind.CAMERA) * (1 + shadowRaysPerPoint(List.of(plan.lights())));
    }

    /** Shadow rays per lit point of {@code lights}: their planned samples, one for a light that cannot say. */
    private static double shadowRaysPerPoint(List<Light> lights) {
        double perPoint = 0;
        for (int i = 0; i < lights.size(); i++) {       // indexed: no iterator
            int n = lights.get(i).plannedShadowRays();
            perPoint += n < 0 ? 1 : n;
        }
        return perPoint;
    }

    /**
     * Whether a scene is long before its meshes are read: {@code objBytes} of OBJ files (those the parser
     * is about to read and those before them) from {@link #MESH_BYTES}, and from {@link #MESH_RAYS} camera
     * rays and shadow rays of their first hits by the lights read so far (a scene that names its image size,
     * samples or lights after its meshes is judged by what was read: it may be found long again after the
     * parse, by {@link #isLong}, at the cost of a second read of its files).
     */
    static boolean isLongBeforeFiles(ray.Scene sceneSoFar, ray.settings.RenderSettings settings, long objBytes) {
        if (objBytes < MESH_BYTES) {
            return false;
        }
        int ns = settings.samples();
        double camera = (double) Math.max(0, sceneSoFar.width) * Math.max(0, sceneSoFar.height) * ns * ns;
        return camera * (1 + shadowRaysPerPoint(sceneSoFar.lights)) >= MESH_RAYS;
    }

    /**
     * The parser's listener for the first scene ({@link Main#beforeFiles}): before each Mesh's OBJ file is
     * read it adds the file's size and, once the scene read so far is long ({@link #isLongBeforeFiles}),
     * starts the launcher again under C2 and ends this process's parse by throwing {@link Relaunched}
     * (nothing read twice but the scene's text before the mesh). A class, not a lambda (StartupClassesTest).
     */
    static final class BeforeMeshes implements ray.parse.BeforeFile {
        private final Main main;
        private long bytes;

        BeforeMeshes(Main main) {
            this.main = main;
        }

        @Override
        public void beforeFile(ray.Scene sceneSoFar, long size) {
            if (size > 0) {
                bytes += size;
            }
            boolean isLong;
            try {
                isLong = isLongBeforeFiles(sceneSoFar, main.renderSettings().resolve(sceneSoFar), bytes);
            } catch (RuntimeException e) {
                return;   // a setting the scene does not allow yet: the parse reports it, the plan decides later
            }
            if (isLong && main.relaunchNow(true)) {   // MESH_BYTES of OBJ files: some 270,000 triangles
                throw new Relaunched();
            }
        }
    }

    /** Thrown through the parser once the launcher started again has run the command line (stackless). */
    static final class Relaunched extends Error {
        private static final long serialVersionUID = 1L;

        Relaunched() {
            super(null, null, false, false);
        }
    }

    /**
     * Whether the render {@code plan} plans is long enough to want C2 (and not one the cost gate
     * refuses: that is reported here, without another process).
     */
    static boolean isLong(RenderPlan plan, String name, boolean allowLong) {
        return expectedRays(plan) >= LONG_RAYS && (allowLong || CostGate.refusal(name, plan) == null);
    }

    /**
     * Set to 1 in a long render's environment when its scene is large ({@link #wantsWide}) and the SIMD
     * traversal pays on this JDK ({@link #simdPays}): the launcher then adds the Vector API's module, and
     * the tree is traversed four boxes at a time ({@code ray.accel.Wide4}). A value the user set (0:
     * never, 1: on any JDK that has the module) is left as it is.
     */
    static final String SIMD = "RAYTRACER_SIMD";
    /**
     * Primitives from which a long render's tree is traversed wide: about the tree of 1,024 inner nodes from
     * which the BVH does so ({@code Bvh.WIDE_NODES}). Below it (classichd: five primitives) the JVM is not
     * given the module at all: it would only cost the render its start-up.
     */
    static final long WIDE_PRIMITIVES = 2048;

    /** Whether a scene of {@code surfaces} is large enough for the wide traversal ({@link #WIDE_PRIMITIVES}). */
    static boolean wantsWide(List<ray.surface.Surface> surfaces) {
        long n = 0;
        for (int i = 0; i < surfaces.size() && n < WIDE_PRIMITIVES; i++) {   // indexed: no iterator
            n += surfaces.get(i).plannedPrimitiveCount();
        }
        return n >= WIDE_PRIMITIVES;
    }

    /**
     * The JDK releases on which a long render gets the SIMD traversal: measured to pay on the first and
     * the last (mesh1m 0.91-0.94x the CPU time on 17, 0.90x on 25; docs/performance.md, "The JIT's share
     * of a long render"), the same incubating module between them (18-24 not measured). Later releases
     * are left out until measured: the module may change or go.
     */
    static final int FIRST_SIMD_JDK = 17, LAST_SIMD_JDK = 25;

    /**
     * Whether a long render on this JDK gets the SIMD traversal: the JDK the render's JVM runs is this
     * one (the same launcher, the same JAVA_HOME), and it must be one of {@link #FIRST_SIMD_JDK} to
     * {@link #LAST_SIMD_JDK} with {@code jdk.incubator.vector} among its own modules. (Session 27 measured
     * JDK 25 at 1.10x the CPU time with it and left 25 out; the cause was C2 compiling each wide traversal
     * twice, inlined into its caller and alone, which the launcher no longer lets it do.)
     * {@code RAYTRACER_SIMD=1} asks for it on any JDK.
     */
    static boolean simdPays() {
        return simdPays(Runtime.version().feature(), hasVectorModule());
    }

    /** {@link #simdPays()}'s rule for a JDK of release {@code feature}, with or without the module. */
    static boolean simdPays(int feature, boolean hasModule) {
        return feature >= FIRST_SIMD_JDK && feature <= LAST_SIMD_JDK && hasModule;
    }

    /** Whether this JDK has {@code jdk.incubator.vector} among its own modules. */
    static boolean hasVectorModule() {
        try {
            return java.lang.module.ModuleFinder.ofSystem().find("jdk.incubator.vector").isPresent();
        } catch (RuntimeException e) {
            return false;
        }
    }

    /**
     * Runs {@code launcher args} with {@code RAYTRACER_JIT=long} (and {@link #SIMD} where {@code wide}
     * and the module is there), this process's standard streams passed through (stderr through a
     * {@link NoticeFilter}, which drops the JVM's start-up notices), and returns its exit status; -1 when it
     * could not be started (the caller renders here). A shutdown hook ends the child if this process is
     * stopped first.
     */
    static int relaunch(String launcher, String[] args, boolean wide) {
        List<String> cmd = new ArrayList<>(args.length + 1);
        cmd.add(launcher);
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd).inheritIO();
        pb.environment().put("RAYTRACER_JIT", "long");
        pb.environment().remove(RELAUNCH);
        if (wide && !pb.environment().containsKey(SIMD) && simdPays()) {
            pb.environment().put(SIMD, "1");
        }
        pb.redirectError(ProcessBuilder.Redirect.PIPE);   // through NoticeFilter
        pb.environment().put("RAYTRACER_STDERR_TTY", Terminal.stderr() ? "true" : "false");
        Process p;
        try {
            p = pb.start();
        } catch (IOException | RuntimeException e) {
            return -1;
        }
        NoticeFilter filter = new NoticeFilter(p.getErrorStream());
        filter.start();
        Thread stop = new Thread(p::destroy, "raytracer-relaunch-stop");
        Runtime.getRuntime().addShutdownHook(stop);
        try {
            while (true) {
                try {
                    int status = p.waitFor();
                    filter.join();   // the child's last words are on this stderr before this process ends
                    return status;
                } catch (InterruptedException e) {
                    p.destroy();   // this thread was asked to stop: so is the render it waits for
                }
            }
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(stop);
            } catch (IllegalStateException e) {
                // already shutting down: the hook runs
            }
        }
    }

    /**
     * Copies a long render's stderr to this process's own, byte for byte as it comes (the progress line
     * included), but for the JVM's own notices among its first lines, which say nothing a user should act
     * on: that the incubator module is used ({@link #NOTICE}; the launcher adds it for the wide traversal,
     * {@link #SIMD}) and how many compiler directives it read ({@link #DIRECTIVES}: the launcher's
     * {@code lib/c2-directives.json}), in either order. A line that is neither ends the notices: it and
     * everything after it pass unchanged.
     */
    static final class NoticeFilter extends Thread {
        /** What the JVM prints when the module is added ({@code ModuleBootstrap}, JDK 17-25). */
        static final byte[] NOTICE = "WARNING: Using incubator modules: jdk.incubator.vector\n"
                .getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        /**
         * What the JVM prints after a count when it has read a compiler-directives file
         * ({@code DirectivesParser}, JDK 17-25): "1 compiler directives added".
         */
        static final byte[] DIRECTIVES = " compiler directives added\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII);
        /** Digits of the count before {@link #DIRECTIVES}: more would be no notice of ours. */
        private static final int COUNT_DIGITS = 4;
        private final java.io.InputStream in;
        private final java.io.OutputStream out;
        /** The current first line so far, while it may still be a notice; its length is {@link #held}. */
        private final byte[] line = new byte[Math.max(NOTICE.length, COUNT_DIGITS + DIRECTIVES.length)];
        private int held;

        NoticeFilter(java.io.InputStream in) {
            this(in, new java.io.FileOutputStream(java.io.FileDescriptor.err));
        }

        NoticeFilter(java.io.InputStream in, java.io.OutputStream out) {
            super("raytracer-stderr");
            setDaemon(true);
            this.in = in;
            this.out = out;
        }

        @Override
        public void run() {
            byte[] buf = new byte[8192];
            boolean notices = true;   // still among the leading notices
            try {
                for (int n; (n = in.read(buf)) > 0; ) {
                    int from = 0;
                    while (notices && from < n) {
                        byte b = buf[from++];
                        line[held++] = b;
                        if (b == '\n' && isNotice(line, held)) {
                            held = 0;   // a whole notice: dropped
                        } else if (b == '\n' || !mayBeNotice(line, held)) {
                            out.write(line, 0, held);   // not a notice: what was held back, then the rest
                            held = 0;
                            notices = false;
                        }
                    }
                    out.write(buf, from, n - from);
                    out.flush();
                }
                out.write(line, 0, held);   // a beginning of a notice that the stream ended in
                out.flush();
            } catch (IOException e) {
                // this process's stderr closed, or the child's: nothing more to pass on
            }
        }

        /** Whether {@code b[0..len)}, a whole line with its newline, is one of the notices. */
        private static boolean isNotice(byte[] b, int len) {
            return startsLike(b, len, NOTICE) && len == NOTICE.length
                    || countThen(b, len) && len - digits(b, len) == DIRECTIVES.length;
        }

        /** Whether {@code b[0..len)} is the beginning of a notice (or a whole one). */
        private static boolean mayBeNotice(byte[] b, int len) {
            return startsLike(b, len, NOTICE) || countThen(b, len);
        }

        /** Whether {@code b[0..len)} is a count so far, or a count and the beginning of {@link #DIRECTIVES}. */
        private static boolean countThen(byte[] b, int len) {
            int d = digits(b, len);
            if (d > COUNT_DIGITS || d == 0 && len > 0) {
                return false;
            }
            if (len - d > DIRECTIVES.length) {
                return false;
            }
            for (int i = d; i < len; i++) {
                if (b[i] != DIRECTIVES[i - d]) {
                    return false;
                }
            }
            return true;
        }

        /** The leading ASCII digits of {@code b[0..len)}. */
        private static int digits(byte[] b, int len) {
            int d = 0;
            while (d < len && b[d] >= '0' && b[d] <= '9') {
                d++;
            }
            return d;
        }

        /** Whether {@code b[0..len)} is a prefix of {@code notice} (the whole of it included). */
        private static boolean startsLike(byte[] b, int len, byte[] notice) {
            if (len > notice.length) {
                return false;
            }
            for (int i = 0; i < len; i++) {
                if (b[i] != notice[i]) {
                    return false;
                }
            }
            return true;
        }
    }
}
