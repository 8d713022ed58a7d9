import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;

/**
 * Everything a scene file describes: the camera, the surfaces, lights and materials, and the global
 * settings (BGColor, AmbientLight, Width, Height, AASamples, MaxDepth).
 */
public class Scene {

    public Camera camera;
    /** BGColor: what a ray that hits nothing sees. */
    public Vector3d backgroundColor = new Vector3d();
    /** AmbientLight: I_a of the ambient term k_a I_a. */
    public Vector3d ambientLight = new Vector3d();
    /** Width and Height: the image size in pixels. */
    public int width, height;
    /** AASamples, n_s: each pixel is the mean of n_s x n_s samples. */
    public int samplesPerPixel = 1;
    /** MaxDepth: how many mirror bounces are followed. */
    public int maxDepth = 10;
    public List<Surface> surfaces = new ArrayList<>();
    public List<Light> lights = new ArrayList<>();
    public List<Material> materials = new ArrayList<>();

    /**
     * Method 9 of 11. The colour seen along {@code ray}: find the closest hit among all surfaces (the
     * smallest t within the ray's span, whatever order the surfaces are listed in) and return what
     * its surface's material shades there; where nothing is hit, BGColor (a copy). A ray deeper than
     * MaxDepth (ray.depth > maxDepth) is not followed: return black.
     */
    public Vector3d trace(Ray ray) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 9 of 11
        // STUB: return null;
        if (ray.depth > maxDepth) {
            return new Vector3d();
        }
        IntersectionRecord closest = null;
        for (Surface surface : surfaces) {
            IntersectionRecord record = new IntersectionRecord();
            if (surface.intersects(ray, record, this) && (closest == null || record.t < closest.t)) {
                closest = record;
            }
        }
        if (closest == null) {
            return new Vector3d(backgroundColor);
        }
        return closest.surface.material.shade(ray, closest, this);
        // END SOLUTION
    }

    /**
     * Method 10 of 11. The colour of pixel (x, y), x across from the left, y down from the top: the
     * mean of n_s x n_s samples (n_s = samplesPerPixel), one through the centre of each cell of an
     * n_s x n_s grid over the pixel. With n_s = 1 that is the pixel's centre (x + 0.5, y + 0.5).
     * Use camera.getRayThrough and trace. Keep the values as they are (no clamping).
     */
    public Vector3d renderPixel(int x, int y) {
        // BEGIN SOLUTION
        // STUB: // TODO: method 10 of 11
        // STUB: return null;
        int n = samplesPerPixel;
        Vector3d sum = new Vector3d();
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                Ray ray = camera.getRayThrough(x + (i + 0.5) / n, y + (j + 0.5) / n, width, height);
                sum.add(trace(ray));
            }
        }
        sum.scale(1.0 / (n * n));
        return sum;
        // END SOLUTION
    }

    /**
     * Method 11 of 11. The whole image as {@code image[x][y]}, width by height, x across from the
     * left, y down from the top row: each entry is {@link #renderPixel}(x, y).
     */
    public Vector3d[][] renderAll() {
        // BEGIN SOLUTION
        // STUB: // TODO: method 11 of 11
        // STUB: return null;
        Vector3d[][] image = new Vector3d[width][height];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                image[x][y] = renderPixel(x, y);
            }
        }
        return image;
        // END SOLUTION
    }
}
