package ray.robust;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Consumer;
import javax.vecmath.Vector3d;
import ray.Camera;
import ray.Scene;
import ray.material.Diffuse;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.Renderer;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * Shared pieces of the robustness tests: seeded cases whose seed is in every failure message,
 * log-uniform scales, unnormalised directions, exact residuals and small scene builders.
 */
final class RobustSupport {

    /** Unit roundoff of double (2^-53). */
    static final double EPS = 0x1p-53;

    private RobustSupport() {
    }

    /**
     * Runs {@code body} for {@code n} cases, case i with its own {@code Random(seed)}; any failure is
     * rethrown with the seed and case number in front of its message, so it can be replayed alone
     * with {@link #replay}.
     */
    static void forEachSeed(long base, int n, Consumer<Random> body) {
        for (int i = 0; i < n; i++) {
            long seed = mix(base + i);
            replay(seed, i, n, body);
        }
    }

    /** Runs one case with the seed a failure message printed. */
    static void replay(long seed, int i, int n, Consumer<Random> body) {
        try {
            body.accept(new Random(seed));
        } catch (AssertionError | RuntimeException e) {
            throw new AssertionError(String.format("[seed 0x%016xL, case %d of %d] %s", seed, i, n, e.getMessage()), e);
        }
    }

    /** SplitMix64 finaliser: neighbouring case numbers give unrelated seeds. */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /** A number drawn log-uniformly from [lo, hi]. */
    static double logUniform(Random r, double lo, double hi) {
        return Math.exp(Math.log(lo) + r.nextDouble() * (Math.log(hi) - Math.log(lo)));
    }

    /** A uniformly distributed unit vector. */
    static Vector3d unit(Random r) {
        while (true) {
            Vector3d v = new Vector3d(r.nextGaussian(), r.nextGaussian(), r.nextGaussian());
            double l = v.length();
            if (l > 1e-6) {
                v.scale(1 / l);
                return v;
            }
        }
    }

    /** A unit vector at angle acos(cosTheta) from the unit vector {@code n}, around it at random. */
    static Vector3d atAngle(Random r, Vector3d n, double cosTheta) {
        Vector3d t = unit(r);
        t.scaleAdd(-t.dot(n), n, t);     // t minus its component along n
        t.normalize();
        double sin = Math.sqrt(Math.max(0, 1 - cosTheta * cosTheta));
        Vector3d v = new Vector3d();
        v.scaleAdd(cosTheta, n, v);
        v.scaleAdd(sin, t, v);
        return v;
    }

    /** {@code v} scaled by a length drawn log-uniformly from [1e-3, 1e3]: an unnormalised direction. */
    static Vector3d unnormalised(Random r, Vector3d v) {
        Vector3d d = new Vector3d(v);
        d.scale(logUniform(r, 1e-3, 1e3));
        return d;
    }

    static double maxAbs(Vector3d v) {
        return Math.max(Math.abs(v.x), Math.max(Math.abs(v.y), Math.abs(v.z)));
    }

    static Vector3d sub(Vector3d a, Vector3d b) {
        Vector3d v = new Vector3d();
        v.sub(a, b);
        return v;
    }

