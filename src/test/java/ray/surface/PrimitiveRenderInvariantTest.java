package ray.surface;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import ray.Scene;
import ray.parse.Parser;
import ray.render.Image;
import ray.render.Renderer;

/**
 * Images a wrong primitive cannot produce: a Box renders as the 12 outward triangles that bound it, and
 * a Disc renders, wherever it is seen, exactly as the Plane it lies in. Lit by a point light, shadows
 * on a floor and a mirror sphere reflecting the shape, so shadow and mirror rays take part too.
 */
class PrimitiveRenderInvariantTest {

    private static final String SETTING = """
            Width 96
            Height 72
            BGColor [0.1 0.2 0.3]
            AmbientLight [0.2 0.2 0.2]

            Camera Camera
            Vector3d eye [2.2 1.9 3.3]
            Vector3d target [-0.4 0.3 -0.2]
            double yFOV 50

            Material BlinnPhong shape
            Vector3d ambientColor [0.1 0.05 0.05]
            Vector3d diffuseColor [0.7 0.3 0.2]
            Vector3d specularColor [0.5 0.5 0.5]
            double exponent 30

            Material Diffuse floorMaterial
            Vector3d ambientColor [0.1 0.1 0.1]
            Vector3d diffuseColor [0.6 0.6 0.6]

            Material GlazedMaterial mirror
            double mirrorCoefficient 0.8

            Surface Sphere
            Vector3d center [-1.9 0.3 -1.2]
            double radius 0.8
            ref material mirror

            Light PointLight
            Vector3d position [2.5 4.5 3.5]
            Vector3d intensity [25 25 25]

            """;

    private static Image render(String text) throws Exception {
        List<String> warnings = new ArrayList<>();
        Scene s = Parser.parse(text, "invariant.txt", warnings);
        assertEquals(List.of(), warnings);
        Renderer r = new Renderer(s).threads(2);
        Image img = r.render();
        assertEquals(0, r.stats().invalidSamples);
        return img;
    }

    private static String triangle(double[] a, double[] b, double[] c) {
        return "Surface Triangle\nVector3d v0 " + vec(a) + "\nVector3d v1 " + vec(b) + "\nVector3d v2 " + vec(c)
                + "\nref material shape\n\n";
    }

    private static String vec(double[] v) {
        return "[" + v[0] + " " + v[1] + " " + v[2] + "]";
    }

    /** The 12 triangles of the box [lo, hi], each facing outward (counter-clockwise seen from outside). */
    static String boxTriangles(double[] lo, double[] hi) {
        StringBuilder sb = new StringBuilder();
        for (int axis = 0; axis < 3; axis++) {
            int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            for (int side = 0; side < 2; side++) {
                double[][] q = new double[4][3];
                double[][] uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                for (int k = 0; k < 4; k++) {
                    q[k][axis] = side == 0 ? lo[axis] : hi[axis];
                    // on the max face (a1, a2) runs counter-clockwise seen from outside; on the min face, reversed
                    double u = uv[k][side == 0 ? 1 : 0], v = uv[k][side == 0 ? 0 : 1];
                    q[k][a1] = u == 0 ? lo[a1] : hi[a1];
                    q[k][a2] = v == 0 ? lo[a2] : hi[a2];
                }
                sb.append(triangle(q[0], q[1], q[2])).append(triangle(q[0], q[2], q[3]));
            }
        }
        return sb.toString();
    }

    /**
     * Every pixel equal to its 8-bit value: the slab test and the watertight triangles find the same
     * points up to rounding and the same axis normals, so shading, shadows and the reflection agree.
     */
    @Test
    void boxRendersAsTheTwelveOutwardTrianglesThatBoundIt() throws Exception {
        double[] lo = {-0.7, 0, -0.4}, hi = {0.9, 1.3, 0.6};
        String floor = "Surface Plane\nVector3d point [0 0 0]\nVector3d normal [0 1 0]\nref material floorMaterial\n\n";
        Image box = render(SETTING + floor + "Surface Box\nVector3d minPoint " + vec(lo) + "\nVector3d maxPoint " + vec(hi)
                + "\nref material shape\n\n");
        Image tris = render(SETTING + floor + boxTriangles(lo, hi));
        int differ = 0, boxPixels = 0;
        for (int i = 0; i < box.width * box.height; i++) {
            for (int k = 0; k < 3; k++) {
                if (Image.toByte(box.rgb[3 * i + k]) != Image.toByte(tris.rgb[3 * i + k])) {
                    differ++;
                    break;
                }
            }
        }
        Image without = render(SETTING + floor);
        for (int i = 0; i < box.width * box.height; i++) {
            if (box.rgb[3 * i] != without.rgb[3 * i]) {
                boxPixels++;
            }
        }
        assertTrue(boxPixels > 1000, "the box (and its shadow and reflection) covers " + boxPixels + " pixels");
        assertEquals(0, differ, "pixels where the Box differs from its 12 triangles");
    }

    /** Where the disc is seen, the disc's image is bit for bit the plane's: the same kernel, the same record. */
    @Test
    void discRendersAsItsPlaneWhereverItIsSeen() throws Exception {
        String lift = "Surface Sphere\nVector3d center [0.4 0.5 0.3]\ndouble radius 0.5\nref material shape\n\n";
        String where = "Vector3d normal [0.1 1 0.2]\nref material floorMaterial\n\n";
        Image disc = render(SETTING + lift + "Surface Disc\nVector3d center [0.2 0 0.1]\ndouble radius 2.2\n" + where);
        Image plane = render(SETTING + lift + "Surface Plane\nVector3d point [0.2 0 0.1]\n" + where);
        Image neither = render(SETTING + lift);
        int seen = 0, outside = 0;
        for (int i = 0; i < disc.width * disc.height; i++) {
            boolean discSeen = false;
            for (int k = 0; k < 3; k++) {
                discSeen |= disc.rgb[3 * i + k] != neither.rgb[3 * i + k];
            }
            if (!discSeen) {
                continue;
            }
            seen++;
            for (int k = 0; k < 3; k++) {
                assertEquals(plane.rgb[3 * i + k], disc.rgb[3 * i + k], 0, "pixel " + (i % disc.width) + "," + (i / disc.width));
            }
        }
        for (int i = 0; i < disc.width * disc.height; i++) {
            if (plane.rgb[3 * i] != disc.rgb[3 * i]) {
                outside++;
            }
        }
        assertTrue(seen > 1500, "the disc changes " + seen + " pixels");
        assertTrue(outside > 500, "the plane reaches beyond the disc in " + outside + " pixels");
    }
}
