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
    /**
     * Per sample k, the point the grid sampler picks in its cell (offsets u = v = 0.5: the centre), x y z,
     * worked out by {@link #init()} with the same arithmetic as {@link #sample}, which reads it instead.
     */
    private double[] centres = new double[0];

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
        int n = samples;
        double[] c = new double[3 * n * n];
        for (int k = 0; k < n * n; k++) {
            double s = ((k % n) + 0.5) / n - 0.5, t = ((k / n) + 0.5) / n - 0.5;
            c[3 * k] = position.x + s * edge1.x + t * edge2.x;
            c[3 * k + 1] = position.y + s * edge1.y + t * edge2.y;
            c[3 * k + 2] = position.z + s * edge1.z + t * edge2.z;
        }
        centres = c;
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
        double lx, ly, lz;
        double[] c = centres;
        if (ps.u == 0.5 && ps.v == 0.5 && index >= 0 && index < c.length / 3) {   // the cell's centre, as init() found it
            lx = c[3 * index];
            ly = c[3 * index + 1];
            lz = c[3 * index + 2];
        } else {
            double s = ((index % n) + ps.u) / n - 0.5, t = ((index / n) + ps.v) / n - 0.5;
            lx = position.x + s * edge1.x + t * edge2.x;
            ly = position.y + s * edge1.y + t * edge2.y;
            lz = position.z + s * edge1.z + t * edge2.z;
        }
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
        double ix = intensity.x * k, iy = intensity.y * k, iz = intensity.z * k;
        out.intensity.set(ix, iy, iz);
        out.shadowTested = false;
        return Double.isFinite(ix) && Double.isFinite(iy) && Double.isFinite(iz);   // (C1 would call finite())
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
