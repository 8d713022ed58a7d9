package ray.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.vecmath.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.app.MainBadInputTest.Run;
import ray.material.BlinnPhong;
import ray.material.DielectricMaterial;
import ray.material.Diffuse;
import ray.material.GlazedMaterial;
import ray.material.Material;

/**
 * Issue 15: a user's shade() that returns null or a NaN colour stops the render with one line naming the
 * class, the method and the pixel, a non-zero status and no PNG (it was a silently black pixel, status 0).
 */
class UserColorTest {

    @TempDir
    Path dir;

    /** Null in the upper right quarter of the image (x > 0, y > 0 on the plane z = 0 seen from +z), grey elsewhere. */
    public static class NullThere extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return record.location.x > 0 && record.location.y > 0 ? null : new Vector3d(0.5, 0.5, 0.5);
        }
    }

    /** NaN in the lower left quarter: 0/0 in green. */
    public static class NaNThere extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            double zero = record.location.x < 0 && record.location.y < 0 ? 0 : 1;
            return new Vector3d(0.5, zero / zero, 0.5);
        }
    }

    /** Large colours, infinite ones included, are colours (clamped in the PNG), not mistakes. */
    public static class Bright extends Material {
        @Override
        public Vector3d shade(Ray ray, IntersectionRecord record, Scene scene) {
            return new Vector3d(Double.POSITIVE_INFINITY, 7, -3);
        }
    }

    /** A 40 x 30 image filled by two triangles in the plane z = 0 with the user's material. */
    private Path scene(String material) throws IOException {
        Path p = dir.resolve(material + ".txt");
        Files.writeString(p, "Width 40\nHeight 30\n\nCamera Camera\nVector3d eye [0 0 1]\ndouble yFOV 90\n\n"
                + "Material ray.app.UserColorTest$" + material + " m\n\n"
                + "Surface Triangle\nVector3d v0 [-9 -9 0]\nVector3d v1 [9 -9 0]\nVector3d v2 [9 9 0]\nref material m\n\n"
                + "Surface Triangle\nVector3d v0 [-9 -9 0]\nVector3d v1 [9 9 0]\nVector3d v2 [-9 9 0]\nref material m\n");
        return p;
    }

    /** The one error line for {@code material}'s scene, checked to be one line, status 1 and no PNG; returns the pixel. */
    private int[] fails(String material, String returned) throws IOException {
        Path s = scene(material);
        Run r = MainBadInputTest.run("-q", s.toString());
        assertEquals(1, r.status(), r.err());
        assertEquals(1, r.errLines().size(), "one line, no stack trace:\n" + r.err());
        Matcher m = Pattern.compile(Pattern.quote(s + ": rendering failed: UserColorTest$" + material + ".shade returned " + returned)
                + " for pixel \\((\\d+), (\\d+)\\) \\(expected a Vector3d of numbers\\)").matcher(r.errLines().get(0));
        assertTrue(m.matches(), r.errLines().get(0));
        assertFalse(Files.exists(dir.resolve(material + ".png")), "no PNG from a failed render");
        return new int[] {Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2))};
    }

    @Test
    void nullNamesTheClassMethodAndPixel() throws IOException {
        int[] p = fails("NullThere", "null");
        assertTrue(p[0] >= 20 && p[1] < 15, "the pixel is in the upper right quarter, where shade returns null: " + p[0] + ", " + p[1]);
    }

    @Test
    void nanNamesTheClassMethodAndPixel() throws IOException {
        int[] p = fails("NaNThere", "a NaN colour (0.5, NaN, 0.5)");
        assertTrue(p[0] < 20 && p[1] >= 15, "the pixel is in the lower left quarter, where shade returns NaN: " + p[0] + ", " + p[1]);
    }

    @Test
    void infiniteAndOutOfRangeColoursStillRender() throws IOException {
        Path s = scene("Bright");
        Run r = MainBadInputTest.run("-q", s.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.size(dir.resolve("Bright.png")) > 0);
    }

    /** The check is in the framework form's path only: every built-in material shades on its own fast path. */
    @Test
    void builtInMaterialsNeverPassTheCheck() throws NoSuchMethodException {
        for (Class<?> c : new Class<?>[] {Diffuse.class, BlinnPhong.class, GlazedMaterial.class, DielectricMaterial.class}) {
            Class<?> declaring = c.getMethod("shade", Ray.class, IntersectionRecord.class, Scene.class, TraceContext.class, Vector3d.class)
                    .getDeclaringClass();
            assertTrue(declaring != Material.class, c.getSimpleName() + " overrides the allocation-free shade");
        }
    }
}