    /** a + s b. */
    static Vector3d add(Vector3d a, double s, Vector3d b) {
        return new Vector3d(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
    }

    /** |p - c| - r computed without rounding error in the subtraction (BigDecimal, 40 digits). */
    static double sphereResidual(Vector3d p, Vector3d c, double r) {
        MathContext mc = new MathContext(40);
        BigDecimal dx = new BigDecimal(p.x).subtract(new BigDecimal(c.x));
        BigDecimal dy = new BigDecimal(p.y).subtract(new BigDecimal(c.y));
        BigDecimal dz = new BigDecimal(p.z).subtract(new BigDecimal(c.z));
        BigDecimal d2 = dx.multiply(dx).add(dy.multiply(dy)).add(dz.multiply(dz));
        BigDecimal rr = new BigDecimal(r);
        BigDecimal dist = d2.sqrt(mc);
        return dist.subtract(rr, mc).doubleValue();
    }

    /** Signed distance of p from the plane through a with normal (b - a) x (c - a), in exact arithmetic. */
    static double planeResidual(Vector3d p, Vector3d a, Vector3d b, Vector3d c) {
        MathContext mc = new MathContext(60);
        BigDecimal[] e = diff(b, a), f = diff(c, a), q = diff(p, a);
        BigDecimal nx = e[1].multiply(f[2]).subtract(e[2].multiply(f[1]));
        BigDecimal ny = e[2].multiply(f[0]).subtract(e[0].multiply(f[2]));
        BigDecimal nz = e[0].multiply(f[1]).subtract(e[1].multiply(f[0]));
        BigDecimal dot = nx.multiply(q[0]).add(ny.multiply(q[1])).add(nz.multiply(q[2]));
        BigDecimal len = nx.multiply(nx).add(ny.multiply(ny)).add(nz.multiply(nz)).sqrt(mc);
        return dot.divide(len, mc).doubleValue();
    }

    private static BigDecimal[] diff(Vector3d a, Vector3d b) {
        return new BigDecimal[] {
            new BigDecimal(a.x).subtract(new BigDecimal(b.x)),
            new BigDecimal(a.y).subtract(new BigDecimal(b.y)),
            new BigDecimal(a.z).subtract(new BigDecimal(b.z))};
    }

    static Diffuse grey() {
        Diffuse d = new Diffuse();
        d.diffuseColor.set(0.5, 0.5, 0.5);
        return d;
    }

    static Sphere sphere(Vector3d c, double r) {
        Sphere s = new Sphere();
        s.center.set(c);
        s.radius = r;
        s.material = grey();
        s.init();
        return s;
    }

    static Triangle triangle(Vector3d a, Vector3d b, Vector3d c) {
        Triangle t = new Triangle();
        t.v0.set(a);
        t.v1.set(b);
        t.v2.set(c);
        t.material = grey();
        t.init();
        return t;
    }

    /** A scene holding {@code surfaces} (and a default camera, which the BVH build needs), prepared. */
    static Scene scene(List<? extends Surface> surfaces) {
        Scene s = new Scene();
        s.camera = new Camera();
        s.width = 4;
        s.height = 3;
        s.surfaces = new ArrayList<>(surfaces);
        s.prepare();
        return s;
    }

    /** Parses scene text (no warnings expected). */
    static Scene parse(String text, String name) {
        try {
            List<String> warnings = new ArrayList<>();
            Scene s = Parser.parse(text, name, warnings);
            if (!warnings.isEmpty()) {
                throw new AssertionError("unexpected warnings: " + warnings);
            }
            return s;
        } catch (SceneFormatException e) {
            throw new AssertionError(e.getMessage(), e);
        }
    }

    /**
     * Renders on two threads and checks the renderer's last line of defence was never needed: a NaN or
     * infinite sample would be replaced by black and counted, hiding the bug that made it.
     */
    static Image render(Scene scene) {
        Renderer r = new Renderer(scene).threads(2);
        Image img = r.render();
        if (r.stats().invalidSamples != 0) {
            throw new AssertionError(r.stats().invalidSamples + " NaN or infinite samples reached the renderer");
        }
        return img;
    }

    /** The 8-bit value of channel k of pixel i as the PNG stores it. */
    static int byteAt(Image img, int i, int k) {
        return Image.toByte(img.rgb[3 * i + k]);
    }

    /** Pixels of a and b whose 8-bit values differ by more than one step in any channel. */
    static int pixelsDifferingByMoreThanOneStep(Image a, Image b) {
        int n = 0;
        for (int i = 0; i < a.width * a.height; i++) {
            for (int k = 0; k < 3; k++) {
                if (Math.abs(byteAt(a, i, k) - byteAt(b, i, k)) > 1) {
                    n++;
                    break;
                }
            }
        }
        return n;
    }

    /** Formats a number so the parser reads back exactly the same double. */
    static String num(double v) {
        return Double.toString(v);
    }

    /** "[x y z]" for the parser, exact. */
    static String vec(double x, double y, double z) {
        return "[" + num(x) + " " + num(y) + " " + num(z) + "]";
    }
}
