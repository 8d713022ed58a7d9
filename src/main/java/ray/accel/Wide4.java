package ray.accel;

import java.util.Arrays;
import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import ray.IntersectionRecord;

/**
 * The BVH's binary tree collapsed into nodes of up to four children whose four boxes are tested together,
 * in SIMD (the JDK's Vector API, {@code jdk.incubator.vector}): the traversal a long render under C2 runs
 * over a large tree ({@link Bvh#WIDE}). The class is loaded only where that module is in the
 * boot layer; nothing else in the program refers to the Vector API.
 *
 * <p>Built from the binary tree ({@link Bvh#node}), not by a builder of its own: each node takes its binary
 * node's two children, then, while it has fewer than four, replaces the inner child of largest surface area
 * by that child's two children (Wald et al. 2008, Embree's BVH4 collapse). The leaves, their slots and so
 * the primitives each leaf holds are the binary tree's. An unused lane has an empty box (+infinity to
 * -infinity), which every ray misses.
 *
 * <p>The box test is the binary traversal's ({@link Bvh#slabs}), lane for lane: each float plane widened to
 * the same double, minus the same origin, times the same inverse direction, the same NaN rule (a NaN slab
 * distance leaves the interval as it was: {@code n > lo} is false for NaN, so the blend keeps {@code lo}),
 * the same slack on the far end. So a box is entered exactly when the binary traversal would enter it over
 * the same interval, every leaf that could hold a hit is reached, its primitives are tested with the same
 * kernels, and since a closest hit's tie rule does not depend on the order of tests ({@link RayQuery#offer}),
 * every answer (hit or not, t, which primitive, the record filled) is the binary traversal's.
 * {@code Wide4Test} checks that on seeded random scenes and rays.
 *
 * <p>The closest-hit query visits the children it enters nearest first (their entry distances sorted, at
 * most four), keeps the others with their distances and drops those a closer hit has passed, as the binary
 * traversal does. The any-hit query takes them in lane order, unsorted, as Embree's occlusion traversal
 * does: any hit ends it, so nearest first buys it little, and the sort costs about what it saves (in-process
 * on mesh100k, without it: camera rays as any-hit queries 1.12x the rays a second, shadow rays 0.94x; whole
 * long renders even or better: mesh1m 0.98-0.99x the CPU time, mesh100k at 48 M camera rays 0.995x).
 * Camera packets have their own traversal ({@link #closestHits}), as in {@link Bvh}.
 *
 * <p>Memory: per node 24 floats of boxes and 4 child references, 112 bytes, twice a binary node's, for
 * about half as many nodes (a node over leaves is often filled with two or three children): about what
 * the binary nodes took, whose array the BVH then drops (mesh1m 60.9 bytes a triangle with its mesh,
 * against 60.7; {@code Wide4Test}'s scenes within 2%).
 */
final class Wide4 {

    private static final VectorSpecies<Float> F = FloatVector.SPECIES_128;
    private static final VectorSpecies<Double> D = DoubleVector.SPECIES_256;
    private static final DoubleVector INFINITE = DoubleVector.broadcast(D, Double.POSITIVE_INFINITY);
    /** Floats per node: min x, min y, min z, max x, max y, max z, four lanes each. */
    static final int NODE = 24;
    /**
     * Stack entries a query may need: a node pushes at most three children, and a path visits at most
     * one wide node per binary level, whose depth the builder bounds ({@link BvhBuilder#SAH_DEPTH} SAH
     * levels, then median splits of at most 31 levels).
     */
    static final int STACK = 3 * (BvhBuilder.SAH_DEPTH + 32);

    /** Per node: {@link #NODE} floats of its children's boxes, structure of arrays. */
    final float[] box;
    /** Per node: its four children's references (node index, or a leaf's {@code ~(first slot << 4 | count)}). */
    final int[] child;
    final int root;
    private int count;

    /** Collapses the binary tree {@code node} ({@link Bvh#NODE} floats a node) under its inner root. */
    Wide4(float[] node, int binaryRoot, int binaryNodes) {
        float[] b = new float[NODE * binaryNodes];
        int[] c = new int[4 * binaryNodes];
        root = collapse(node, binaryRoot, b, c);
        box = Arrays.copyOf(b, NODE * count);
        child = Arrays.copyOf(c, 4 * count);
    }

