package ray.spark;

import java.io.IOException;
import java.io.Serializable;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import ray.Scene;
import ray.accel.Bvh;
import ray.parse.Parser;
import ray.settings.RenderSettings;
import ray.render.SplitRender;
import ray.surface.Mesh;
import ray.surface.Surface;

/**
 * A scene as the executors get it: the scene file's bytes, the OBJ files it names (as written in it,
 * relative to its folder), the command line's sampling overrides and, for the study, a pixel limit. Sent
 * once per executor (a broadcast). {@link #load} parses it and builds its BVH once per executor JVM: a
 * cache keyed by the content's SHA-256, so every task of the scene on that JVM shares one parsed,
 * prepared scene.
 */
final class SceneBundle implements Serializable {

    private static final long serialVersionUID = 1L;

    /** The scene as named on the command line (for messages). */
    final String name;
    private final byte[] scene;
    private final List<String> files;
    private final List<byte[]> fileBytes;
    final Overrides overrides;
    /** SHA-256 of all of the above, in hex: the executor cache's key. */
    final String key;

    /**
     * The command line's render options as {@code raytracer} reads them (unset: the scene's own global) and
     * the study's pixel limit (0: none).
     */
    record Overrides(RenderSettings settings, int maxPixels) implements Serializable {
        static final Overrides NONE = new Overrides(new RenderSettings(), 0);

        /** Fits a freshly parsed scene to the study's size (the study's renders only). */
        void fit(Scene s) {
            if (maxPixels > 0) {
                ray.study.StudySettings.fit(s, maxPixels);
            }
        }
    }

    private SceneBundle(String name, byte[] scene, List<String> files, List<byte[]> fileBytes, Overrides overrides) {
        this.name = name;
        this.scene = scene;
        this.files = files;
        this.fileBytes = fileBytes;
        this.overrides = overrides;
        this.key = digest();
    }

    /**
     * The bundle of a scene the driver has parsed ({@code parsed}, from {@code path}): the file and every
     * OBJ file its meshes (CSG operands included) read.
     */
    static SceneBundle of(Path path, Scene parsed, Overrides overrides) throws IOException {
        return of(path.toString(), Files.readAllBytes(path), path.toAbsolutePath().getParent(), parsed, overrides);
    }

    /**
     * The bundle of a scene the driver has parsed from {@code bytes} (named {@code name}: {@code -} for
     * standard input), its OBJ files read from {@code folder}.
     */
    static SceneBundle of(String name, byte[] bytes, Path folder, Scene parsed, Overrides overrides) throws IOException {
        List<String> files = new ArrayList<>();
        List<byte[]> fileBytes = new ArrayList<>();
        List<Surface> todo = new ArrayList<>(parsed.surfaces);
        while (!todo.isEmpty()) {
            Surface s = todo.remove(todo.size() - 1);
            todo.addAll(s.operands());
            if (s instanceof Mesh m && m.file != null && !files.contains(m.file)) {
                files.add(m.file);
                fileBytes.add(Files.readAllBytes(folder.resolve(m.file)));
            }
        }
        return new SceneBundle(name, bytes, files, fileBytes, overrides);
    }

    /** The same scene with other render options (the study's reference renders: one bundle per setting). */
    SceneBundle with(Overrides other) {
        return new SceneBundle(name, scene, files, fileBytes, other);
    }

    /** Total bytes shipped. */
    long size() {
        long n = scene.length;
        for (byte[] b : fileBytes) {
            n += b.length;
        }
        return n;
    }

