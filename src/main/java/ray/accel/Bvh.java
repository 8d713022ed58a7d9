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
 * (watertight triangles, the improved sphere quadratic, with exactly {@link Triangle#hit}'s and
 * {@link Sphere#hit}'s arithmetic); any other {@link Surface} with finite {@link Surface#bounds()}
 * sits in the same tree and is tested through its own {@code intersects}. Surfaces without bounds are
 * tested against every ray. Zero-area triangles are left out.
 *
 * <p>Traversal: an inner node holds both children's boxes, so one visit tests both; the closest-hit
 * query descends into the nearer child first and keeps the farther one, with its entry distance, on
 * a stack, dropping it when a closer hit has been found meanwhile. The any-hit (shadow) query stops
 * at the first hit. Box tests use the ray's direction signs to pick the near and far slab planes (no
 * min/max) and leave the interval unchanged when a slab distance is NaN, so they stay conservative.
 * Where two primitives are hit at exactly the same t, the one in the earlier leaf slot wins, whatever
 * the order they were tested in.
 *
 * <p>Memory: 56 bytes per inner node (two float boxes and two references; about one inner node per
 * leaf) and, per triangle, 72 bytes of vertices plus a 4-byte slot entry and a 4-byte reference to
 * its {@code Surface} ({@link #memoryBytes()}).
 */
public final class Bvh implements Accelerator {

    private static final int TRI = 0, SPHERE = 1, OTHER = 2;
    /** Count node visits and primitive tests in the TraceContext (-Dray.bvh.count=true; a constant the JIT folds). */
    static final boolean COUNT = Boolean.getBoolean("ray.bvh.count");
    /** Widens the far slab distance to cover rounding in the box test (pbrt: 1 + 2 gamma(3)). */
    private static final double SLAB_SLACK = 1 + 8 * 0x1p-53;

    private final Scene scene;
    private final int root;
    private final float[] rootBox;
    /** Per inner node: 6 floats of the first child's box, then 6 of the second's. */
    private final float[] nodeBox;
    /** Per inner node: the two child references (node index, or {@code ~(first slot << 4 | count)}). */
    private final int[] nodeChild;
    /** Per leaf slot: (index within its kind) << 2 | kind. */
    private final int[] prims;
    private final double[] tris;          // 9 per triangle, in slot order
    private final Surface[] triSurface;
    private final double[] spheres;       // cx, cy, cz, r
    private final Surface[] sphereSurface;
    private final Surface[] others;
    private final Surface[] unbounded;
    private final long buildNanos;

    private Bvh(Scene scene, BvhBuilder b, List<Surface> bounded, List<Surface> unbounded, long buildNanos) {
        this.scene = scene;
        this.root = b.root;
        this.rootBox = b.rootBox;
        this.nodeBox = b.nodeBox;
        this.nodeChild = b.nodeChild;
        this.unbounded = unbounded.toArray(new Surface[0]);
        this.buildNanos = buildNanos;
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
                int o = 9 * nt;
                tris[o] = t.v0.x; tris[o + 1] = t.v0.y; tris[o + 2] = t.v0.z;
                tris[o + 3] = t.v1.x; tris[o + 4] = t.v1.y; tris[o + 5] = t.v1.z;
                tris[o + 6] = t.v2.x; tris[o + 7] = t.v2.y; tris[o + 8] = t.v2.z;
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

    /**
     * Builds the BVH over the primitives of {@code sceneSurfaces} ({@link Surface#collectPrimitives}),
     * leaving out those that can never be hit.
     */
    public static Bvh build(List<Surface> sceneSurfaces, Scene scene) {
        long t0 = System.nanoTime();
        List<Surface> surfaces = new ArrayList<>(sceneSurfaces.size());
        for (Surface s : sceneSurfaces) {
            s.collectPrimitives(surfaces);
        }
        List<Surface> bounded = new ArrayList<>(surfaces.size());
        List<Surface> unbounded = new ArrayList<>();
        double[] box = new double[6 * surfaces.size()];
        for (Surface s : surfaces) {
            if (s.isDegenerate()) {
                continue;
            }
            Aabb a = s.bounds();
            if (a.isFinite()) {
                int i = bounded.size();
                box[6 * i] = a.minX; box[6 * i + 1] = a.minY; box[6 * i + 2] = a.minZ;
                box[6 * i + 3] = a.maxX; box[6 * i + 4] = a.maxY; box[6 * i + 5] = a.maxZ;
                bounded.add(s);
            } else {
                unbounded.add(s);
            }
        }
        BvhBuilder b = new BvhBuilder(java.util.Arrays.copyOf(box, 6 * bounded.size()));
        b.build();
        return new Bvh(scene, b, bounded, unbounded, System.nanoTime() - t0);
    }

    /** Inner nodes (a tree of one leaf has none). */
    public int nodeCount() {
        return nodeChild.length / 2;
    }

    public int primitiveCount() {
        return prims.length + unbounded.length;
    }

    /** Wall time of {@link #build}, nanoseconds. */
    public long buildNanos() {
        return buildNanos;
    }

    /** Bytes held by the tree and its packed primitives (not the scene's Surface objects). */
    public long memoryBytes() {
        return 4L * nodeBox.length + 4L * nodeChild.length + 4L * prims.length
                + 8L * tris.length + 8L * spheres.length
                + 4L * (triSurface.length + sphereSurface.length + others.length);
    }

    @Override
    public boolean closestHit(Ray ray, IntersectionRecord rec, TraceContext ctx) {
        double tMin = ray.tMin, best = ray.tMax;
        int hit = -1, hitSlot = Integer.MAX_VALUE;
        for (Surface s : unbounded) {
            if (userHit(s, ray, best, rec)) {
                best = rec.t;
                hit = OTHER | (-1 << 2);
            }
        }
        double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
        double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
        double aa = dx * dx + dy * dy + dz * dz;   // |d|^2, for the spheres' clear-miss test
        // near/far plane offsets in a 6-float box, from the direction's signs
        int nx = ix < 0 ? 3 : 0, ny = iy < 0 ? 4 : 1, nz = iz < 0 ? 5 : 2;
        int fx = 3 - nx, fy = 5 - ny, fz = 7 - nz;
        // the root's own box only when the root is a leaf: an inner root's children are tested anyway,
        // and most rays (all shadow rays) are inside the scene's box
        if (root < 0 && !(slabs(rootBox, 0, nx, ny, nz, fx, fy, fz, ox, oy, oz, ix, iy, iz, tMin, best) <= Double.MAX_VALUE)) {
            return hit != -1;
        }
        double[] k = ctx.rayKernel;
        double b0 = 0, b1 = 0, b2 = 0;
        // the watertight triangle test's per-ray set-up, made when the first triangle is tested
        boolean setUp = false;
        int kx = 0, ky = 0, kz = 0;
        double sx = 0, sy = 0, sz = 0, okx = 0, oky = 0, okz = 0;
        float[] nb = nodeBox;
        int[] nc = nodeChild, pr = prims;
        double[] tv = tris, sv = spheres;
        int[] stack = ctx.stack;
        double[] stackT = ctx.stackT;
        int sp = 0, ref = root;
        while (true) {
            if (ref >= 0) {
                // inner node: test both children (slabs(), written out: C1 would not inline it), go to
                // the nearer, keep the farther with its entry distance
                int o = 12 * ref;
                if (COUNT) {
                    ctx.nodeVisits++;
                }
                double lo0 = tMin, hi0 = best, lo1 = tMin, hi1 = best, t;
                t = (nb[o + nx] - ox) * ix; if (t > lo0) lo0 = t;
                t = (nb[o + fx] - ox) * ix; if (t < hi0) hi0 = t;
                t = (nb[o + ny] - oy) * iy; if (t > lo0) lo0 = t;
                t = (nb[o + fy] - oy) * iy; if (t < hi0) hi0 = t;
                t = (nb[o + nz] - oz) * iz; if (t > lo0) lo0 = t;
                t = (nb[o + fz] - oz) * iz; if (t < hi0) hi0 = t;
                t = (nb[o + 6 + nx] - ox) * ix; if (t > lo1) lo1 = t;
                t = (nb[o + 6 + fx] - ox) * ix; if (t < hi1) hi1 = t;
                t = (nb[o + 6 + ny] - oy) * iy; if (t > lo1) lo1 = t;
                t = (nb[o + 6 + fy] - oy) * iy; if (t < hi1) hi1 = t;
                t = (nb[o + 6 + nz] - oz) * iz; if (t > lo1) lo1 = t;
                t = (nb[o + 6 + fz] - oz) * iz; if (t < hi1) hi1 = t;
                boolean h0 = lo0 <= hi0 * SLAB_SLACK, h1 = lo1 <= hi1 * SLAB_SLACK;
                if (h0 && h1) {
                    if (lo1 < lo0) {
                        stack[sp] = nc[2 * ref];
                        stackT[sp++] = lo0;
                        ref = nc[2 * ref + 1];
                    } else {
                        stack[sp] = nc[2 * ref + 1];
                        stackT[sp++] = lo1;
                        ref = nc[2 * ref];
                    }
                    continue;
                } else if (h0) {
                    ref = nc[2 * ref];
                    continue;
                } else if (h1) {
                    ref = nc[2 * ref + 1];
                    continue;
                }
            } else {
                int leaf = ~ref;
                for (int i = leaf >>> 4, end = i + (leaf & 15); i < end; i++) {
                    int p = pr[i], idx = p >>> 2;
                    if (COUNT) {
                        ctx.primitiveTests++;
                    }
                    switch (p & 3) {
                        case TRI: {
                            if (!setUp) {
                                Triangle.setupRay(ray, k);
                                kx = (int) k[0]; ky = (int) k[1]; kz = (int) k[2];
                                sx = k[3]; sy = k[4]; sz = k[5]; okx = k[6]; oky = k[7]; okz = k[8];
                                setUp = true;
                            }
                            // Triangle.hit, written out with the set-up in locals: the same operations
                            // in the same order, so the same t
                            int v = 9 * idx;
                            double ax = tv[v + kx] - okx, ay = tv[v + ky] - oky, az = tv[v + kz] - okz;
                            double bx = tv[v + 3 + kx] - okx, by = tv[v + 3 + ky] - oky, bz = tv[v + 3 + kz] - okz;
                            double cx = tv[v + 6 + kx] - okx, cy = tv[v + 6 + ky] - oky, cz = tv[v + 6 + kz] - okz;
                            double pax = sx * az, pay = sy * az, pbx = sx * bz, pby = sy * bz, pcx = sx * cz, pcy = sy * cz;
                            double qax = ax - pax, qay = ay - pay, qbx = bx - pbx, qby = by - pby, qcx = cx - pcx, qcy = cy - pcy;
                            double u = qcx * qby - qcy * qbx;
                            double w0 = qax * qcy - qay * qcx;
                            double w1 = qbx * qay - qby * qax;
                            if (u < 0 || w0 < 0 || w1 < 0) {
                                break;
                            }
                            double det = u + w0 + w1;
                            if (!(det > 0)) {
                                break;
                            }
                            double tScaled = sz * (u * az + w0 * bz + w1 * cz);
                            if (tScaled < tMin * det || tScaled > best * det) {
                                break;
                            }
                            // the ray lies in the triangle's plane up to rounding: a miss (see Triangle.hit)
                            if (det <= Triangle.PARALLEL * ((Math.abs(cx) + Math.abs(pcx)) * (Math.abs(by) + Math.abs(pby))
                                    + (Math.abs(cy) + Math.abs(pcy)) * (Math.abs(bx) + Math.abs(pbx))
                                    + (Math.abs(ax) + Math.abs(pax)) * (Math.abs(cy) + Math.abs(pcy))
                                    + (Math.abs(ay) + Math.abs(pay)) * (Math.abs(cx) + Math.abs(pcx))
                                    + (Math.abs(bx) + Math.abs(pbx)) * (Math.abs(ay) + Math.abs(pay))
                                    + (Math.abs(by) + Math.abs(pby)) * (Math.abs(ax) + Math.abs(pax)))) {
                                break;
                            }
                            double inv = 1 / det;
                            double th = tScaled * inv;
                            if (th < best || (th == best && i < hitSlot)) {
                                best = th;
                                hit = p;
                                hitSlot = i;
                                b0 = u * inv;
                                b1 = w0 * inv;
                                b2 = w1 * inv;
                            }
                            break;
                        }
                        case SPHERE: {
                            int so = 4 * idx;
                            double scx = sv[so], scy = sv[so + 1], scz = sv[so + 2], sr = sv[so + 3];
                            // Sphere.hit's division-free clear-miss test, written out (C1 would call)
                            double gx = ox - scx, gy = oy - scy, gz = oz - scz;
                            double qx = gy * dz - gz * dy, qy = gz * dx - gx * dz, qz = gx * dy - gy * dx;
                            if (qx * qx + qy * qy + qz * qz > aa * (sr * sr * (1 + 1e-6) + 1e-6 * (gx * gx + gy * gy + gz * gz))) {
                                break;
                            }
                            double th = Sphere.hit(scx, scy, scz, sr, ox, oy, oz, dx, dy, dz, tMin, best);
                            if (th < best || (th == best && i < hitSlot)) {
                                best = th;
                                hit = p;
                                hitSlot = i;
                            }
                            break;
                        }
                        default: {
                            if (userHit(others[idx], ray, best, rec)) {
                                best = rec.t;
                                hit = p;
                                hitSlot = i;
                            }
                        }
                    }
                }
            }
            // pop the nearest pending subtree that may still hold a closer hit
            do {
                if (sp == 0) {
                    k[9] = b0;
                    k[10] = b1;
                    k[11] = b2;
                    return finish(hit, best, ray, rec, k, ox, oy, oz, dx, dy, dz);
                }
                ref = stack[--sp];
            } while (stackT[sp] > best * SLAB_SLACK);
        }
    }

    /**
     * A user surface's own test over [ray.tMin, best]; on a hit the record is the one the surface filled
     * ({@link #finishOther}), on a miss it is left as it was. The ray's tMax is restored even if the
     * surface throws.
     */
    private boolean userHit(Surface s, Ray ray, double best, IntersectionRecord rec) {
        double saved = ray.tMax, savedError = rec.error;
        boolean savedFront = rec.frontFace;
        Surface savedSurface = rec.surface;
        // what a surface written against the framework alone does not set: unknown error bound, front
        // face unless its normal says otherwise, and the surface itself
        rec.error = 0;
        rec.frontFace = true;
        rec.surface = null;
        ray.tMax = best;
        boolean hit = false;
        try {
            hit = userIntersects(s, ray, rec);
        } finally {
            ray.tMax = saved;
            if (!hit) {
                rec.error = savedError;
                rec.frontFace = savedFront;
                rec.surface = savedSurface;
            }
        }
        if (hit) {
            finishOther(ray, rec, s);
        }
        return hit;
    }

    /**
     * Calls a user surface's own intersects. Framework code may point the record's vectors at its own
     * objects ({@code record.normal = normal}); the record gets its own vectors back, holding the values,
     * so later writes into the record (the next hit's fill) cannot change the surface's fields.
     */
    private boolean userIntersects(Surface s, Ray ray, IntersectionRecord rec) {
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

    /** Fills the record for the closest hit found (a user surface has filled it already). */
    private boolean finish(int hit, double best, Ray ray, IntersectionRecord rec, double[] k,
                           double ox, double oy, double oz, double dx, double dy, double dz) {
        if (hit == -1) {
            return false;
        }
        int idx = hit >>> 2;
        switch (hit & 3) {
            case TRI: {
                // the barycentrics the winning test computed are in k[9..11]
                Triangle.fill(tris, 9 * idx, k, best, rec);
                rec.surface = triSurface[idx];
                break;
            }
            case SPHERE: {
                int o = 4 * idx;
                Sphere.fill(spheres[o], spheres[o + 1], spheres[o + 2], spheres[o + 3], ox, oy, oz, dx, dy, dz, best, rec);
                rec.surface = sphereSurface[idx];
                break;
            }
            default:
                break;   // already filled by the surface's own intersects
        }
        return true;
    }

    /**
     * A user surface's record is kept as its author wrote it (t, point, frontFace, error bound, and the
     * surface it names, {@code s} when it names none). Only a normal pointing away from the ray (a
     * surface written against the framework alone, which returns the outward normal) is turned to face
     * the ray, and then the ray is on the back side.
     */
    private static void finishOther(Ray ray, IntersectionRecord rec, Surface s) {
        if (rec.surface == null) {
            rec.surface = s;
        }
        double dn = rec.normal.x * ray.direction.x + rec.normal.y * ray.direction.y + rec.normal.z * ray.direction.z;
        if (dn > 0) {
            rec.normal.negate();
            rec.frontFace = false;
        }
    }

    @Override
    public boolean anyHit(Ray ray, TraceContext ctx) {
        IntersectionRecord scratch = ctx.scratchRecord;
        for (Surface s : unbounded) {
            if (userIntersects(s, ray, scratch)) {
                return true;
            }
        }
        double tMin = ray.tMin, tMax = ray.tMax;
        double ox = ray.origin.x, oy = ray.origin.y, oz = ray.origin.z;
        double dx = ray.direction.x, dy = ray.direction.y, dz = ray.direction.z;
        double ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
        double aa = dx * dx + dy * dy + dz * dz;   // |d|^2, for the spheres' clear-miss test
        int nx = ix < 0 ? 3 : 0, ny = iy < 0 ? 4 : 1, nz = iz < 0 ? 5 : 2;
        int fx = 3 - nx, fy = 5 - ny, fz = 7 - nz;
        if (root < 0 && !(slabs(rootBox, 0, nx, ny, nz, fx, fy, fz, ox, oy, oz, ix, iy, iz, tMin, tMax) <= Double.MAX_VALUE)) {
            return false;
        }
        double[] k = ctx.rayKernel;
        boolean setUp = false;
        int kx = 0, ky = 0, kz = 0;
        double sx = 0, sy = 0, sz = 0, okx = 0, oky = 0, okz = 0;
        float[] nb = nodeBox;
        int[] nc = nodeChild, pr = prims;
        double[] tv = tris, sv = spheres;
        int[] stack = ctx.stack;
        int sp = 0, ref = root;
        while (true) {
            if (ref >= 0) {
                int o = 12 * ref;
                if (COUNT) {
                    ctx.nodeVisits++;
                }
                double lo0 = tMin, hi0 = tMax, lo1 = tMin, hi1 = tMax, t;
                t = (nb[o + nx] - ox) * ix; if (t > lo0) lo0 = t;
                t = (nb[o + fx] - ox) * ix; if (t < hi0) hi0 = t;
                t = (nb[o + ny] - oy) * iy; if (t > lo0) lo0 = t;
                t = (nb[o + fy] - oy) * iy; if (t < hi0) hi0 = t;
                t = (nb[o + nz] - oz) * iz; if (t > lo0) lo0 = t;
                t = (nb[o + fz] - oz) * iz; if (t < hi0) hi0 = t;
                t = (nb[o + 6 + nx] - ox) * ix; if (t > lo1) lo1 = t;
                t = (nb[o + 6 + fx] - ox) * ix; if (t < hi1) hi1 = t;
                t = (nb[o + 6 + ny] - oy) * iy; if (t > lo1) lo1 = t;
                t = (nb[o + 6 + fy] - oy) * iy; if (t < hi1) hi1 = t;
                t = (nb[o + 6 + nz] - oz) * iz; if (t > lo1) lo1 = t;
                t = (nb[o + 6 + fz] - oz) * iz; if (t < hi1) hi1 = t;
                boolean h0 = lo0 <= hi0 * SLAB_SLACK, h1 = lo1 <= hi1 * SLAB_SLACK;
                if (h0) {
                    if (h1) {
                        stack[sp++] = nc[2 * ref + 1];
                    }
                    ref = nc[2 * ref];
                    continue;
                } else if (h1) {
                    ref = nc[2 * ref + 1];
                    continue;
                }
            } else {
                int leaf = ~ref;
                for (int i = leaf >>> 4, end = i + (leaf & 15); i < end; i++) {
                    int p = pr[i], idx = p >>> 2;
                    if (COUNT) {
                        ctx.primitiveTests++;
                    }
                    switch (p & 3) {
                        case TRI: {
                            if (!setUp) {
                                Triangle.setupRay(ray, k);
                                kx = (int) k[0]; ky = (int) k[1]; kz = (int) k[2];
                                sx = k[3]; sy = k[4]; sz = k[5]; okx = k[6]; oky = k[7]; okz = k[8];
                                setUp = true;
                            }
                            int v = 9 * idx;
                            double ax = tv[v + kx] - okx, ay = tv[v + ky] - oky, az = tv[v + kz] - okz;
                            double bx = tv[v + 3 + kx] - okx, by = tv[v + 3 + ky] - oky, bz = tv[v + 3 + kz] - okz;
                            double cx = tv[v + 6 + kx] - okx, cy = tv[v + 6 + ky] - oky, cz = tv[v + 6 + kz] - okz;
                            double pax = sx * az, pay = sy * az, pbx = sx * bz, pby = sy * bz, pcx = sx * cz, pcy = sy * cz;
                            double qax = ax - pax, qay = ay - pay, qbx = bx - pbx, qby = by - pby, qcx = cx - pcx, qcy = cy - pcy;
                            double u = qcx * qby - qcy * qbx;
                            double w0 = qax * qcy - qay * qcx;
                            double w1 = qbx * qay - qby * qax;
                            if (u < 0 || w0 < 0 || w1 < 0) {
                                break;
                            }
                            double det = u + w0 + w1;
                            if (!(det > 0)) {
                                break;
                            }
                            double tScaled = sz * (u * az + w0 * bz + w1 * cz);
                            if (tScaled < tMin * det || tScaled > tMax * det) {
                                break;
                            }
                            // the ray lies in the triangle's plane up to rounding: a miss (see Triangle.hit)
                            if (det <= Triangle.PARALLEL * ((Math.abs(cx) + Math.abs(pcx)) * (Math.abs(by) + Math.abs(pby))
                                    + (Math.abs(cy) + Math.abs(pcy)) * (Math.abs(bx) + Math.abs(pbx))
                                    + (Math.abs(ax) + Math.abs(pax)) * (Math.abs(cy) + Math.abs(pcy))
                                    + (Math.abs(ay) + Math.abs(pay)) * (Math.abs(cx) + Math.abs(pcx))
                                    + (Math.abs(bx) + Math.abs(pbx)) * (Math.abs(ay) + Math.abs(pay))
                                    + (Math.abs(by) + Math.abs(pby)) * (Math.abs(ax) + Math.abs(pax)))) {
                                break;
                            }
                            return true;
                        }
                        case SPHERE: {
                            int so = 4 * idx;
                            double scx = sv[so], scy = sv[so + 1], scz = sv[so + 2], sr = sv[so + 3];
                            // Sphere.hit's division-free clear-miss test, written out (C1 would call)
                            double gx = ox - scx, gy = oy - scy, gz = oz - scz;
                            double qx = gy * dz - gz * dy, qy = gz * dx - gx * dz, qz = gx * dy - gy * dx;
                            if (qx * qx + qy * qy + qz * qz > aa * (sr * sr * (1 + 1e-6) + 1e-6 * (gx * gx + gy * gy + gz * gz))) {
                                break;
                            }
                            double th = Sphere.hit(scx, scy, scz, sr, ox, oy, oz, dx, dy, dz, tMin, tMax);
                            if (th == th) {
                                return true;
                            }
                            break;
                        }
                        default:
                            if (userIntersects(others[idx], ray, scratch)) {
                                return true;
                            }
                    }
                }
            }
            if (sp == 0) {
                return false;
            }
            ref = stack[--sp];
        }
    }

    /**
     * Slab test of the box at {@code b[o..o+5]} against the ray over [tMin, tMax]: the entry distance,
     * or +infinity on a miss. The near and far planes per axis come from the direction's signs (offsets
     * {@code n*}, {@code f*}); a NaN slab distance (origin on the plane, direction parallel) leaves the
     * interval as it was: conservative.
     */
    private static double slabs(float[] b, int o, int nx, int ny, int nz, int fx, int fy, int fz,
                                double ox, double oy, double oz, double ix, double iy, double iz,
                                double tMin, double tMax) {
        double lo = tMin, hi = tMax;
        double t0 = (b[o + nx] - ox) * ix, t1 = (b[o + fx] - ox) * ix;
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
        t0 = (b[o + ny] - oy) * iy;
        t1 = (b[o + fy] - oy) * iy;
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
        t0 = (b[o + nz] - oz) * iz;
        t1 = (b[o + fz] - oz) * iz;
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
        return lo <= hi * SLAB_SLACK ? lo : Double.POSITIVE_INFINITY;
    }
}