    /** The surface-area measure (half the area) of lane {@code lane}'s box in node {@code w} of {@code b}. */
    private static double area(float[] b, int w, int lane) {
        int o = NODE * w + lane;
        double x = (double) b[o + 12] - b[o], y = (double) b[o + 16] - b[o + 4], z = (double) b[o + 20] - b[o + 8];
        return x * y + y * z + z * x;
    }

    /** Lane {@code lane} of node {@code w}: the box at {@code node[from..from + 5]} and the reference {@code ref}. */
    private static void put(float[] node, int from, float[] b, int[] c, int w, int lane, int ref) {
        for (int a = 0; a < 6; a++) {
            b[NODE * w + 4 * a + lane] = node[from + a];
        }
        c[4 * w + lane] = ref;
    }

    /**
     * Makes the wide node of binary node {@code bin} in {@code b} and {@code c} and then, depth first, its
     * inner children's; returns its index. The node is filled in place, no scratch per node.
     */
    private int collapse(float[] node, int bin, float[] b, int[] c) {
        int w = count++;   // numbered before its children: depth-first order
        int o = Bvh.NODE * bin;
        put(node, o, b, c, w, 0, Float.floatToRawIntBits(node[o + 12]));
        put(node, o + 6, b, c, w, 1, Float.floatToRawIntBits(node[o + 13]));
        int k = 2;
        while (k < 4) {
            int open = -1;
            double largest = -1;
            for (int i = 0; i < k; i++) {
                if (c[4 * w + i] >= 0) {
                    double a = area(b, w, i);
                    if (a > largest) {
                        largest = a;
                        open = i;
                    }
                }
            }
            if (open < 0) {
                break;   // every child a leaf
            }
            int p = Bvh.NODE * c[4 * w + open];
            put(node, p, b, c, w, open, Float.floatToRawIntBits(node[p + 12]));
            put(node, p + 6, b, c, w, k, Float.floatToRawIntBits(node[p + 13]));
            k++;
        }
        for (int lane = k; lane < 4; lane++) {   // unused: an empty box, never entered, over an empty leaf
            for (int a = 0; a < 6; a++) {
                b[NODE * w + 4 * a + lane] = a < 3 ? Float.POSITIVE_INFINITY : Float.NEGATIVE_INFINITY;
            }
            c[4 * w + lane] = ~0;
        }
        for (int lane = 0; lane < k; lane++) {
            int ref = c[4 * w + lane];
            if (ref >= 0) {
                c[4 * w + lane] = collapse(node, ref, b, c);
            }
        }
        return w;
    }

    long memoryBytes() {
        return 4L * box.length + 4L * child.length;
    }

    /** Four planes of one kind (say min x) widened to doubles. */
    private static DoubleVector planes(float[] b, int o) {
        return (DoubleVector) FloatVector.fromArray(F, b, o).convertShape(VectorOperators.F2D, D, 0);
    }

    /**
     * The four children's entry distances into {@code d[0..3]} (+infinity for a box the ray misses over
     * [lo, hi]); returns whether any is entered. The offsets pick each axis's near and far planes by the
     * direction's sign, as {@link Bvh#slabs} does.
     */
    private static boolean enter(float[] b, int o, int nx, int fx, int ny, int fy, int nz, int fz,
                                 DoubleVector ox, DoubleVector oy, DoubleVector oz,
                                 DoubleVector ix, DoubleVector iy, DoubleVector iz, DoubleVector lo, DoubleVector hi, double[] d) {
        DoubleVector n = planes(b, o + nx).sub(ox).mul(ix), f = planes(b, o + fx).sub(ox).mul(ix);
        lo = lo.blend(n, n.compare(VectorOperators.GT, lo));
        hi = hi.blend(f, f.compare(VectorOperators.LT, hi));
        n = planes(b, o + ny).sub(oy).mul(iy);
        f = planes(b, o + fy).sub(oy).mul(iy);
        lo = lo.blend(n, n.compare(VectorOperators.GT, lo));
        hi = hi.blend(f, f.compare(VectorOperators.LT, hi));
        n = planes(b, o + nz).sub(oz).mul(iz);
        f = planes(b, o + fz).sub(oz).mul(iz);
        lo = lo.blend(n, n.compare(VectorOperators.GT, lo));
        hi = hi.blend(f, f.compare(VectorOperators.LT, hi));
        VectorMask<Double> in = lo.compare(VectorOperators.LE, hi.mul(Bvh.SLAB_SLACK));
        if (!in.anyTrue()) {
            return false;
        }
        INFINITE.blend(lo, in).intoArray(d, 0);
        return true;
    }

