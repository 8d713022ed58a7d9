package ray.accel;

import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Sphere;
import ray.surface.Surface;
import ray.surface.Triangle;

/**
 * The scene's acceleration structure: one SAH BVH over every bounded surface, flattened into arrays.
 * Built-in triangles and spheres are copied into packed double arrays in leaf order and tested inline
 * (watertight triangles, the improved sphere quadratic); any other {@link Surface} with finite
 * {@link Surface#bounds()} sits in the same tree and is tested through its own {@code intersects}.
 * Surfaces without bounds are tested against every ray. Zero-area triangles are left out.
 *
 * <p>Memory: 32 bytes per node (float boxes) and, per triangle, 72 bytes of vertices plus a 4-byte
 * reference and a pointer to its {@code Surface}.
 */
public final class Bvh implements Accelerator {

    private static final int TRI = 0, SPHERE = 1, OTHER = 2;
    /** Widens the far slab distance to cover rounding in the box test (pbrt: 1 + 2 gamma(3)). */
    private static final double SLAB_SLACK = 1 + 8 * 0x1p-53;

    private final Scene scene;
    private final float[] nodeBox;
    private final int[] nodeInfo;
    /** Per leaf slot: (index within its kind) << 2 | kind. */
    private final int[] prims;
    private final double[] tris;          // 9 per triangle
    private final Surface[] triSurface;
    private final double[] spheres;       // cx, cy, cz, r
    private final Surface[] sphereSurface;
    private final Surface[] others;
    private final Surface[] unbounded;

    private Bvh(Scene scene, BvhBuilder b, List<Surface> bounded, List<Surface> unbounded) {
        this.scene = scene;
        this.nodeBox = b.nodeBox;
        this.nodeInfo = b.nodeInfo;
        this.unbounded = unbounded.toArray(new Surface[0]);
        int n = b.order.length, nt = 0, ns = 0, no = 0;
        for (Surface s : bounded) {
            int k = kind(s);
            if (k == TRI) nt++; else if (k == SPHERE) ns++; else no++;
        }
        prims = new int[n];
        tris = new double[9 * nt];
        triSurface = new Surface[nt];
        spheres = new double[4 * ns];
        sphereSurface = new Surface[ns];
        others = new Surface[no];
        nt = ns = no = 0;
        for (int i = 0; i < n; i++) {
            Surface s = bounded.get(b.order[i]);
            int k = kind(s);
            if (k == TRI) {
                Triangle t = (Triangle) s;
                double[] v = {t.v0.x, t.v0.y, t.v0.z, t.v1.x, t.v1.y, t.v1.z, t.v2.x, t.v2.y, t.v2.z};
                System.arraycopy(v, 0, tris, 9 * nt, 9);
                triSurface[nt] = s;
                prims[i] = nt++ << 2 | TRI;
            } else if (k == SPHERE) {
                Sphere sp = (Sphere) s;
                spheres[4 * ns] = sp.center.x;
                spheres[4 * ns + 1] = sp.center.y;
                spheres[4 * ns + 2] = sp.center.z;
                spheres[4 * ns + 3] = sp.radius;
                sphereSurface[ns] = s;
                prims[i] = ns++ << 2 | SPHERE;
            } else {
                others[no] = s;
                prims[i] = no++ << 2 | OTHER;
            }
        }
    }

    /** Exactly the built-in classes take the inline path; subclasses may override intersects. */
    private static int kind(Surface s) {
        Class<?> c = s.getClass();
        return c == Triangle.class ? TRI : c == Sphere.class ? SPHERE : OTHER;
    }

    /** Builds the BVH over {@code surfaces}, leaving out those that can never be hit. */
    public static Bvh build(List<Surface> surfaces, Scene scene) {
        List<Surface> bounded = new ArrayList<>();
        List<Surface> unbounded = new ArrayList<>();
        for (Surface s : surfaces) {
            if (s.isDegenerate()) {
                continue;
            }
            if (s.bounds().isFinite()) {
                bounded.add(s);
            } else {
                unbounded.add(s);
            }
        }
        double[] box = new double[6 * bounded.size()];
        for (int i = 0; i < bounded.size(); i++) {
            Aabb a = bounded.get(i).bounds();
            box[6 * i] = a.minX; box[6 * i + 1] = a.minY; box[6 * i + 2] = a.minZ;
            box[6 * i + 3] = a.maxX; box[6 * i + 4] = a.maxY; box[6 * i + 5] = a.maxZ;
        }
        BvhBuilder b = new BvhBuilder(box);
        b.build();
        return new Bvh(scene, b, bounded, unbounded);
    }

