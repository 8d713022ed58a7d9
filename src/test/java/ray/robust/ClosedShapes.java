package ray.robust;

import static ray.robust.RobustSupport.logUniform;
import static ray.robust.RobustSupport.unit;

import java.math.BigDecimal;
import java.math.MathContext;
import java.util.Random;
import javax.vecmath.Vector3d;
import ray.surface.AxialSurface;
import ray.surface.Box;
import ray.surface.Cone;
import ray.surface.Cylinder;
import ray.surface.Surface;
import ray.surface.Torus;

/**
 * Random closed primitives for the property tests, each with an exact residual (signed distance-like
 * function, zero exactly on the surface, computed in BigDecimal from the scene fields) and a way to
 * draw points well inside it.
 */
abstract class ClosedShapes {

    static final MathContext MC = new MathContext(50);

    final Surface surface;

    ClosedShapes(Surface surface) {
        this.surface = surface;
        surface.material = RobustSupport.grey();
        surface.init();
    }

    /** Zero on the surface, negative inside, |value| at most about the distance to the surface. */
    abstract double residual(Vector3d p);

    /** A point at least a tenth of the shape's thickness inside it. */
    abstract Vector3d inside(Random r);

    /** The shape's size (for scaling distances). */
    abstract double size();

    /** A random shape of the given kind (0 box, 1 cylinder, 2 cone, 3 torus) of size ~s at up to maxFar sizes from the origin. */
    static ClosedShapes random(int kind, Random r, double s, double maxFar) {
        Vector3d c = unit(r);
        c.scale(s * logUniform(r, 1e-3, maxFar));
        switch (kind) {
            case 0: {
                Box b = new Box();
                b.minPoint.set(c);
                b.maxPoint.set(c.x + s * logUniform(r, 0.1, 10), c.y + s * logUniform(r, 0.1, 10), c.z + s * logUniform(r, 0.1, 10));
                return new BoxShape(b);
            }
            case 1: case 2: {
                Vector3d axis = unit(r);
                axis.scale(s * logUniform(r, 0.1, 10));
                double rad = s * logUniform(r, 0.1, 10);
                return new AxialShape(kind == 1 ? new Cylinder() : new Cone(), c, axis, rad);
            }
            default: {
                double big = s * logUniform(r, 0.5, 2);
                Vector3d axis = unit(r);
                axis.scale(logUniform(r, 1e-3, 1e3));
                return new TorusShape(c, axis, big, big * logUniform(r, 0.01, 0.9));
            }
        }
    }

    static BigDecimal bd(double v) {
        return new BigDecimal(v);
    }

    /** Local (radial distance from the axis, height along it) of p, exactly to 50 digits. */
    static BigDecimal[] cylindrical(Vector3d p, Vector3d base, Vector3d axis) {
        BigDecimal ex = bd(p.x).subtract(bd(base.x)), ey = bd(p.y).subtract(bd(base.y)), ez = bd(p.z).subtract(bd(base.z));
        BigDecimal len = bd(axis.x).pow(2).add(bd(axis.y).pow(2)).add(bd(axis.z).pow(2)).sqrt(MC);
        BigDecimal z = ex.multiply(bd(axis.x)).add(ey.multiply(bd(axis.y))).add(ez.multiply(bd(axis.z))).divide(len, MC);
        BigDecimal rho2 = ex.pow(2).add(ey.pow(2)).add(ez.pow(2)).subtract(z.pow(2));
        BigDecimal rho = rho2.signum() <= 0 ? BigDecimal.ZERO : rho2.sqrt(MC);
        return new BigDecimal[] {rho, z, len};
    }

    /** A unit vector perpendicular to a. */
    static Vector3d perpendicular(Random r, Vector3d a) {
        Vector3d n = new Vector3d(a);
        n.normalize();
        Vector3d t = unit(r);
        t.scaleAdd(-t.dot(n), n, t);
        t.normalize();
        return t;
    }

    static final class BoxShape extends ClosedShapes {
        final Box b;

        BoxShape(Box b) {
            super(b);
            this.b = b;
        }

        @Override
        double residual(Vector3d p) {
            double[] q = {p.x, p.y, p.z}, lo = {b.minPoint.x, b.minPoint.y, b.minPoint.z}, hi = {b.maxPoint.x, b.maxPoint.y, b.maxPoint.z};
            BigDecimal m = null;
            for (int i = 0; i < 3; i++) {
                BigDecimal a = bd(lo[i]).subtract(bd(q[i])).max(bd(q[i]).subtract(bd(hi[i])));
                m = m == null ? a : m.max(a);
            }
            return m.doubleValue();
        }