    /**
     * The packet's {@link #enter}: the four children's entry distances over the range of the packet's
     * inverse directions, as {@link Bvh}'s packet test ({@code a >= 0 ? a * lo : a * hi} per plane: the
     * rounded products are monotonic in the inverse, so the interval holds every ray's). Its last lines are
     * the single ray's: written out, because a helper taking the vectors (one more call level) left C2
     * boxing them on mesh1m (peak RSS 2.2 GiB, 1.2x the CPU time).
     */
    private static boolean enter(float[] b, int o, int nx, int fx, int ny, int fy, int nz, int fz,
                                 DoubleVector ox, DoubleVector oy, DoubleVector oz, DoubleVector ixLo, DoubleVector ixHi,
                                 DoubleVector iyLo, DoubleVector iyHi, DoubleVector izLo, DoubleVector izHi,
                                 DoubleVector lo, DoubleVector hi, double[] d) {
        DoubleVector a = planes(b, o + nx).sub(ox), c = planes(b, o + fx).sub(ox);
        DoubleVector n = a.mul(ixHi).blend(a.mul(ixLo), a.compare(VectorOperators.GE, 0));
        DoubleVector f = c.mul(ixLo).blend(c.mul(ixHi), c.compare(VectorOperators.GE, 0));
        lo = lo.blend(n, n.compare(VectorOperators.GT, lo));
        hi = hi.blend(f, f.compare(VectorOperators.LT, hi));
        a = planes(b, o + ny).sub(oy);
        c = planes(b, o + fy).sub(oy);
        n = a.mul(iyHi).blend(a.mul(iyLo), a.compare(VectorOperators.GE, 0));
        f = c.mul(iyLo).blend(c.mul(iyHi), c.compare(VectorOperators.GE, 0));
        lo = lo.blend(n, n.compare(VectorOperators.GT, lo));
        hi = hi.blend(f, f.compare(VectorOperators.LT, hi));
        a = planes(b, o + nz).sub(oz);
        c = planes(b, o + fz).sub(oz);
        n = a.mul(izHi).blend(a.mul(izLo), a.compare(VectorOperators.GE, 0));
        f = c.mul(izLo).blend(c.mul(izHi), c.compare(VectorOperators.GE, 0));
        lo = lo.blend(n, n.compare(VectorOperators.GT, lo));
        hi = hi.blend(f, f.compare(VectorOperators.LT, hi));
        VectorMask<Double> in = lo.compare(VectorOperators.LE, hi.mul(Bvh.SLAB_SLACK));
        if (!in.anyTrue()) {
            return false;
        }
        INFINITE.blend(lo, in).intoArray(d, 0);
        return true;
    }

    /**
     * Sorts the entered children (distance in {@code d[0..3]}) nearest first: their distances into
     * {@code d[4..]}, their lanes into {@code lane}; returns how many.
     */
    private static int sortEntered(double[] d, int[] lane) {
        int c = 0;
        for (int i = 0; i < 4; i++) {
            double t = d[i];
            if (t <= Double.MAX_VALUE) {
                int j = c++;
                while (j > 0 && d[3 + j] > t) {
                    d[4 + j] = d[3 + j];
                    lane[j] = lane[j - 1];
                    j--;
                }
                d[4 + j] = t;
                lane[j] = i;
            }
        }
        return c;
    }