    public int nodeCount() {
        return nodeInfo.length / 2;
    }

    public int primitiveCount() {
        return prims.length + unbounded.length;
    }

    /** Bytes held by the tree and its packed primitives (not the scene's Surface objects). */
    public long memoryBytes() {
        return 4L * nodeBox.length + 4L * nodeInfo.length + 4L * prims.length
                + 8L * tris.length + 8L * spheres.length
                + 4L * (triSurface.length + sphereSurface.length + others.length);
    }

    @Override
    public boolean closestHit(Ray ray, IntersectionRecord rec, TraceContext ctx) {
        double tMin = ray.tMin, best = ray.tMax;
        int hit = -1;
        double savedTMax = ray.tMax;
        try {
            for (Surface s : unbounded) {
                ray.tMax = best;
                if (userHit(s, ray, rec)) {
                    best = rec.t;
                    hit = OTHER | (-1 << 2);
                    finishOther(ray, rec, s);
                }
            }
            if (nodeInfo.length == 0) {
                return hit != -1;
            }
            double[] k = ctx.rayKernel;
            Triangle.setupRay(ray, k);
            double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
            double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
            double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
            boolean negX = ix < 0, negY = iy < 0, negZ = iz < 0;
            double b0 = 0, b1 = 0, b2 = 0;
            int[] stack = ctx.stack;
            int sp = 0, node = 0;
            while (true) {
                if (boxHit(node, ox, oy, oz, ix, iy, iz, tMin, best)) {
                    int info0 = nodeInfo[2 * node], info1 = nodeInfo[2 * node + 1];
                    if (info1 > 0) {
                        for (int i = info0, end = info0 + info1; i < end; i++) {
                            int p = prims[i], idx = p >>> 2;
                            switch (p & 3) {
                                case TRI: {
                                    double t = Triangle.hit(tris, 9 * idx, k, tMin, best);
                                    if (t == t) {
                                        best = t;
                                        hit = p;
                                        b0 = k[9]; b1 = k[10]; b2 = k[11];
                                    }
                                    break;
                                }
                                case SPHERE: {
                                    int o = 4 * idx;
                                    double t = Sphere.hit(spheres[o], spheres[o + 1], spheres[o + 2], spheres[o + 3],
                                            ox, oy, oz, dx, dy, dz, tMin, best);
                                    if (t == t) {
                                        best = t;
                                        hit = p;
                                    }
                                    break;
                                }
                                default: {
                                    ray.tMax = best;
                                    Surface s = others[idx];
                                    if (userHit(s, ray, rec)) {
                                        best = rec.t;
                                        hit = p;
                                        finishOther(ray, rec, s);
                                    }
                                }
                            }
                        }
                    } else {
                        // visit the child on the ray's near side of the split first
                        int axis = -info1 - 1;
                        boolean farFirst = axis == 0 ? negX : axis == 1 ? negY : negZ;
                        if (farFirst) {
                            stack[sp++] = node + 1;
                            node = info0;
                        } else {
                            stack[sp++] = info0;
                            node = node + 1;
                        }
                        continue;
                    }
                }
                if (sp == 0) {
                    break;
                }
                node = stack[--sp];
            }
            if (hit == -1) {
                return false;
            }
            int idx = hit >>> 2;
            switch (hit & 3) {
                case TRI:
                    k[9] = b0; k[10] = b1; k[11] = b2;
                    Triangle.fill(tris, 9 * idx, k, best, rec);
                    rec.surface = triSurface[idx];
                    break;
                case SPHERE:
                    int o = 4 * idx;
                    Sphere.fill(spheres[o], spheres[o + 1], spheres[o + 2], spheres[o + 3], ox, oy, oz, dx, dy, dz, best, rec);
                    rec.surface = sphereSurface[idx];
                    break;
                default:
                    break;   // already filled by the surface's own intersects
            }
            return true;
        } finally {
            ray.tMax = savedTMax;
        }
    }

