import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.lang.reflect.Field;
import java.lang.reflect.Modifier;
import java.nio.file.Files;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import javax.imageio.ImageIO;
import javax.vecmath.Vector3d;

/**
 * The program: {@code java RayTracer scene.txt [more.txt ...]} renders each scene to a PNG of the
 * same name beside it (scene.png); with no arguments the viewer ({@link ViewingFrame}) opens, and
 * {@code java RayTracer --view scene.txt} opens it on that scene.
 * Given: not one of the methods you write.
 *
 * <p>It also checks your colours: where a method returns null or a colour with NaN in it, the render
 * stops with one line naming the method and the pixel, e.g.
 * {@code scenes/x.txt: Diffuse.shade returned null for pixel (12, 40)}, instead of a silently black
 * or broken image.
 */
public class RayTracer {

    /** A render that went wrong in one of your methods: the message is one line naming the method and the pixel. */
    public static class RenderException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        public RenderException(String message) {
            super(message, null, false, false);
        }
    }

    public static void main(String[] args) {
        if (args.length == 0 || args[0].equals("--view")) {
            ViewingFrame.open(args.length > 1 ? new File(args[1]) : null);
            return;
        }
        int failed = 0;
        for (String name : args) {
            try {
                File png = renderToFile(new File(name));
                System.out.println(name + " -> " + png.getPath());
            } catch (Parser.SceneFormatException e) {
                System.err.println(e.getMessage());
                failed++;
            } catch (RenderException | IOException e) {
                System.err.println(name + ": " + e.getMessage());
                failed++;
            }
        }
        System.exit(failed == 0 ? 0 : 1);
    }

    /** Reads {@code sceneFile}, renders it and writes the PNG beside it (x.txt to x.png); returns the PNG. */
    public static File renderToFile(File sceneFile) throws Parser.SceneFormatException, IOException {
        Scene scene = Parser.parse(sceneFile);
        prepare(scene);
        Vector3d[][] image = render(scene);
        String name = sceneFile.getName();
        int dot = name.lastIndexOf('.');
        File png = new File(sceneFile.getAbsoluteFile().getParentFile(), (dot > 0 ? name.substring(0, dot) : name) + ".png");
        writePng(image, png);
        return png;
    }

    /** Calls your {@link Camera#recalculate()} on a freshly read scene; a failure there is reported like any other. */
    public static void prepare(Scene scene) {
        try {
            scene.camera.recalculate();
        } catch (RuntimeException | StackOverflowError e) {
            throw new RenderException(threw("Camera.recalculate", e, null));
        }
    }

    /**
     * Renders {@code scene} with your {@link Scene#renderAll()} and checks the result: width x height,
     * every pixel a colour of finite numbers. Where something is wrong, finds the method at fault
     * (see {@link #diagnose}) and throws a {@link RenderException} naming it and the pixel.
     */
    public static Vector3d[][] render(Scene scene) {
        Vector3d[][] pixels;
        try {
            pixels = scene.renderAll();
        } catch (RuntimeException | StackOverflowError e) {
            String found = diagnoseAll(scene);
            throw new RenderException(found != null ? found : threw("Scene.renderAll", e, null));
        }
        if (pixels == null) {
            String found = diagnoseAll(scene);
            throw new RenderException(found != null ? found : "Scene.renderAll returned null (expected a new Vector3d["
                    + scene.width + "][" + scene.height + "])");
        }
        if (pixels.length != scene.width) {
            throw new RenderException("Scene.renderAll returned an array of " + pixels.length + " columns (expected pixels[x][y] with "
                    + scene.width + " columns, x from 0 to Width - 1)");
        }
        for (int x = 0; x < scene.width; x++) {
            if (pixels[x] == null || pixels[x].length != scene.height) {
                throw new RenderException("Scene.renderAll returned column " + x + " with " + (pixels[x] == null ? "null"
                        : pixels[x].length + " rows") + " (expected " + scene.height + " rows, y from 0 to Height - 1)");
            }
        }
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                String bad = badColor(pixels[x][y]);
                if (bad != null) {
                    String found = diagnose(scene, x, y);
                    throw new RenderException(found != null ? found : "Scene.renderAll returned " + bad + " for pixel "
                            + pixel(x, y) + ", although renderPixel" + pixel(x, y) + " returns a colour");
                }
            }
        }
        return pixels;
    }

    /**
     * Renders pixel (x, y) with your {@link Scene#renderPixel} under the checks of {@link #diagnose}: the
     * colour, or a {@link RenderException} naming the method at fault. The viewer uses this.
     */
    public static Vector3d renderPixelChecked(Scene scene, int x, int y) {
        Vector3d c;
        try {
            c = scene.renderPixel(x, y);
        } catch (RuntimeException | StackOverflowError e) {
            String found = diagnose(scene, x, y);
            throw new RenderException(found != null ? found : threw("Scene.renderPixel", e, pixel(x, y)));
        }
        String bad = badColor(c);
        if (bad != null) {
            String found = diagnose(scene, x, y);
            throw new RenderException(found != null ? found : "Scene.renderPixel returned " + bad + " for pixel " + pixel(x, y));
        }
        return c;
    }

    /** Looks for the first pixel (row by row) at which one of the methods fails; its message, or null. */
    private static String diagnoseAll(Scene scene) {
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                String found = diagnose(scene, x, y);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    /**
     * Finds which method goes wrong at pixel (x, y), trying them in the order a colour is made:
     * Camera.getRayThrough for the pixel's centre, then Scene.trace of that ray (with every material's
     * shade and every light's getIntensity checked as trace calls them, and the record each shade
     * receives checked for the surface that filled it), then Scene.renderPixel. Returns a one-line
     * message naming the method and the pixel, or null when all of them return sound colours.
     */
    public static String diagnose(Scene scene, int x, int y) {
        String where = pixel(x, y);
        Ray ray;
        try {
            ray = scene.camera.getRayThrough(x + 0.5, y + 0.5, scene.width, scene.height);
        } catch (RuntimeException | StackOverflowError e) {
            return threw("Camera.getRayThrough", e, where);
        }
        if (ray == null) {
            return "Camera.getRayThrough returned null for pixel " + where + " (expected a new Ray)";
        }
        if (ray.origin == null || ray.direction == null || !finite(ray.origin) || !finite(ray.direction)
                || ray.direction.lengthSquared() == 0) {
            return "Camera.getRayThrough returned a ray with origin " + ray.origin + " and direction " + ray.direction
                    + " for pixel " + where + " (did Camera.recalculate set u, v and w?)";
        }
        Checks checks = new Checks(scene, where);
        try {
            checks.install();
            Vector3d c;
            try {
                c = scene.trace(ray);
            } catch (RenderException e) {
                return e.getMessage();
            } catch (RuntimeException | StackOverflowError e) {
                return threw("Scene.trace", e, where);
            }
            String bad = badColor(c);
            if (bad != null) {
                return "Scene.trace returned " + bad + " for the ray through the centre of pixel " + where;
            }
            try {
                c = scene.renderPixel(x, y);
            } catch (RenderException e) {
                return e.getMessage();
            } catch (RuntimeException | StackOverflowError e) {
                return threw("Scene.renderPixel", e, where);
            }
            bad = badColor(c);
            if (bad != null) {
                return "Scene.renderPixel returned " + bad + " for pixel " + where;
            }
            return null;
        } finally {
            checks.remove();
        }
    }

    /**
     * While {@link #diagnose} runs: every material a surface (or another material, such as a Glazed
     * base) refers to and every light of the scene is replaced by a checking stand-in that calls the
     * original and checks what it returns. Put back afterwards.
     */
    private static final class Checks {
        private final Scene scene;
        private final String where;
        private final List<Runnable> undo = new ArrayList<>();
        private final Map<Material, Material> wrapped = new IdentityHashMap<>();

        Checks(Scene scene, String where) {
            this.scene = scene;
            this.where = where;
        }

        void install() {
            for (Surface s : scene.surfaces) {
                Material original = s.material;
                s.material = wrap(original);
                undo.add(() -> s.material = original);
            }
            for (int i = 0; i < scene.lights.size(); i++) {
                Light original = scene.lights.get(i);
                int index = i;
                scene.lights.set(i, new CheckedLight(original, where));
                undo.add(() -> scene.lights.set(index, original));
            }
        }

        void remove() {
            for (int i = undo.size() - 1; i >= 0; i--) {
                undo.get(i).run();
            }
        }

        /** The checking stand-in for {@code m}, its Material fields (a Glazed base) wrapped too. */
        private Material wrap(Material m) {
            if (m == null || m instanceof CheckedMaterial) {
                return m;
            }
            Material w = wrapped.get(m);
            if (w != null) {
                return w;
            }
            w = new CheckedMaterial(m, where);
            wrapped.put(m, w);
            for (Class<?> k = m.getClass(); k != Material.class && k != null; k = k.getSuperclass()) {
                for (Field f : k.getDeclaredFields()) {
                    if (f.getType() == Material.class && !Modifier.isStatic(f.getModifiers()) && !Modifier.isFinal(f.getModifiers())) {
                        try {
                            f.setAccessible(true);
                            Material inner = (Material) f.get(m);
                            if (inner != null) {
                                f.set(m, wrap(inner));
                                undo.add(() -> {
                                    try {
                                        f.set(m, inner);
                                    } catch (IllegalAccessException e) {
                                        throw new IllegalStateException(e);
                                    }
                                });
                            }
                        } catch (IllegalAccessException | RuntimeException e) {
                            // a field we cannot reach stays as it is: only that check is lost
                        }
                    }
                }
            }
            return w;
        }
    }

    /** A material that calls the original's shade and checks the record it gets and the colour it returns. */
    private static final class CheckedMaterial extends Material {
        private final Material inner;
        private final String where;

        CheckedMaterial(Material inner, String where) {
            this.inner = inner;
            this.where = where;
        }

        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            String surface = record == null || record.surface == null ? "Surface" : record.surface.getClass().getSimpleName();
            if (record != null && (record.location == null || record.normal == null || !finite(record.location) || !finite(record.normal)
                    || Math.abs(record.normal.lengthSquared() - 1) > 1e-6 || !(record.t >= ray.tMin && record.t <= ray.tMax))) {
                throw new RenderException(surface + ".intersects filled the record wrongly for pixel " + where + ": t " + record.t
                        + ", location " + record.location + ", normal " + record.normal
                        + " (expected t within the ray's span, a finite location and a unit-length normal)");
            }
            return checked(inner.getClass().getSimpleName() + ".shade", where, () -> inner.shade(ray, record, scene),
                    " (shading the " + surface + " at " + record.location + ")");
        }
    }

    /** A light that calls the original and checks what its getIntensity and getDirection return. */
    private static final class CheckedLight extends Light {
        private final Light inner;
        private final String where;

        CheckedLight(Light inner, String where) {
            this.inner = inner;
            this.where = where;
        }

        @Override
        public Vector3d getIntensity(IntersectionRecord record, Scene scene) {
            return checked(inner.getClass().getSimpleName() + ".getIntensity", where, () -> inner.getIntensity(record, scene),
                    " (at " + record.location + ")");
        }

        @Override
        public Vector3d getDirection(IntersectionRecord record) {
            return inner.getDirection(record);
        }
    }

    /**
     * Calls one of the student's colour methods ({@code name}, e.g. "Diffuse.shade"): its colour, or a
     * RenderException naming it when it throws or returns null or NaN.
     */
    private static Vector3d checked(String name, String where, java.util.function.Supplier<Vector3d> call, String context) {
        Vector3d c;
        try {
            c = call.get();
        } catch (RenderException e) {
            throw e;
        } catch (RuntimeException | StackOverflowError e) {
            throw new RenderException(threw(name, e, where));
        }
        String bad = badColor(c);
        if (bad != null) {
            throw new RenderException(name + " returned " + bad + " for pixel " + where + context);
        }
        return c;
    }

    /** Why {@code c} is not a colour ("null", "NaN in (NaN, 0.5, 0.1)"), or null when it is one. */
    static String badColor(Vector3d c) {
        if (c == null) {
            return "null";
        }
        if (Double.isNaN(c.x) || Double.isNaN(c.y) || Double.isNaN(c.z)) {
            return "a NaN colour " + c;
        }
        if (Double.isInfinite(c.x) || Double.isInfinite(c.y) || Double.isInfinite(c.z)) {
            return "an infinite colour " + c;
        }
        return null;
    }

    private static boolean finite(Vector3d v) {
        return Double.isFinite(v.x) && Double.isFinite(v.y) && Double.isFinite(v.z);
    }

    private static String pixel(int x, int y) {
        return "(" + x + ", " + y + ")";
    }

    /** "Diffuse.shade threw NullPointerException (message) at Diffuse.shade(Diffuse.java:40) for pixel (x, y)". */
    static String threw(String method, Throwable e, String where) {
        String at = "";
        for (StackTraceElement f : e.getStackTrace()) {
            String c = f.getClassName();
            if (!(c.startsWith("java.") || c.startsWith("javax.") || c.startsWith("jdk.") || c.startsWith("sun."))) {
                at = " at " + f;
                break;
            }
        }
        String msg = e.getMessage() == null ? "" : " (" + e.getMessage().replaceAll("\\s+", " ") + ")";
        if (e instanceof StackOverflowError) {
            msg = " (a method that calls itself without end: does every mirror ray get depth + 1, and does Scene.trace stop"
                    + " past MaxDepth?)";
        }
        return method + " threw " + e.getClass().getSimpleName() + msg + at + (where == null ? "" : " for pixel " + where);
    }

    /**
     * The PNG of {@code image}: each channel clamped to [0, 1] and rounded to the nearest of 0..255
     * (floor(255 v + 0.5)), no gamma. Written to a temporary file first, so a failed write leaves no
     * broken PNG.
     */
    public static void writePng(Vector3d[][] image, File png) throws IOException {
        File dir = png.getAbsoluteFile().getParentFile();
        File tmp = File.createTempFile(".render-", ".png", dir);
        try {
            if (!ImageIO.write(toImage(image), "png", tmp)) {
                throw new IOException("no PNG writer");
            }
            Files.move(tmp.toPath(), png.toPath(), StandardCopyOption.REPLACE_EXISTING);
        } finally {
            Files.deleteIfExists(tmp.toPath());
        }
    }

    /** The 8-bit image of {@code image[x][y]} (clamped, rounded, no gamma). */
    public static BufferedImage toImage(Vector3d[][] image) {
        int w = image.length, h = w == 0 ? 0 : image[0].length;
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int x = 0; x < w; x++) {
            for (int y = 0; y < h; y++) {
                out.setRGB(x, y, rgb(image[x][y]));
            }
        }
        return out;
    }

    /** One colour as 0xRRGGBB. */
    public static int rgb(Vector3d c) {
        return (channel(c.x) << 16) | (channel(c.y) << 8) | channel(c.z);
    }

    private static int channel(double v) {
        double clamped = v < 0 ? 0 : v > 1 ? 1 : v;
        return (int) Math.floor(255 * clamped + 0.5);
    }
}