    /** {@link Bvh#anyHit(ray.Ray, ray.TraceContext, int)}'s traversal from the root, the query set up. */
    boolean anyHit(Bvh bvh, RayQuery q, int slot, boolean cache, double ix, double iy, double iz) {
        DoubleVector vox = DoubleVector.broadcast(D, q.ox), voy = DoubleVector.broadcast(D, q.oy), voz = DoubleVector.broadcast(D, q.oz);
        DoubleVector vix = DoubleVector.broadcast(D, ix), viy = DoubleVector.broadcast(D, iy), viz = DoubleVector.broadcast(D, iz);
        DoubleVector lo = DoubleVector.broadcast(D, q.tMin), hi = DoubleVector.broadcast(D, q.tMax);
        int nx = ix < 0 ? 12 : 0, ny = iy < 0 ? 16 : 4, nz = iz < 0 ? 20 : 8;
        float[] b = box;
        double[] d = q.wideT;
        int[] kids = child, stack = q.stack;
        int sp = 0, ref = root;
        while (true) {
            if (ref >= 0) {
                if (Bvh.COUNT) {
                    q.nodeVisits++;
                }
                if (enter(b, NODE * ref, nx, nx ^ 12, ny, ny ^ 20, nz, nz ^ 28, vox, voy, voz, vix, viy, viz, lo, hi, d)) {
                    // lane order, unsorted (class comment): the lowest lane entered next, the others pushed.
                    // Written out rather than a loop over the lanes: C2 unrolls that loop anyway, but the
                    // interpreter and C1 count its four back-edges a node, ~45 a query on mesh1m, above the
                    // launcher's Tier3BackEdgeThreshold / Tier3MinInvocationThreshold (4000 / 100), so the
                    // method was compiled on stack first and C2 compiled it two or three times
                    // (docs/performance.md, issue 20, session 38).
                    int w = 4 * ref, next = 0;
                    boolean found = false;
                    if (d[3] <= Double.MAX_VALUE) {
                        next = kids[w + 3];
                        found = true;
                    }
                    if (d[2] <= Double.MAX_VALUE) {
                        if (found) {
                            stack[sp++] = next;
                        }
                        next = kids[w + 2];
                        found = true;
                    }
                    if (d[1] <= Double.MAX_VALUE) {
                        if (found) {
                            stack[sp++] = next;
                        }
                        next = kids[w + 1];
                        found = true;
                    }
                    if (d[0] <= Double.MAX_VALUE) {
                        if (found) {
                            stack[sp++] = next;
                        }
                        next = kids[w];
                    }
                    ref = next;   // enter returned true: at least one lane was entered
                    continue;
                }
            } else if (bvh.hit(~ref, q, slot, cache)) {
                return true;
            }
            if (sp == 0) {
                return Bvh.unshadowed(q, slot, cache);
            }
            ref = stack[--sp];
        }
    }

    /** {@link Bvh#closestHit}'s traversal from the root, the query set up; fills {@code rec}. */
    boolean closestHit(Bvh bvh, RayQuery q, IntersectionRecord rec, double ix, double iy, double iz) {
        DoubleVector vox = DoubleVector.broadcast(D, q.ox), voy = DoubleVector.broadcast(D, q.oy), voz = DoubleVector.broadcast(D, q.oz);
        DoubleVector vix = DoubleVector.broadcast(D, ix), viy = DoubleVector.broadcast(D, iy), viz = DoubleVector.broadcast(D, iz);
        DoubleVector lo = DoubleVector.broadcast(D, q.tMin);
        int nx = ix < 0 ? 12 : 0, ny = iy < 0 ? 16 : 4, nz = iz < 0 ? 20 : 8;
        float[] b = box;
        double[] d = q.wideT, stackT = q.stackT;
        int[] kids = child, entered = q.wideRef, stack = q.stack;
        int sp = 0, ref = root;
        while (true) {
            if (ref >= 0) {
                if (Bvh.COUNT) {
                    q.nodeVisits++;
                }
                DoubleVector hi = DoubleVector.broadcast(D, q.tMax);
                if (enter(b, NODE * ref, nx, nx ^ 12, ny, ny ^ 20, nz, nz ^ 28, vox, voy, voz, vix, viy, viz, lo, hi, d)) {
                    int c = sortEntered(d, entered), w = 4 * ref;
                    for (int j = c - 1; j > 0; j--) {
                        stack[sp] = kids[w + entered[j]];
                        stackT[sp++] = d[4 + j];
                    }
                    ref = kids[w + entered[0]];
                    continue;
                }
            } else {
                bvh.hit(~ref, q);
            }
            do {
                if (sp <= 0) {   // not sp == 0: see Bvh.closestHit's pop loop
                    return Bvh.finish(q, rec);
                }
                ref = stack[--sp];
            } while (stackT[sp] > q.tMax * Bvh.SLAB_SLACK);
        }
    }

