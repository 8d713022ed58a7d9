package ray.bench;

import java.awt.Color;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import javax.imageio.ImageIO;
import javax.vecmath.Vector3d;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;
import ray.Camera;
import ray.Scene;
import ray.accel.Bvh;
import ray.light.PointLight;
import ray.material.Diffuse;
import ray.render.Renderer;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * {@code gradle scaling}: how build time, render time and memory grow with the triangle count. A
 * bumpy tessellated sphere (like mesh100k's) of about 1 thousand to 1 million one-sided triangles,
 * 2 point lights, a 400x300 image at one sample per pixel. For each size, in one warmed-up JVM:
 * BVH build time (median of 3), render time after the build (median of 3, all cores), closest-hit
 * time per camera ray (1 thread), bytes per triangle of the BVH and its packed primitives
 * ({@link Bvh#memoryBytes()}), node visits and primitive tests per camera and per shadow ray (counted
 * in a separate JVM with {@code -Dray.bvh.count=true}, so the timings carry no counting), and heap
 * bytes per triangle of the scene's own objects (a
 * {@code Triangle} and its three {@code Vector3d}s). Prints a Markdown table and draws
 * {@code docs/images/scaling.png} (log axes), with reference curves proportional to log n and
 * n log n through the first point.
 */
public final class Scaling {

    /** One measured size. */
    static final class Row {
        int triangles;
        double buildMs, renderMs, nsPerRay, bvhBytes, sceneBytes;
        /** Per camera ray: node visits, primitive tests; per shadow ray: the same. */
        double[] work;
        int nodes;
    }

    private Scaling() {
    }

    /** A bumpy sphere of about {@code target} triangles, outward-facing, centred at the origin. */
    static List<Surface> mesh(int target, Diffuse material) {
        int slices = Math.max(8, (int) Math.round(Math.sqrt(target)));
        int stacks = Math.max(4, (int) Math.round(target / (2.0 * slices)) + 1);
        Vector3d[][] p = new Vector3d[stacks + 1][slices];
        for (int i = 0; i <= stacks; i++) {
            double th = Math.PI * i / stacks;
            for (int j = 0; j < slices; j++) {
                double ph = 2 * Math.PI * j / slices;
                double r = 1 + 0.08 * Math.sin(7 * th) * Math.cos(5 * ph) + 0.03 * Math.sin(23 * th + 17 * ph);
                p[i][j] = new Vector3d(r * Math.sin(th) * Math.cos(ph), r * Math.cos(th), r * Math.sin(th) * Math.sin(ph));
            }
        }
        List<Surface> out = new ArrayList<>();
        for (int i = 0; i < stacks; i++) {
            for (int j = 0; j < slices; j++) {
                int k = (j + 1) % slices;
                if (i > 0) {
                    out.add(tri(p[i][j], p[i][k], p[i + 1][j], material));
                }
                if (i < stacks - 1) {
                    out.add(tri(p[i][k], p[i + 1][k], p[i + 1][j], material));
                }
            }
        }
        return out;
    }

    private static Triangle tri(Vector3d a, Vector3d b, Vector3d c, Diffuse m) {
        Triangle t = new Triangle();
        // wound so that (b - a) x (c - a) points away from the centre
        Vector3d e = new Vector3d(), f = new Vector3d(), n = new Vector3d();
        e.sub(b, a);
        f.sub(c, a);
        n.cross(e, f);
        boolean outward = n.dot(a) > 0;
        t.v0 = new Vector3d(a);
        t.v1 = new Vector3d(outward ? b : c);
        t.v2 = new Vector3d(outward ? c : b);
        t.material = m;
        return t;
    }

    static Scene scene(List<Surface> surfaces, Diffuse material) {
        Scene s = new Scene();
        s.width = 400;
        s.height = 300;
        s.samplesPerPixel = 1;
        s.backgroundColor = new Vector3d(0.1, 0.1, 0.15);
        s.ambientLight = new Vector3d(0.1, 0.1, 0.1);
        s.camera = new Camera();
        s.camera.eye = new Vector3d(0.6, 0.9, 3.2);
        s.camera.target = new Vector3d(0, 0, 0);
        s.camera.yFOV = 40;
        s.materials.add(material);
        for (double[] l : new double[][] {{4, 5, 6}, {-5, 3, 2}}) {
            PointLight p = new PointLight();
            p.position = new Vector3d(l[0], l[1], l[2]);
            p.intensity = new Vector3d(40, 40, 40);
            s.lights.add(p);
        }
        s.surfaces = surfaces;
        return s;
    }

    private static double median(double[] v) {
        double[] a = v.clone();
        Arrays.sort(a);
        return a[a.length / 2];
    }

    private static long usedHeap() {
        Runtime rt = Runtime.getRuntime();
        for (int i = 0; i < 3; i++) {
            System.gc();
        }
        return rt.totalMemory() - rt.freeMemory();
    }

    static Row measure(int target) {
        Diffuse m = new Diffuse();
        m.diffuseColor = new Vector3d(0.7, 0.6, 0.5);
        m.ambientColor = new Vector3d(0.7, 0.6, 0.5);
        long h0 = usedHeap();
        List<Surface> tris = mesh(target, m);
        long h1 = usedHeap();
        Scene s = scene(tris, m);
        Row r = new Row();
        r.triangles = tris.size();
        r.sceneBytes = (double) (h1 - h0) / tris.size();
        double[] build = new double[3], render = new double[3];
        for (int i = 0; i < 3; i++) {
            long t0 = System.nanoTime();
            s.prepare();
            build[i] = (System.nanoTime() - t0) / 1e6;
        }
        Bvh bvh = (Bvh) s.accelerator();
        r.buildMs = median(build);
        r.bvhBytes = (double) bvh.memoryBytes() / bvh.primitiveCount();
        r.nodes = bvh.nodeCount();
        for (int i = 0; i < 3; i++) {
            Renderer renderer = new Renderer(s);
            long t0 = System.nanoTime();
            renderer.render();
            // the renderer rebuilds the BVH first (Scene.prepare): count only the rendering
            render[i] = (System.nanoTime() - t0) / 1e6 - ((Bvh) s.accelerator()).buildNanos() / 1e6;
        }
        r.renderMs = median(render);
        Throughput t = new Throughput(s);
        r.nsPerRay = 1e3 / t.closestHit(2, 5).mraysPerSecond();
        return r;
    }

    /** Node visits and primitive tests per camera ray (closest hit) and per shadow ray, from a JVM that counts. */
    static double[] work(int target) throws IOException {
        List<String> cmd = List.of(ProcessHandle.current().info().command().orElse("java"), "-Dray.bvh.count=true",
                "-Xmx3g", "-cp", System.getProperty("java.class.path"), Scaling.class.getName(), "--count", Integer.toString(target));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String text = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8).trim();
        try {
            if (p.waitFor() != 0) {
                throw new IOException("counting run failed: " + text);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException(e);
        }
        String[] f = text.split(" ");
        return new double[] {Double.parseDouble(f[0]), Double.parseDouble(f[1]), Double.parseDouble(f[2]), Double.parseDouble(f[3])};
    }

    /** {@code Scaling [maxTriangles] [png]}: measures and writes the plot. */
    public static void main(String[] args) throws IOException {
        if (args.length == 2 && args[0].equals("--count")) {
            Diffuse m = new Diffuse();
            Throughput t = new Throughput(scene(mesh(Integer.parseInt(args[1]), m), m));
            double[] c = t.workPerRay(ray.RayKind.CAMERA), s = t.workPerRay(ray.RayKind.SHADOW);
            System.out.println(String.format(Locale.ROOT, "%.3f %.3f %.3f %.3f", c[0], c[1], s[0], s[1]));
            return;
        }
        int max = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        Path png = Path.of(args.length > 1 ? args[1] : "docs/images/scaling.png");
        // warm-up: the JIT compiles parsing-free build, render and traversal code on small meshes first
        for (int i = 0; i < 3; i++) {
            measure(20_000);
        }
        List<Row> rows = new ArrayList<>();
        for (int n : new int[] {1_000, 3_000, 10_000, 30_000, 100_000, 300_000, 1_000_000}) {
            if (n > max) {
                break;
            }
            Row r = measure(n);
            r.work = work(n);
            rows.add(r);
            System.err.println(String.format(Locale.ROOT, "%,d triangles done", r.triangles));
        }
        System.out.println("| triangles | BVH inner nodes | build ms | build ns / (n log2 n) | render ms (400x300, all cores) "
                + "| closest hit ns/ray (1 thread) | node visits / tests per camera ray | per shadow ray "
                + "| BVH + primitives bytes/triangle | scene objects bytes/triangle |");
        System.out.println("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
        for (Row r : rows) {
            double nlogn = r.triangles * Math.log(r.triangles) / Math.log(2);
            System.out.println(String.format(Locale.ROOT, "| %,d | %,d | %.1f | %.2f | %.1f | %.0f | %.1f / %.1f | %.1f / %.1f | %.1f | %.0f |",
                    r.triangles, r.nodes, r.buildMs, 1e6 * r.buildMs / nlogn, r.renderMs, r.nsPerRay, r.work[0], r.work[1],
                    r.work[2], r.work[3], r.bvhBytes, r.sceneBytes));
        }
        plot(rows, png);
        System.out.println();
        System.out.println("plot: " + png);
    }

    static void plot(List<Row> rows, Path png) throws IOException {
        double[] n = rows.stream().mapToDouble(r -> r.triangles).toArray();
        double[] build = rows.stream().mapToDouble(r -> r.buildMs).toArray();
        double[] render = rows.stream().mapToDouble(r -> r.renderMs).toArray();
        double[] perRay = rows.stream().mapToDouble(r -> r.nsPerRay / 1e3).toArray();   // microseconds
        double[] bvh = rows.stream().mapToDouble(r -> r.bvhBytes).toArray();
        double[] objects = rows.stream().mapToDouble(r -> r.sceneBytes).toArray();
        double[] logRef = new double[n.length], nlognRef = new double[n.length];
        for (int i = 0; i < n.length; i++) {
            logRef[i] = render[0] * Math.log(n[i]) / Math.log(n[0]);
            nlognRef[i] = build[0] * n[i] * Math.log(n[i]) / (n[0] * Math.log(n[0]));
        }
        XYChart time = new XYChartBuilder().width(640).height(480).title("Time against triangle count")
                .xAxisTitle("triangles").yAxisTitle("milliseconds (closest hit: microseconds per ray)").build();
        time.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true).setLegendPosition(Styler.LegendPosition.InsideSE)
                .setChartBackgroundColor(Color.WHITE).setMarkerSize(7);
        time.addSeries("BVH build", n, build).setMarker(SeriesMarkers.CIRCLE);
        time.addSeries("render 400x300 (after build)", n, render).setMarker(SeriesMarkers.SQUARE);
        time.addSeries("closest hit per camera ray (us)", n, perRay).setMarker(SeriesMarkers.DIAMOND);
        time.addSeries("node visits per camera ray (count)", n, rows.stream().mapToDouble(r -> r.work[0]).toArray())
                .setMarker(SeriesMarkers.TRIANGLE_UP);
        XYSeries a = time.addSeries("c * n log n", n, nlognRef);
        a.setMarker(SeriesMarkers.NONE).setLineStyle(new java.awt.BasicStroke(1.5f, java.awt.BasicStroke.CAP_BUTT,
                java.awt.BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
        XYSeries b = time.addSeries("c * log n", n, logRef);
        b.setMarker(SeriesMarkers.NONE).setLineStyle(new java.awt.BasicStroke(1.5f, java.awt.BasicStroke.CAP_BUTT,
                java.awt.BasicStroke.JOIN_MITER, 10, new float[] {6, 4}, 0));
        XYChart mem = new XYChartBuilder().width(640).height(480).title("Memory per triangle")
                .xAxisTitle("triangles").yAxisTitle("bytes per triangle").build();
        mem.getStyler().setXAxisLogarithmic(true).setYAxisLogarithmic(true).setLegendPosition(Styler.LegendPosition.InsideNE)
                .setChartBackgroundColor(Color.WHITE).setMarkerSize(7);
        mem.getStyler().setYAxisMin(10.0);
        mem.getStyler().setYAxisMax(1000.0);
        mem.addSeries("BVH + packed triangles", n, bvh).setMarker(SeriesMarkers.CIRCLE);
        mem.addSeries("scene objects (Triangle + 3 Vector3d)", n, objects).setMarker(SeriesMarkers.SQUARE);
        BufferedImage left = BitmapEncoder.getBufferedImage(time), right = BitmapEncoder.getBufferedImage(mem);
        BufferedImage both = new BufferedImage(left.getWidth() + right.getWidth(), Math.max(left.getHeight(), right.getHeight()),
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = both.createGraphics();
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, both.getWidth(), both.getHeight());
        g.drawImage(left, 0, 0, null);
        g.drawImage(right, left.getWidth(), 0, null);
        g.dispose();
        Files.createDirectories(png.toAbsolutePath().getParent());
        ImageIO.write(both, "png", png.toFile());
    }
}
