package ray.light;

import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Scene;
import ray.PixelSample;

/**
 * A rectangular light: the parallelogram {@code position +- edge1/2 +- edge2/2}, cut into n x n cells.
 * Sample k (k = i + n j) is a point light of intensity I / n^2 at one point of cell (i, j), falling off
 * as r^-2 and shadowed on its own. Where in its cell comes from the render's sampler (two dimensions of
 * the pixel sample per light sample): the grid sampler, the default, puts it at the cell's centre, a
 * jittered or Sobol sampler anywhere in the cell (stratified sampling: Cook, Porter and Carpenter 1984,
 * "Distributed ray tracing"; Shirley et al., Fundamentals of Computer Graphics, 2nd ed., sect. 10.10).
 * The light arriving converges to (I / A) times the integral of cos / r^2 over the rectangle, and a
 * vanishingly small area light is a {@link PointLight}. Like point lights, area lights are not seen
 * directly.
 *
 * <pre>
 * Light AreaLight
 * Vector3d position [0 4 0]      # centre of the rectangle (default [0 0 0])
 * Vector3d edge1 [1 0 0]         # the two edge vectors, full lengths (defaults [1 0 0], [0 0 1])
 * Vector3d edge2 [0 0 1]
 * Vector3d intensity [20 20 20]  # in total (default [1 1 1])
 * int samples 4                  # n: n x n samples per shading point, 1 to 64 (default 4)
 * </pre>
 */
public class AreaLight extends SampledLight {

    /** Largest n: n^2 = 4,096 shadow rays per shading point already takes minutes on a small image. */
    public static final int MAX_SAMPLES = 64;

    public Vector3d position = new Vector3d();
    public Vector3d edge1 = new Vector3d(1, 0, 0);
    public Vector3d edge2 = new Vector3d(0, 0, 1);
    public Vector3d intensity = new Vector3d(1, 1, 1);
    public int samples = 4;

    private double perSample = 1.0 / 16;

    @Override
    public void init() {
        if (!PointLight.finite(position) || !PointLight.finite(edge1) || !PointLight.finite(edge2)
                || !PointLight.finite(intensity)) {
            throw new IllegalArgumentException("area light position, edges and intensity must be finite numbers");
        }
        if (samples < 1 || samples > MAX_SAMPLES) {
            throw new IllegalArgumentException("samples must be from 1 to " + MAX_SAMPLES + " (n x n shadow rays per point), got "
                    + samples);
        }
        perSample = 1.0 / ((double) samples * samples);
    }

    @Override
    public int sampleCount() {
        return samples * samples;
    }

    @Override
    public boolean sample(IntersectionRecord record, Scene scene, int index, LightSample out) {
        int n = samples;
        Vector3d p = record.location;
        // the point in cell (i, j): offsets (a, b) in [0, 1)^2 within the cell, the next 2D dimensions of
        // this pixel sample (the grid sampler gives the cell's centre, jittered and sobol a point in it)
        PixelSample ps = out.pixel;
        ps.next2D();
        double s = ((index % n) + ps.u) / n - 0.5, t = ((index / n) + ps.v) / n - 0.5;
        double lx = position.x + s * edge1.x + t * edge2.x;
        double ly = position.y + s * edge1.y + t * edge2.y;
        double lz = position.z + s * edge1.z + t * edge2.z;
        double dx = lx - p.x, dy = ly - p.y, dz = lz - p.z;
        double r2 = dx * dx + dy * dy + dz * dz;
        if (!(r2 > 0) || r2 == Double.POSITIVE_INFINITY) {
            return false;   // the sample sits on the point: no direction, no finite amount
        }
        double r = Math.sqrt(r2);
        out.direction.set(dx / r, dy / r, dz / r);
        out.position.set(lx, ly, lz);
        out.distance = r;
        double k = perSample / r2;
        out.intensity.set(intensity.x * k, intensity.y * k, intensity.z * k);
        out.shadowTested = false;
        return PointLight.finite(out.intensity);
    }

    /** For the render plan (declared here, where {@link #sample} is): dark when I = 0. */
    @Override
    public boolean isDark() {
        return intensity.x == 0 && intensity.y == 0 && intensity.z == 0;
    }

    /** For the render plan: one shadow ray per sample, n^2 per shading point. */
    @Override
    public int shadowRaysPerPoint() {
        return samples * samples;
    }

    @Override
    public String toString() {
        return "AreaLight[position " + position + ", edge1 " + edge1 + ", edge2 " + edge2 + ", intensity " + intensity
                + ", samples " + samples + "]";
    }
}