    private String digest() {
        try {
            MessageDigest d = MessageDigest.getInstance("SHA-256");
            update(d, scene);
            for (int i = 0; i < files.size(); i++) {
                update(d, files.get(i).getBytes(StandardCharsets.UTF_8));
                update(d, fileBytes.get(i));
            }
            update(d, overrides.toString().getBytes(StandardCharsets.UTF_8));
            return hex(d);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** The digest in hex. */
    static String hex(MessageDigest d) {
        StringBuilder b = new StringBuilder();
        for (byte x : d.digest()) {
            b.append(String.format("%02x", x));
        }
        return b.toString();
    }

    /** Adds {@code b} to the digest, its length first (so no two lists of byte arrays digest alike). */
    static void update(MessageDigest d, byte[] b) {
        d.update(java.nio.ByteBuffer.allocate(8).putLong(b.length).array());
        d.update(b);
    }

    // ---- the executor side: parse and prepare once per JVM ----

    /** A parsed scene prepared for rendering, what it cost, and how many times this JVM parsed any scene. */
    static final class Loaded {
        final SplitRender.Prepared prepared;
        final long buildNanos;
        final long bvhBytes, primitives;

        Loaded(SplitRender.Prepared prepared, long buildNanos) {
            this.prepared = prepared;
            this.buildNanos = buildNanos;
            Bvh b = prepared.scene().accelerator() instanceof Bvh bvh ? bvh : null;
            this.bvhBytes = b != null ? b.memoryBytes() : 0;
            this.primitives = b != null ? b.primitiveCount() : 0;
        }
    }

    /** Scenes this JVM holds, most recently used last; a few at most (an animation's frames come one after another). */
    private static final int CACHED = 4;
    private static final Map<String, Holder> CACHE = new LinkedHashMap<>(16, 0.75f, true);
    /** How many times this JVM parsed a scene (tests: once per scene, not per task). */
    static final java.util.concurrent.atomic.AtomicInteger PARSES = new java.util.concurrent.atomic.AtomicInteger();

    /** One cache entry: loaded by the first task that needs it, the others wait for it. */
    private static final class Holder {
        private Loaded loaded;
        private RuntimeException failure;

        synchronized Loaded get(SceneBundle b) {
            if (loaded == null && failure == null) {
                try {
                    loaded = b.parseAndPrepare();
                } catch (RuntimeException e) {
                    failure = e;
                }
            }
            if (failure != null) {
                throw failure;
            }
            return loaded;
        }
    }

    /** The scene, parsed and prepared once per JVM (see the class comment). */
    Loaded load() {
        Holder h;
        synchronized (CACHE) {
            h = CACHE.computeIfAbsent(key, k -> new Holder());
            while (CACHE.size() > CACHED) {
                CACHE.remove(CACHE.keySet().iterator().next());
            }
        }
        return h.get(this);
    }

    /** Parses and prepares the scene (the cache's loader). */
    private Loaded parseAndPrepare() {
        Scene s = parse();
        long t0 = System.nanoTime();
        SplitRender.Prepared prepared = SplitRender.prepare(s, overrides.settings());
        return new Loaded(prepared, System.nanoTime() - t0);
    }

    /**
     * A freshly parsed copy of the scene (fitted to the study's size when it asks for that): the files
     * written into a private temporary folder laid out as on the driver (the scene deep enough that
     * {@code ../} names stay inside) and parsed there.
     */
    Scene parse() {
        Path root = null;
        try {
            root = Files.createTempDirectory("raytracer-spark-");
            int depth = 0;
            for (String f : files) {
                depth = Math.max(depth, leadingParents(f));
            }
            Path dir = root;
            for (int i = 0; i < depth; i++) {
                dir = dir.resolve("d" + i);
            }
            Files.createDirectories(dir);
            String fileName = name.equals("-") || Path.of(name).getFileName() == null ? "scene.txt" : Path.of(name).getFileName().toString();
            Path scenePath = dir.resolve(fileName);
            Files.write(scenePath, scene);
            for (int i = 0; i < files.size(); i++) {
                Path f = Path.of(files.get(i));
                if (f.isAbsolute()) {
                    continue;   // an absolute name is read where it is (a file system the executors share)
                }
                Path target = dir.resolve(f).normalize();
                if (!target.startsWith(root)) {
                    continue;
                }
                Files.createDirectories(target.getParent());
                Files.write(target, fileBytes.get(i));
            }
            PARSES.incrementAndGet();
            Scene s = Parser.parse(scenePath, new ArrayList<>());
            overrides.fit(s);
            return s;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot unpack the scene on this executor: " + e.getMessage(), e);
        } catch (ray.parse.SceneFormatException e) {
            // parsed on the driver already: only a file that differs here can fail (an absolute OBJ name)
            throw new IllegalStateException(e.getMessage().replace(String.valueOf(root), "<executor>"), e);
        } finally {
            if (root != null) {
                deleteTree(root);
            }
        }
    }

    private static int leadingParents(String f) {
        int n = 0;
        for (Path p : Path.of(f)) {
            if (!p.toString().equals("..")) {
                break;
            }
            n++;
        }
        return n;
    }

    static void deleteTree(Path root) {
        try (Stream<Path> s = Files.walk(root)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            // a temporary folder left behind is not worth failing a render for
        }
    }
}
