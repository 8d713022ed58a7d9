package ray.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import ray.Scene;
import ray.accel.Bvh;
import ray.parse.Parser;
import ray.render.Renderer;
import ray.surface.Mesh;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * {@code gradle meshLoad [-PmeshQuads=500000]}: writes a bumpy sphere of quads (1 million triangles
 * after fanning, with vertex normals) as an OBJ file into a temporary folder, and measures in this
 * JVM (default heap): the time to read it through a scene file (OBJ reading, checking, fanning), the
 * heap it holds, the BVH build time and bytes, and the render time of a 400x300 image against the
 * same triangles as built-in {@code Triangle} objects (interleaved, best of 3). Prints a Markdown table.
 */
public final class MeshLoad {

    private MeshLoad() {
    }

    public static void main(String[] args) throws Exception {
        int quads = args.length > 0 ? Integer.parseInt(args[0]) : 500_000;
        Path dir = Files.createTempDirectory("meshload");
        try {
            run(dir, quads);
        } finally {
            try (var s = Files.list(dir)) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    Files.delete(p);
                }
            }
            Files.delete(dir);
        }
    }

    private static void run(Path dir, int quads) throws Exception {
        int[] g = BumpyMesh.grid(quads);
        Path obj = dir.resolve("bumpy.obj");
        BumpyMesh.writeObj(obj, g[0], g[1]);
        String scene = "Width 400\nHeight 300\nAmbientLight [0.1 0.1 0.1]\n\nCamera Camera\nVector3d eye [0 0.5 3.2]\n\n"
                + "Light PointLight\nVector3d position [3 4 5]\nVector3d intensity [30 30 30]\n\n"
                + "Material Diffuse grey\nVector3d diffuseColor [0.7 0.7 0.7]\n\n"
                + "Surface Mesh\nString file bumpy.obj\nref material grey\nint smooth 0\n";
        Path sceneFile = dir.resolve("scene.txt");
        Files.writeString(sceneFile, scene);
        long objBytes = Files.size(obj);

        long heap0 = usedHeap();
        long t0 = System.nanoTime();
        Scene s = Parser.parse(sceneFile);
        double loadS = (System.nanoTime() - t0) / 1e9;
        Mesh mesh = (Mesh) s.surfaces.get(0);
        int n = mesh.triangleCount();
        long heapMesh = usedHeap() - heap0;
        t0 = System.nanoTime();
        s.prepare();
        double buildS = (System.nanoTime() - t0) / 1e9;
        long heapAll = usedHeap() - heap0;
        Bvh bvh = (Bvh) s.accelerator();

        // the same triangles as Triangle objects, for the render-time ratio
        Scene t = Parser.parse(sceneFile);
        List<Surface> tris = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            Triangle tr = new Triangle();
            mesh.corner(i, 0, tr.v0);
            mesh.corner(i, 1, tr.v1);
            mesh.corner(i, 2, tr.v2);
            tr.material = mesh.material;
            tris.add(tr);
        }
        t.surfaces = tris;
        t.prepare();
        double meshRender = Double.POSITIVE_INFINITY, triRender = Double.POSITIVE_INFINITY;
        for (int k = 0; k < 3; k++) {
            meshRender = Math.min(meshRender, time(s));
            triRender = Math.min(triRender, time(t));
        }
        System.out.println("| triangles | OBJ file | read (parse, check, fan) | heap held by the mesh | BVH build "
                + "| BVH + packed triangles | heap after build | render 400x300, mesh | same as Triangle objects | ratio |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|");
        System.out.println(String.format(Locale.ROOT, "| %,d | %.1f MB | %.2f s | %.1f B/triangle | %.2f s | %.1f B/triangle "
                        + "| %.1f B/triangle | %.3f s | %.3f s | %.2f |",
                n, objBytes / 1e6, loadS, (double) heapMesh / n, buildS, (double) bvh.memoryBytes() / n,
                (double) heapAll / n, meshRender, triRender, meshRender / triRender));
        System.out.println("max heap " + (Runtime.getRuntime().maxMemory() >> 20) + " MiB, "
                + Runtime.getRuntime().availableProcessors() + " cores");
    }

    private static double time(Scene s) {
        long t0 = System.nanoTime();
        new Renderer(s).render();
        return (System.nanoTime() - t0) / 1e9;
    }

    private static long usedHeap() throws InterruptedException {
        Runtime r = Runtime.getRuntime();
        for (int i = 0; i < 3; i++) {
            System.gc();
            Thread.sleep(50);
        }
        return r.totalMemory() - r.freeMemory();
    }
}