    /**
     * Calls a user surface's own intersects. Framework code may point the record's vectors at its own
     * objects ({@code record.normal = normal}); the record gets its own vectors back, holding the values,
     * so later writes into the record (the next hit's fill) cannot change the surface's fields.
     */
    private boolean userHit(Surface s, Ray ray, IntersectionRecord rec) {
        Vector3d location = rec.location, normal = rec.normal;
        boolean hit = s.intersects(ray, rec, scene);
        if (rec.location != location) {
            location.set(rec.location);
            rec.location = location;
        }
        if (rec.normal != normal) {
            normal.set(rec.normal);
            rec.normal = normal;
        }
        return hit;
    }

    /** A user surface's record: make sure its normal faces the ray and its error bound is set. */
    private static void finishOther(Ray ray, IntersectionRecord rec, Surface s) {
        rec.surface = s;
        rec.error = 0;
        double dn = rec.normal.x * ray.direction.x + rec.normal.y * ray.direction.y + rec.normal.z * ray.direction.z;
        rec.frontFace = dn <= 0;
        if (dn > 0) {
            rec.normal.negate();
        }
    }

    @Override
    public boolean anyHit(Ray ray, TraceContext ctx) {
        IntersectionRecord scratch = ctx.scratchRecord;
        for (Surface s : unbounded) {
            if (userHit(s, ray, scratch)) {
                return true;
            }
        }
        if (nodeInfo.length == 0) {
            return false;
        }
        double tMin = ray.tMin, tMax = ray.tMax;
        double[] k = ctx.rayKernel;
        Triangle.setupRay(ray, k);
        double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
        double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
        int[] stack = ctx.stack;
        int sp = 0, node = 0;
        while (true) {
            if (boxHit(node, ox, oy, oz, ix, iy, iz, tMin, tMax)) {
                int info0 = nodeInfo[2 * node], info1 = nodeInfo[2 * node + 1];
                if (info1 > 0) {
                    for (int i = info0, end = info0 + info1; i < end; i++) {
                        int p = prims[i], idx = p >>> 2;
                        switch (p & 3) {
                            case TRI:
                                if (!Double.isNaN(Triangle.hit(tris, 9 * idx, k, tMin, tMax))) {
                                    return true;
                                }
                                break;
                            case SPHERE: {
                                int o = 4 * idx;
                                double t = Sphere.hit(spheres[o], spheres[o + 1], spheres[o + 2], spheres[o + 3],
                                        ox, oy, oz, dx, dy, dz, tMin, tMax);
                                if (t == t) {
                                    return true;
                                }
                                break;
                            }
                            default:
                                if (userHit(others[idx], ray, scratch)) {
                                    return true;
                                }
                        }
                    }
                } else {
                    stack[sp++] = info0;
                    node = node + 1;
                    continue;
                }
            }
            if (sp == 0) {
                return false;
            }
            node = stack[--sp];
        }
    }

    /**
     * Slab test of node's box against the ray over [tMin, tMax]. A slab distance that is NaN (origin on
     * the slab's plane, direction parallel to it) leaves the interval as it was: conservative.
     */
    private boolean boxHit(int node, double ox, double oy, double oz, double ix, double iy, double iz,
                           double tMin, double tMax) {
        int o = 6 * node;
        float[] b = nodeBox;
        double lo = tMin, hi = tMax;
        double t0 = (b[o] - ox) * ix, t1 = (b[o + 3] - ox) * ix;
        double l = Math.min(t0, t1), h = Math.max(t0, t1);
        if (l > lo) lo = l;
        if (h < hi) hi = h;
        t0 = (b[o + 1] - oy) * iy;
        t1 = (b[o + 4] - oy) * iy;
        l = Math.min(t0, t1);
        h = Math.max(t0, t1);
        if (l > lo) lo = l;
        if (h < hi) hi = h;
        t0 = (b[o + 2] - oz) * iz;
        t1 = (b[o + 5] - oz) * iz;
        l = Math.min(t0, t1);
        h = Math.max(t0, t1);
        if (l > lo) lo = l;
        if (h < hi) hi = h;
        return lo <= hi * SLAB_SLACK;
    }
}
