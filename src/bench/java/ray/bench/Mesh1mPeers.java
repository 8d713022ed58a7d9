package ray.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The peers' translations of the long render {@code mesh1m} ({@link LongScenes}), which the shared bench's
 * {@code peers/translate.py} cannot make: it knows point lights only, and mesh1m has an {@code AreaLight}
 * and a smooth OBJ mesh. Written next to the scene, into {@code peers/<peer>/} of the scene's folder, with
 * the conventions of translate.py (camera, materials, ambient, I/r^2 falloff), for the peers that have area
 * lights: POV-Ray ({@code area_light}, 4x4 fixed grid, {@code area_illumination}), Sunflow (a two-triangle
 * {@code meshlight}, 8 samples per triangle) and Mitsuba 3 (a {@code rectangle} area emitter, rendered by
 * the bench's {@code mitsuba_whitted_area.py}, which samples it at the same 4x4 cell centres as our grid
 * sampler). Tachyon has no area light ({@link #NO_AREA_LIGHT}). Deterministic, and written only when
 * missing or made by another version of this class (a stamp file), as LongScenes writes the scene.
 * How each translation matches the scene and what differs: docs/performance.md, "mesh1m against the peers".
 */
final class Mesh1mPeers {

    /** Why Tachyon has no mesh1m column: its scene language and API have point, spot and directional lights only. */
    static final String NO_AREA_LIGHT = "no area lights";
    /** The bench's Whitted script for Mitsuba with area lights (a resource of this class, copied beside the scene). */
    static final String MITSUBA_SCRIPT = "mitsuba_whitted_area.py";
    /** Changes whenever the translations change, so old files are written again (the stamp also holds the scene's and the script's hashes). */
    private static final String VERSION = "mesh1m peers v1 (ray.bench.Mesh1mPeers)";

    private Mesh1mPeers() {
    }

    /** {@code Mesh1mPeers DIR/mesh1m.txt}: writes the translations into DIR/peers/ (by hand; gradle bench --peers does it itself). */
    public static void main(String[] args) throws IOException {
        write(Path.of(args[0]), System.out);
    }

    /** The folder of peer {@code p}'s mesh1m files, beside the scene in {@code sceneDir}. */
    static Path dir(Path sceneDir, String p) {
        return sceneDir.resolve("peers").resolve(p.startsWith("mitsuba") ? "mitsuba" : p);
    }

    /**
     * Writes the peers' files for {@code scene} (mesh1m.txt with its OBJ) unless the stamp says they are
     * there, made from this scene by this version.
     */
    static void write(Path scene, PrintStream out) throws IOException {
        Path sceneDir = scene.toAbsolutePath().getParent();
        String text = Files.readString(scene, StandardCharsets.UTF_8);
        Scene s = Scene.parse(text);
        Path obj = sceneDir.resolve(s.meshFile);
        Path stamp = sceneDir.resolve("peers/" + LongScenes.MESH1M + ".stamp");
        byte[] script;
        try (InputStream in = Mesh1mPeers.class.getResourceAsStream(MITSUBA_SCRIPT)) {
            if (in == null) {
                throw new IOException("resource " + MITSUBA_SCRIPT + " missing from the bench's class path");
            }
            script = in.readAllBytes();
        }
        // the scene's first line (LongScenes' header), a hash of all of it and of the script, the OBJ's size
        String expected = VERSION + "\n" + text.lines().findFirst().orElse("") + "\n" + text.hashCode() + " "
                + Arrays.hashCode(script) + " " + Files.size(obj) + "\n";
        if (Files.isRegularFile(stamp) && Files.readString(stamp, StandardCharsets.UTF_8).equals(expected)) {
            return;
        }
        out.println("- writing the peers' translations of " + scene + " into " + sceneDir.resolve("peers"));
        Mesh m = Mesh.read(obj);
        String name = LongScenes.MESH1M;
        Files.createDirectories(dir(sceneDir, "pov"));
        Files.createDirectories(dir(sceneDir, "sunflow"));
        Files.createDirectories(dir(sceneDir, "mitsuba"));
        try (Writer w = Files.newBufferedWriter(dir(sceneDir, "pov").resolve(name + ".pov"))) {
            writePov(s, m, w);
        }
        Files.writeString(dir(sceneDir, "pov").resolve(name + ".ini"), povIni(s, name), StandardCharsets.UTF_8);
        try (Writer w = Files.newBufferedWriter(dir(sceneDir, "sunflow").resolve(name + ".sc"))) {
            writeSunflow(s, m, w);
        }
        Path mi = dir(sceneDir, "mitsuba");
        for (Map.Entry<String, String> e : triangleObjs(s).entrySet()) {
            Files.writeString(mi.resolve(name + "_" + e.getKey() + ".obj"), e.getValue(), StandardCharsets.UTF_8);
        }
        Files.writeString(mi.resolve(name + ".xml"), mitsubaXml(s, "../../" + s.meshFile, name), StandardCharsets.UTF_8);
        Files.write(mi.resolve(MITSUBA_SCRIPT), script);
        Files.writeString(stamp, expected, StandardCharsets.UTF_8);
    }

    // ---- the scene ----

    /** The part of the scene format mesh1m uses (and translate.py's defaults); anything else is an error. */
    static final class Scene {
        int width, height, ns = 1, maxDepth = 10;
        double[] bg = {0, 0, 0}, ambient = {0, 0, 0};
        double[] eye = {0, 0, 5}, target = {0, 0, 0}, up = {0, 1, 0};
        double yFov = 45;
        double[] lightCentre, edge1, edge2, intensity;
        int lightSamples;
        /** name to {ka, kd, ks, {p}} (Diffuse: ks 0, p 1). */
        final Map<String, double[][]> materials = new LinkedHashMap<>();
        String meshFile, meshMaterial;
        boolean smooth = true;
        final List<double[][]> triangles = new ArrayList<>();
        final List<String> triangleMaterials = new ArrayList<>();

        static Scene parse(String text) {
            Scene s = new Scene();
            List<String> block = new ArrayList<>();
            for (String raw : (text + "\n\n").split("\n", -1)) {
                String line = raw.strip();
                if (line.startsWith("#")) {
                    continue;
                }
                if (line.isEmpty()) {
                    if (!block.isEmpty()) {
                        s.finish(block);
                        block.clear();
                    }
                    continue;
                }
                String head = line.split("\\s+")[0];
                if (block.isEmpty() && !List.of("Camera", "Light", "Material", "Surface").contains(head)) {
                    s.global(head, line.substring(head.length()).strip());
                    continue;
                }
                block.add(line);
            }
            if (s.lightCentre == null || s.meshFile == null || s.width <= 0 || s.height <= 0) {
                throw new IllegalArgumentException("not a mesh1m-like scene: it needs Width, Height, an AreaLight and a Mesh");
            }
            return s;
        }

        private void global(String key, String v) {
            switch (key) {
                case "Width" -> width = Integer.parseInt(v);
                case "Height" -> height = Integer.parseInt(v);
                case "AASamples" -> ns = Integer.parseInt(v);
                case "MaxDepth" -> maxDepth = Integer.parseInt(v);
                case "BGColor" -> bg = vec(v);
                case "AmbientLight" -> ambient = vec(v);
                default -> throw new IllegalArgumentException("unknown global " + key);
            }
        }

        private void finish(List<String> block) {
            String[] h = block.get(0).split("\\s+");
            Map<String, String> f = new LinkedHashMap<>();
            for (String l : block.subList(1, block.size())) {
                String[] t = l.split("\\s+", 3);
                f.put(t[1], t[2]);
            }
            String kind = h[0] + " " + h[1];
            switch (kind) {
                case "Camera Camera" -> {
                    eye = f.containsKey("eye") ? vec(f.get("eye")) : eye;
                    target = f.containsKey("target") ? vec(f.get("target")) : target;
                    up = f.containsKey("up") ? vec(f.get("up")) : up;
                    yFov = f.containsKey("yFOV") ? Double.parseDouble(f.get("yFOV")) : yFov;
                }
                case "Light AreaLight" -> {
                    if (lightCentre != null) {
                        throw new IllegalArgumentException("one area light only");
                    }
                    lightCentre = vec(f.getOrDefault("position", "[0 0 0]"));
                    edge1 = vec(f.getOrDefault("edge1", "[1 0 0]"));
                    edge2 = vec(f.getOrDefault("edge2", "[0 0 1]"));
                    intensity = vec(f.getOrDefault("intensity", "[1 1 1]"));
                    lightSamples = Integer.parseInt(f.getOrDefault("samples", "4"));
                }
                case "Material Diffuse", "Material BlinnPhong" -> {
                    double[] z = {0, 0, 0};
                    boolean phong = h[1].equals("BlinnPhong");
                    materials.put(h[2], new double[][] {
                            f.containsKey("ambientColor") ? vec(f.get("ambientColor")) : z,
                            f.containsKey("diffuseColor") ? vec(f.get("diffuseColor")) : z,
                            phong && f.containsKey("specularColor") ? vec(f.get("specularColor")) : z,
                            {phong && f.containsKey("exponent") ? Double.parseDouble(f.get("exponent")) : 1}});
                }
                case "Surface Mesh" -> {
                    meshFile = f.get("file");
                    meshMaterial = f.get("material");
                    smooth = !"0".equals(f.get("smooth"));
                    if ("1".equals(f.get("twoSided"))) {
                        throw new IllegalArgumentException("two-sided meshes are not translated");
                    }
                }
                case "Surface Triangle" -> {
                    triangles.add(new double[][] {vec(f.get("v0")), vec(f.get("v1")), vec(f.get("v2"))});
                    triangleMaterials.add(f.get("material"));
                }
                default -> throw new IllegalArgumentException("not translated for the peers: " + kind);
            }
        }

        static double[] vec(String v) {
            String[] t = v.replace("[", " ").replace("]", " ").strip().split("\\s+");
            return new double[] {Double.parseDouble(t[0]), Double.parseDouble(t[1]), Double.parseDouble(t[2])};
        }
    }

    /**
     * The OBJ mesh as the peers read it: each vertex's and normal's text as the file writes it (copied,
     * not reformatted), faces fanned from their first corner as ray.surface's mesh does.
     */
    static final class Mesh {
        final List<String> v = new ArrayList<>(), vn = new ArrayList<>();
        int[] tri = new int[3 * 1024];
        int triangles;

        static Mesh read(Path obj) throws IOException {
            Mesh m = new Mesh();
            try (BufferedReader r = Files.newBufferedReader(obj, StandardCharsets.UTF_8)) {
                for (String line; (line = r.readLine()) != null; ) {
                    if (line.startsWith("v ")) {
                        m.v.add(line.substring(2).strip());
                    } else if (line.startsWith("vn ")) {
                        m.vn.add(line.substring(3).strip());
                    } else if (line.startsWith("f ")) {
                        String[] c = line.substring(2).strip().split("\\s+");
                        int[] idx = new int[c.length];
                        for (int i = 0; i < c.length; i++) {
                            String[] parts = c[i].split("/");
                            idx[i] = Integer.parseInt(parts[0]) - 1;
                            if (parts.length == 3 && Integer.parseInt(parts[2]) - 1 != idx[i]) {
                                throw new IOException(obj + ": a corner whose normal index is not its vertex index: " + line);
                            }
                        }
                        for (int i = 1; i + 1 < idx.length; i++) {
                            m.add(idx[0], idx[i], idx[i + 1]);
                        }
                    }
                }
            }
            if (!m.vn.isEmpty() && m.vn.size() != m.v.size()) {
                throw new IOException(obj + ": " + m.v.size() + " vertices but " + m.vn.size() + " normals");
            }
            return m;
        }

        private void add(int a, int b, int c) {
            if (3 * triangles + 3 > tri.length) {
                tri = Arrays.copyOf(tri, 2 * tri.length);
            }
            tri[3 * triangles] = a;
            tri[3 * triangles + 1] = b;
            tri[3 * triangles + 2] = c;
            triangles++;
        }
    }

    // ---- helpers (translate.py's) ----

    static String g(double x) {
        String s = String.format(Locale.ROOT, "%.6g", x);
        // %.6g keeps trailing zeros, Python's does not
        if (s.contains("e")) {
            String[] p = s.split("e");
            return trimZeros(p[0]) + "e" + p[1];
        }
        s = trimZeros(s);
        return s.equals("-0") ? "0" : s;
    }

    private static String trimZeros(String s) {
        if (!s.contains(".")) {
            return s;
        }
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }

    private static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double[] scale(double[] a, double k) {
        return new double[] {a[0] * k, a[1] * k, a[2] * k};
    }

    private static double[] add(double[] a, double[] b) {
        return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] norm(double[] a) {
        return scale(a, 1 / Math.sqrt(dot(a, a)));
    }

    private static double mean(double[] c) {
        return (c[0] + c[1] + c[2]) / 3;
    }

    /** Per-channel a/b (0 where b is 0): an ambient colour relative to the pigment k_d. */
    private static double[] ratio(double[] a, double[] b) {
        return new double[] {b[0] > 1e-9 ? a[0] / b[0] : 0, b[1] > 1e-9 ? a[1] / b[1] : 0, b[2] > 1e-9 ? a[2] / b[2] : 0};
    }

    /** The spec's camera frame u, v, w. */
    private static double[][] frame(Scene s) {
        double[] w = norm(sub(s.eye, s.target));
        double[] u = norm(cross(s.up, w));
        return new double[][] {u, cross(w, u), w};
    }

    /**
     * The area light's two edges, ordered so that edge1 x edge2 points to the camera's target (the side a
     * one-sided emitter must face): Sunflow's meshlight and Mitsuba's rectangle emit from their front only.
     */
    static double[][] facingEdges(Scene s) {
        double[] n = cross(s.edge1, s.edge2);
        return dot(n, sub(s.target, s.lightCentre)) >= 0 ? new double[][] {s.edge1, s.edge2} : new double[][] {s.edge2, s.edge1};
    }

    /** The cosine at the light between its normal and the direction to the camera's target. */
    static double cosToTarget(Scene s) {
        double[][] e = facingEdges(s);
        return dot(norm(cross(e[0], e[1])), norm(sub(s.target, s.lightCentre)));
    }

    private static double area(Scene s) {
        return Math.sqrt(dot(cross(s.edge1, s.edge2), cross(s.edge1, s.edge2)));
    }

    // ---- POV-Ray 3.7 ----

    /**
     * POV-Ray, translate.py's conventions (explicit camera vectors, I/d^2 through fade_power 2 with a tiny
     * fade_distance and the colour scaled by 1/(2 f^2), finish ambient k_a/k_d, specular roughness 1/p), and
     * the area light: {@code area_light} with n x n lights and no jitter or adaptive, so every shading point
     * tests all n^2; POV puts its lights from -axis/2 to +axis/2 inclusive, so the axes are the edges times
     * (n-1)/n, which puts them at our grid's cell centres; {@code area_illumination on} shades with each
     * light's own direction and distance, as ours does, instead of the centre's with a shadow fraction. The
     * mesh is a {@code mesh2} with the OBJ's vertices and normals (smooth triangles).
     */
    static void writePov(Scene s, Mesh m, Writer w) throws IOException {
        double[][] f3 = frame(s);
        double t = Math.tan(Math.toRadians(s.yFov) / 2), aspect = (double) s.width / s.height;
        double f = 1e-3, k = 1 / (2 * f * f);
        int n = s.lightSamples;
        w.write("// generated by ray.bench.Mesh1mPeers from " + LongScenes.MESH1M + ".txt (" + VERSION + ")\n#version 3.7;\n");
        w.write("global_settings { assumed_gamma 1.0 max_trace_level " + (s.maxDepth + 1) + " adc_bailout 0 ambient_light rgb "
                + pv(s.ambient) + " }\n");
        w.write("background { rgb " + pv(s.bg) + " }\n");
        w.write("camera { perspective location " + pv(s.eye) + " direction " + pv(scale(f3[2], -1)) + " right "
                + pv(scale(f3[0], 2 * t * aspect)) + " up " + pv(scale(f3[1], 2 * t)) + " }\n");
        double axis = n > 1 ? (n - 1.0) / n : 0;
        w.write("light_source { " + pv(s.lightCentre) + " color rgb " + pv(scale(s.intensity, k)) + " area_light "
                + pv(scale(s.edge1, axis)) + ", " + pv(scale(s.edge2, axis)) + ", " + n + ", " + n
                + " area_illumination on fade_distance " + g(f) + " fade_power 2 }\n");
        for (Map.Entry<String, double[][]> e : s.materials.entrySet()) {
            double[][] mat = e.getValue();
            StringBuilder fin = new StringBuilder("ambient rgb " + pv(ratio(mat[0], mat[1])) + " diffuse 1");
            if (mean(mat[2]) > 0) {
                fin.append(" specular ").append(g(mean(mat[2]))).append(" roughness ").append(g(1 / mat[3][0]));
            }
            w.write("#declare T_" + e.getKey() + " = texture { pigment { rgb " + pv(mat[1]) + " } finish { " + fin + " } }\n");
        }
        w.write("mesh2 {\n  vertex_vectors { " + m.v.size());
        for (String v : m.v) {
            w.write(",\n<" + v.replace(' ', ',') + ">");
        }
        w.write(" }\n");
        if (s.smooth && !m.vn.isEmpty()) {   // as many normals as vertices: face_indices index them too
            w.write("  normal_vectors { " + m.vn.size());
            for (String v : m.vn) {
                w.write(",\n<" + v.replace(' ', ',') + ">");
            }
            w.write(" }\n");
        }
        w.write("  face_indices { " + m.triangles);
        for (int i = 0; i < m.triangles; i++) {
            w.write(",\n<" + m.tri[3 * i] + "," + m.tri[3 * i + 1] + "," + m.tri[3 * i + 2] + ">");
        }
        w.write(" }\n  texture { T_" + s.meshMaterial + " }\n}\n");
        Map<String, StringBuilder> groups = new LinkedHashMap<>();
        for (int i = 0; i < s.triangles.size(); i++) {
            double[][] tr = s.triangles.get(i);
            groups.computeIfAbsent(s.triangleMaterials.get(i), x -> new StringBuilder())
                    .append("triangle{").append(pv(tr[0])).append(',').append(pv(tr[1])).append(',').append(pv(tr[2])).append("}\n");
        }
        for (Map.Entry<String, StringBuilder> e : groups.entrySet()) {
            w.write("mesh {\n" + e.getValue() + "texture { T_" + e.getKey() + " } }\n");
        }
    }

    private static String pv(double[] p) {
        return "<" + g(p[0]) + "," + g(p[1]) + "," + g(p[2]) + ">";
    }

    static String povIni(Scene s, String name) {
        return "; generated by ray.bench.Mesh1mPeers\nInput_File_Name=" + name + ".pov\nWidth=" + s.width * s.ns + "\nHeight="
                + s.height * s.ns + "\nAntialias=off\nOutput_File_Type=N\nOutput_Alpha=off\nDisplay=off\nVerbose=off\n"
                + "File_Gamma=1.0\nDisplay_Gamma=1.0\n";
    }

    // ---- Sunflow 0.07 ----

    /**
     * Sunflow, translate.py's conventions (horizontal fov, phong with exponent p/4 and its normalisation
     * undone, no ambient term, box filter without jitter), the mesh as a generic-mesh with vertex normals,
     * and the area light as a two-triangle {@code meshlight}: Sunflow samples each triangle of it on its own
     * (spherical-triangle sampling of the solid angle, quasi-random points), so n^2/2 samples per triangle
     * make n^2 shadow rays per shading point. It is a Lambertian emitter (radiance L: the light's cosine
     * enters), our area light is n^2 isotropic points: L = pi I / (A cos) with the cosine at the light toward
     * the camera's target makes the diffuse term k_d I/r^2 n.l exact there, as translate.py scales Tachyon's
     * highlights at the target.
     */
    static void writeSunflow(Scene s, Mesh m, Writer w) throws IOException {
        double aspect = (double) s.width / s.height;
        double hfov = Math.toDegrees(2 * Math.atan(aspect * Math.tan(Math.toRadians(s.yFov) / 2)));
        int aa = Integer.numberOfTrailingZeros(s.ns);
        if (Integer.bitCount(s.ns) != 1) {
            throw new IllegalArgumentException("AASamples must be a power of two for Sunflow's grid");
        }
        w.write("% generated by ray.bench.Mesh1mPeers from " + LongScenes.MESH1M + ".txt (" + VERSION + ")\n");
        w.write("image {\n  resolution " + s.width + " " + s.height + "\n  aa " + aa + " " + aa
                + "\n  samples 1\n  filter box\n  jitter false\n}\n");
        w.write("trace-depths {\n  diff 0\n  refl " + s.maxDepth + "\n  refr 0\n}\n");
        w.write("gi { type none }\n");
        w.write("background {\n  color " + sc(s.bg) + "\n}\n");
        w.write("camera {\n  type pinhole\n  eye " + sp(s.eye) + "\n  target " + sp(s.target) + "\n  up " + sp(s.up) + "\n  fov "
                + g(hfov) + "\n  aspect " + g(aspect) + "\n}\n");
        double[][] e = facingEdges(s);
        double[] c00 = sub(sub(s.lightCentre, scale(e[0], 0.5)), scale(e[1], 0.5));
        double[] c10 = add(c00, e[0]), c11 = add(c10, e[1]), c01 = add(c00, e[1]);
        double radianceScale = Math.PI / (area(s) * cosToTarget(s));
        int perTriangle = Math.max(1, s.lightSamples * s.lightSamples / 2);
        w.write("light {\n  type meshlight\n  name area\n  emit " + sc(scale(s.intensity, radianceScale)) + "\n  radiance 1\n  samples "
                + perTriangle + "\n  points 4\n    " + sp(c00) + "\n    " + sp(c10) + "\n    " + sp(c11) + "\n    " + sp(c01)
                + "\n  triangles 2\n    0 1 2\n    0 2 3\n}\n");
        for (Map.Entry<String, double[][]> me : s.materials.entrySet()) {
            double[][] mat = me.getValue();
            String body;
            if (Math.max(mat[2][0], Math.max(mat[2][1], mat[2][2])) > 0) {
                double pp = Math.max(1, mat[3][0] / 4);
                body = "type phong\n  diff " + sc(mat[1]) + "\n  spec " + sc(scale(mat[2], 2 / (pp + 2))) + " " + g(pp) + "\n  samples 0";
            } else {
                body = "type diffuse\n  diff " + sc(mat[1]);
            }
            w.write("shader {\n  name " + me.getKey() + "\n  " + body + "\n}\n");
        }
        w.write("object {\n  shader " + s.meshMaterial + "\n  type generic-mesh\n  name mesh\n  points " + m.v.size() + "\n");
        for (String v : m.v) {
            w.write("    " + v + "\n");
        }
        w.write("  triangles " + m.triangles + "\n");
        for (int i = 0; i < m.triangles; i++) {
            w.write("    " + m.tri[3 * i] + " " + m.tri[3 * i + 1] + " " + m.tri[3 * i + 2] + "\n");
        }
        if (s.smooth && !m.vn.isEmpty()) {
            w.write("  normals vertex\n");
            for (String v : m.vn) {
                w.write("    " + v + "\n");
            }
        } else {
            w.write("  normals none\n");
        }
        w.write("  uvs none\n}\n");
        for (int i = 0; i < s.triangles.size(); i++) {
            double[][] tr = s.triangles.get(i);
            w.write("object {\n  shader " + s.triangleMaterials.get(i) + "\n  type generic-mesh\n  name t" + i + "\n  points 3\n    "
                    + sp(tr[0]) + "\n    " + sp(tr[1]) + "\n    " + sp(tr[2]) + "\n  triangles 1\n    0 1 2\n  normals none\n  uvs none\n}\n");
        }
    }

    private static String sc(double[] c) {
        return "{ \"sRGB linear\" " + g(c[0]) + " " + g(c[1]) + " " + g(c[2]) + " }";
    }

    private static String sp(double[] p) {
        return g(p[0]) + " " + g(p[1]) + " " + g(p[2]);
    }

    // ---- Mitsuba 3 ----

    /**
     * Mitsuba 3, translate.py's conventions (perspective sensor, y fov, stratified sampler without jitter,
     * box filter, the spec's shading in the 'whittedmat' material, the 'whitted' integrator), the mesh read
     * from the OBJ file itself ({@code <shape type="obj">}: its vertex normals are the shading normals), and
     * the light as a {@code rectangle} with an {@code area} emitter of radiance I / A, which the bench's
     * {@link #MITSUBA_SCRIPT} samples at the n x n cell centres, dividing out the emitter's cosine: n^2 point
     * lights of I / n^2 each, falling off as r^-2, our grid sampler's light exactly.
     */
    static String mitsubaXml(Scene s, String meshPath, String name) {
        StringBuilder b = new StringBuilder();
        b.append("<?xml version=\"1.0\" encoding=\"utf-8\"?>\n<!-- generated by ray.bench.Mesh1mPeers from ").append(LongScenes.MESH1M)
                .append(".txt (").append(VERSION).append(") -->\n<scene version=\"3.0.0\">\n");
        b.append("  <integrator type=\"whitted\"><integer name=\"max_depth\" value=\"").append(s.maxDepth)
                .append("\"/><integer name=\"area_samples\" value=\"").append(s.lightSamples).append("\"/><vector name=\"ambient\" ")
                .append(mx(s.ambient)).append("/><vector name=\"background\" ").append(mx(s.bg)).append("/></integrator>\n");
        b.append("  <sensor type=\"perspective\"><float name=\"fov\" value=\"").append(g(s.yFov)).append("\"/><string name=\"fov_axis\" value=\"y\"/>\n");
        b.append("    <float name=\"near_clip\" value=\"0.0001\"/><float name=\"far_clip\" value=\"1e7\"/>\n");
        b.append("    <transform name=\"to_world\"><lookat origin=\"").append(mc(s.eye)).append("\" target=\"").append(mc(s.target))
                .append("\" up=\"").append(mc(s.up)).append("\"/></transform>\n");
        b.append("    <sampler type=\"stratified\"><integer name=\"sample_count\" value=\"").append(s.ns * s.ns)
                .append("\"/><boolean name=\"jitter\" value=\"false\"/></sampler>\n");
        b.append("    <film type=\"hdrfilm\"><integer name=\"width\" value=\"").append(s.width).append("\"/><integer name=\"height\" value=\"")
                .append(s.height).append("\"/><rfilter type=\"box\"/><string name=\"pixel_format\" value=\"rgb\"/></film>\n  </sensor>\n");
        double[][] e = facingEdges(s);
        double[] nrm = norm(cross(e[0], e[1]));
        double[] x = scale(e[0], 0.5), y = scale(e[1], 0.5), c = s.lightCentre;
        b.append("  <shape type=\"rectangle\"><transform name=\"to_world\"><matrix value=\"")
                .append(String.join(" ", g(x[0]), g(y[0]), g(nrm[0]), g(c[0]), g(x[1]), g(y[1]), g(nrm[1]), g(c[1]),
                        g(x[2]), g(y[2]), g(nrm[2]), g(c[2]), "0", "0", "0", "1"))
                .append("\"/></transform>\n    <emitter type=\"area\"><rgb name=\"radiance\" value=\"").append(mc(scale(s.intensity, 1 / area(s))))
                .append("\"/></emitter></shape>\n");
        for (Map.Entry<String, double[][]> me : s.materials.entrySet()) {
            double[][] m = me.getValue();
            b.append("  <bsdf type=\"whittedmat\" id=\"").append(me.getKey()).append("\"><vector name=\"ka\" ").append(mx(m[0]))
                    .append("/><vector name=\"kd\" ").append(mx(m[1])).append("/><vector name=\"ks\" ").append(mx(m[2]))
                    .append("/><float name=\"p\" value=\"").append(g(m[3][0])).append("\"/><float name=\"km\" value=\"0\"/></bsdf>\n");
        }
        b.append("  <shape type=\"obj\"><string name=\"filename\" value=\"").append(meshPath).append("\"/><boolean name=\"face_normals\" value=\"")
                .append(!s.smooth).append("\"/><ref id=\"").append(s.meshMaterial).append("\"/></shape>\n");
        for (String mat : new java.util.LinkedHashSet<>(s.triangleMaterials)) {
            b.append("  <shape type=\"obj\"><string name=\"filename\" value=\"").append(name).append('_')
                    .append(mat).append(".obj\"/><boolean name=\"face_normals\" value=\"true\"/><ref id=\"").append(mat).append("\"/></shape>\n");
        }
        return b.append("</scene>\n").toString();
    }

    private static String mx(double[] p) {
        return "x=\"" + g(p[0]) + "\" y=\"" + g(p[1]) + "\" z=\"" + g(p[2]) + "\"";
    }

    private static String mc(double[] p) {
        return g(p[0]) + "," + g(p[1]) + "," + g(p[2]);
    }

    /** The scene's single triangles as one OBJ text per material (name to text), for Mitsuba. */
    static Map<String, String> triangleObjs(Scene s) {
        Map<String, StringBuilder> vs = new LinkedHashMap<>(), fs = new LinkedHashMap<>();
        for (int i = 0; i < s.triangles.size(); i++) {
            String mat = s.triangleMaterials.get(i);
            StringBuilder v = vs.computeIfAbsent(mat, k -> new StringBuilder("# generated by ray.bench.Mesh1mPeers\n"));
            StringBuilder f = fs.computeIfAbsent(mat, k -> new StringBuilder());
            int first = f.length() == 0 ? 1 : 1 + 3 * (int) f.chars().filter(ch -> ch == '\n').count();
            for (double[] p : s.triangles.get(i)) {
                v.append("v ").append(sp(p)).append('\n');
            }
            f.append("f ").append(first).append(' ').append(first + 1).append(' ').append(first + 2).append('\n');
        }
        Map<String, String> out = new LinkedHashMap<>();
        for (String mat : vs.keySet()) {
            out.put(mat, vs.get(mat).append(fs.get(mat)).toString());
        }
        return out;
    }
}
