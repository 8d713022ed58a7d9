package ray;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Imports point one way (docs/architecture.md, "Layers"): read from the compiled product classes (every
 * class a class file names, in its constant pool and its signatures), each class may use only classes of
 * its own package or of a lower layer. Layer 0 is the core (packages {@code ray} and {@code ray.accel})
 * with the framework's API classes, which may use each other: the one cycle the framework forces
 * (Scene, Surface, Material, Light, IntersectionRecord: a material shades through the scene). Packages
 * of one layer do not use each other; a package not in the table fails the test until it is placed.
 */
class ArchitectureTest {

    /** Package to layer, bottom first. */
    static final Map<String, Integer> LAYERS = new TreeMap<>(Map.ofEntries(
            Map.entry("ray", 0), Map.entry("ray.accel", 0),
            Map.entry("ray.grade.child", 0),   // the grader's harness, run in a sandbox without the product: uses nothing of it
            Map.entry("ray.surface", 1), Map.entry("ray.material", 1), Map.entry("ray.light", 1),
            Map.entry("ray.settings", 2), Map.entry("ray.io", 2),
            Map.entry("ray.plan", 3),
            Map.entry("ray.render", 4),
            Map.entry("ray.parse", 5), Map.entry("ray.judge", 5),
            Map.entry("ray.study", 6), Map.entry("ray.viewer", 6), Map.entry("ray.grade", 6),
            Map.entry("ray.app", 7),
            Map.entry("", 8)));

    /**
     * The framework's API classes, in layer 0 wherever their package is, with the types their signatures
     * hand to a student's or a built-in's code (a light sample, a material's declared terms and hit cost,
     * the plan as a material sees it).
     */
    static final Set<String> API = Set.of("ray.surface.Surface", "ray.material.Material", "ray.material.Term",
            "ray.material.HitCost", "ray.material.ShadingPlan", "ray.light.Light", "ray.light.LightSample");

    /** What package {@code ray} may use of {@code ray.accel}: the interface rays are cast through (the BVH is built above). */
    static final Set<String> CORE_USES_OF_ACCEL = Set.of("ray.accel.Accelerator");

    private static final Pattern DESCRIPTOR = Pattern.compile("L(ray/[A-Za-z0-9_/$]+|RayTracer[A-Za-z0-9_$]*);");

    @Test
    void importsPointOneWay() throws IOException {
        Map<String, Set<String>> uses = classGraph();
        assertTrue(uses.size() > 100, "read " + uses.size() + " classes");
        List<String> wrong = violations(uses);
        assertTrue(wrong.isEmpty(), wrong.size() + " imports point the wrong way:\n  " + String.join("\n  ", wrong));
    }

    /** The rule can fail: the edges this project once had (issue 16) are each caught, and the class files are read. */
    @Test
    void theEdgesThatOncePointedBackAreCaught() throws IOException {
        Map<String, Set<String>> old = new TreeMap<>();
        old.put("ray.Scene", Set.of("ray.render.Renderer", "ray.accel.Bvh", "ray.plan.RenderPlan"));
        old.put("ray.TraceContext", Set.of("ray.render.PixelSample"));
        old.put("ray.surface.Mesh", Set.of("ray.parse.ObjFile", "ray.material.DielectricMaterial"));
        old.put("ray.plan.PlanCommand", Set.of("ray.parse.Parser"));
        old.put("ray.material.Material", Set.of("ray.plan.RenderPlan"));
        old.put("ray.viewer.X", Set.of("ray.study.Y"));
        old.put("ray.elsewhere.Z", Set.of());
        assertTrue(violations(old).size() == 10, String.join("\n", violations(old)));
        try (InputStream in = Scene.class.getResourceAsStream("Scene.class")) {
            Set<String> named = namedClasses(in);
            assertTrue(named.contains("ray/accel/Accelerator") && named.contains("ray/surface/Surface"), named.toString());
        }
    }