        @Override
        Vector3d inside(Random r) {
            return new Vector3d(mix(r, b.minPoint.x, b.maxPoint.x), mix(r, b.minPoint.y, b.maxPoint.y), mix(r, b.minPoint.z, b.maxPoint.z));
        }

        private static double mix(Random r, double lo, double hi) {
            double f = 0.1 + 0.8 * r.nextDouble();
            return lo + f * (hi - lo);
        }

        @Override
        double size() {
            return Math.max(b.maxPoint.x - b.minPoint.x, Math.max(b.maxPoint.y - b.minPoint.y, b.maxPoint.z - b.minPoint.z));
        }
    }

    /** A Cylinder or a Cone (both AxialSurface: base, axis, radius). */
    static final class AxialShape extends ClosedShapes {
        final AxialSurface c;
        final boolean cone;

        AxialShape(AxialSurface c, Vector3d base, Vector3d axis, double radius) {
            super(set(c, base, axis, radius));
            this.c = c;
            this.cone = c instanceof Cone;
        }

        private static AxialSurface set(AxialSurface c, Vector3d base, Vector3d axis, double radius) {
            c.base.set(base);
            c.axis.set(axis);
            c.radius = radius;
            return c;
        }

        /**
         * Cylinder: max(rho - r, -z, z - h). Cone: max of the distance outside the side (measured
         * perpendicular to it) and below the base.
         */
        @Override
        double residual(Vector3d p) {
            BigDecimal[] q = cylindrical(p, c.base, c.axis);
            if (!cone) {
                return q[0].subtract(bd(c.radius)).max(q[1].negate()).max(q[1].subtract(q[2])).doubleValue();
            }
            BigDecimal k = bd(c.radius).divide(q[2], MC);
            BigDecimal side = q[0].subtract(k.multiply(q[2].subtract(q[1])))
                    .divide(BigDecimal.ONE.add(k.pow(2)).sqrt(MC), MC);
            return side.max(q[1].negate()).doubleValue();
        }

        /** A point at 10% to 90% (cone: 80%) of the height, within 0.9 of the radius there. */
        @Override
        Vector3d inside(Random r) {
            double f = 0.1 + (cone ? 0.7 : 0.8) * r.nextDouble();
            Vector3d p = RobustSupport.add(c.base, f, c.axis);
            return RobustSupport.add(p, 0.9 * c.radius * (cone ? 1 - f : 1) * r.nextDouble(), perpendicular(r, c.axis));
        }

        @Override
        double size() {
            return Math.max(c.radius, c.axis.length());
        }
    }

    static final class TorusShape extends ClosedShapes {
        final Torus t;

        TorusShape(Vector3d center, Vector3d axis, double big, double small) {
            super(make(center, axis, big, small));
            this.t = (Torus) surface;
        }

        private static Torus make(Vector3d center, Vector3d axis, double big, double small) {
            Torus t = new Torus();
            t.center.set(center);
            t.axis.set(axis);
            t.majorRadius = big;
            t.minorRadius = small;
            return t;
        }

        @Override
        double residual(Vector3d p) {
            BigDecimal[] q = cylindrical(p, t.center, t.axis);
            BigDecimal a = q[0].subtract(bd(t.majorRadius));
            return a.pow(2).add(q[1].pow(2)).sqrt(MC).subtract(bd(t.minorRadius)).doubleValue();
        }

        /** A point of the tube's middle circle, moved at most 0.9 r from it. */
        @Override
        Vector3d inside(Random r) {
            Vector3d e1 = perpendicular(r, t.axis), e2 = new Vector3d();
            Vector3d w = new Vector3d(t.axis);
            w.normalize();
            e2.cross(w, e1);
            double a = 2 * Math.PI * r.nextDouble();
            Vector3d p = RobustSupport.add(t.center, t.majorRadius * Math.cos(a), e1);
            p = RobustSupport.add(p, t.majorRadius * Math.sin(a), e2);
            return RobustSupport.add(p, 0.9 * t.minorRadius * r.nextDouble(), unit(r));
        }

        @Override
        double size() {
            return t.majorRadius + t.minorRadius;
        }
    }
}