    /**
     * {@link Bvh#closestHits}'s traversal of a packet that is traced together (one origin and span, one
     * sign per axis, no infinite inverse: checked there), its rays' queries started: each node's four
     * boxes tested once for the packet over its inverse directions' range ({@link #enter(float[], int, int,
     * int, int, int, int, int, DoubleVector, DoubleVector, DoubleVector, DoubleVector, DoubleVector,
     * DoubleVector, DoubleVector, DoubleVector, DoubleVector, DoubleVector, DoubleVector, double[])}) against
     * the largest t any ray may still hit at; at a leaf each ray tests the leaf's box with its own span
     * ({@link Bvh#slabs}, the binary traversal's own test) and, when it passes, the leaf's primitives in its
     * own query, as its single query would. Each ray's answer is its single query's.
     */
    void closestHits(Bvh bvh, RayQuery q, RayQuery[] lanes, int n, double ox, double oy, double oz, double tMin,
                     double ixLo, double ixHi, double iyLo, double iyHi, double izLo, double izHi, double far) {
        double[] lix = q.laneIx, liy = q.laneIy, liz = q.laneIz;
        boolean sx = ixHi < 0, sy = iyHi < 0, sz = izHi < 0;
        DoubleVector vox = DoubleVector.broadcast(D, ox), voy = DoubleVector.broadcast(D, oy), voz = DoubleVector.broadcast(D, oz);
        DoubleVector xLo = DoubleVector.broadcast(D, ixLo), xHi = DoubleVector.broadcast(D, ixHi);
        DoubleVector yLo = DoubleVector.broadcast(D, iyLo), yHi = DoubleVector.broadcast(D, iyHi);
        DoubleVector zLo = DoubleVector.broadcast(D, izLo), zHi = DoubleVector.broadcast(D, izHi);
        DoubleVector lo = DoubleVector.broadcast(D, tMin);
        int nx = sx ? 12 : 0, ny = sy ? 16 : 4, nz = sz ? 20 : 8;
        float[] b = box, leafBox = q.wideBox;
        double[] d = q.wideT, stackT = q.stackT;
        int[] kids = child, entered = q.wideRef, stack = q.stack, stackBox = q.stackBox;
        int sp = 0, ref = root, at = 0;
        while (true) {
            if (ref >= 0) {
                if (Bvh.COUNT) {
                    q.nodeVisits++;
                }
                DoubleVector hi = DoubleVector.broadcast(D, far);
                int o = NODE * ref;
                if (enter(b, o, nx, nx ^ 12, ny, ny ^ 20, nz, nz ^ 28, vox, voy, voz, xLo, xHi, yLo, yHi, zLo, zHi, lo, hi, d)) {
                    int c = sortEntered(d, entered), w = 4 * ref;
                    for (int j = c - 1; j > 0; j--) {
                        stack[sp] = kids[w + entered[j]];
                        stackBox[sp] = o + entered[j];
                        stackT[sp++] = d[4 + j];
                    }
                    ref = kids[w + entered[0]];
                    at = o + entered[0];
                    continue;
                }
            } else {
                for (int a = 0; a < 6; a++) {
                    leafBox[a] = b[at + 4 * a];   // the leaf's box, as the binary node holds it
                }
                double f = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < n; k++) {
                    RayQuery l = lanes[k];
                    if (Bvh.slabs(leafBox, 0, sx, sy, sz, ox, oy, oz, lix[k], liy[k], liz[k], tMin, l.tMax) <= Double.MAX_VALUE) {
                        bvh.hit(~ref, l);
                    }
                    if (l.tMax > f) {
                        f = l.tMax;
                    }
                }
                far = f;
            }
            do {
                if (sp <= 0) {   // not sp == 0: see Bvh.closestHit's pop loop
                    return;
                }
                ref = stack[--sp];
                at = stackBox[sp];
            } while (stackT[sp] > far * Bvh.SLAB_SLACK);
        }
    }
}