    static List<String> violations(Map<String, Set<String>> uses) {
        List<String> wrong = new ArrayList<>();
        for (Map.Entry<String, Set<String>> e : uses.entrySet()) {
            String from = e.getKey();
            Integer a = layer(from);
            if (a == null) {
                wrong.add(from + ": package " + pkg(from) + " has no layer (add it to ArchitectureTest.LAYERS and docs/architecture.md)");
                continue;
            }
            for (String to : e.getValue()) {
                Integer b = layer(to);
                if (b == null || pkg(from).equals(pkg(to))) {
                    continue;
                }
                if (b > a || b.equals(a) && a > 0) {
                    wrong.add(from + " -> " + to + (b > a ? " (points up: layer " + a + " to " + b + ")" : " (sideways within layer " + a + ")"));
                } else if (pkg(from).equals("ray") && pkg(to).equals("ray.accel") && !CORE_USES_OF_ACCEL.contains(to)) {
                    wrong.add(from + " -> " + to + " (the model casts rays through Accelerator only; the BVH is built above it)");
                }
            }
        }
        return wrong;
    }

    static Integer layer(String cls) {
        return API.contains(cls) ? Integer.valueOf(0) : LAYERS.get(pkg(cls));
    }

    static String pkg(String cls) {
        int dot = cls.lastIndexOf('.');
        return dot < 0 ? "" : cls.substring(0, dot);
    }

    /** Every product class (nested classes folded into their top-level class) and the product classes it names. */
    static Map<String, Set<String>> classGraph() throws IOException {
        Path root;
        try {
            root = Path.of(Scene.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        } catch (java.net.URISyntaxException e) {
            throw new IOException(e);
        }
        Map<String, Set<String>> graph = new TreeMap<>();
        try (Stream<Path> files = Files.walk(root)) {
            for (Path f : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".class"))::iterator) {
                String name = topLevel(root.relativize(f).toString().replace('\\', '/').replace(".class", ""));
                Set<String> out = graph.computeIfAbsent(name, k -> new TreeSet<>());
                try (InputStream in = Files.newInputStream(f)) {
                    for (String used : namedClasses(in)) {
                        String u = topLevel(used);
                        if (!u.equals(name)) {
                            out.add(u);
                        }
                    }
                }
            }
        }
        return graph;
    }

    private static String topLevel(String internal) {
        int d = internal.indexOf('$');
        return (d < 0 ? internal : internal.substring(0, d)).replace('/', '.');
    }

    /** The classes a class file's constant pool names: class entries and the types in descriptors and signatures. */
    static Set<String> namedClasses(InputStream raw) throws IOException {
        DataInputStream in = new DataInputStream(raw);
        if (in.readInt() != 0xCAFEBABE) {
            throw new IOException("not a class file");
        }
        in.readUnsignedShort();
        in.readUnsignedShort();
        int count = in.readUnsignedShort();
        String[] utf8 = new String[count];
        List<Integer> classNames = new ArrayList<>();
        for (int i = 1; i < count; i++) {
            int tag = in.readUnsignedByte();
            switch (tag) {
                case 1 -> utf8[i] = in.readUTF();
                case 7 -> classNames.add(in.readUnsignedShort());
                case 8, 16, 19, 20 -> in.readUnsignedShort();
                case 15 -> in.skipBytes(3);
                case 3, 4, 9, 10, 11, 12, 17, 18 -> in.skipBytes(4);
                case 5, 6 -> {
                    in.skipBytes(8);
                    i++;
                }
                default -> throw new IOException("constant pool tag " + tag);
            }
        }
        Set<String> out = new TreeSet<>();
        for (int idx : classNames) {
            String n = utf8[idx];
            while (n.startsWith("[")) {
                n = n.substring(1);
            }
            if (n.startsWith("L") && n.endsWith(";")) {
                n = n.substring(1, n.length() - 1);
            }
            if (n.startsWith("ray/") || n.startsWith("RayTracer")) {
                out.add(n);
            }
        }
        for (String s : utf8) {
            if (s != null && s.indexOf(';') > 0) {
                Matcher m = DESCRIPTOR.matcher(s);
                while (m.find()) {
                    out.add(m.group(1));
                }
            }
        }
        return out;
    }
}
