package ray.accel;

import java.util.Arrays;
import java.util.concurrent.RecursiveTask;

/**
 * Builds a bounding volume hierarchy by the surface area heuristic, with centroids binned into
 * {@value #BINS} buckets per axis (Wald, "On fast Construction of SAH-based Bounding Volume
 * Hierarchies", 2007): O(n log n) time. One pass over a node's primitives bins all three axes at
 * once; the split's two child boxes come out of the bins, the children's centroid bounds out of the
 * partition pass, so each level reads every primitive twice, in order: the partition moves the
 * primitives' boxes and centroids along with their ids, so both passes stream through memory
 * instead of following an index into it. Subtrees with more than
 * {@value #PARALLEL_MIN} primitives are built in parallel (fork/join); the result does not depend on
 * the thread count.
 *
 * <p>The result is flat, the form traversal wants: an inner node holds the boxes of both children
 * (12 floats) and two child references. A reference {@code >= 0} is an inner node's index; a leaf is
 * {@code ~(first << 4 | count)}, a run of {@code count <= }{@value #MAX_LEAF} primitive slots. Nodes
 * are in depth-first order (a node's first inner child follows it). Primitive boxes are rounded
 * outward to floats, so every node box is a union of float boxes that contain their primitives: the
 * boxes stay conservative without any further rounding.
 */
final class BvhBuilder {

    static final int BINS = 16;
    /** Most primitives in a leaf (at most 15: the count has 4 bits in a leaf reference). */
    static final int MAX_LEAF = 8;
    /** Cost of visiting an inner node (two box tests) relative to one primitive test. */
    static final float TRAVERSAL_COST = 3.0f;
    /** Subtrees at least this large are split between threads. */
    static final int PARALLEL_MIN = 16_384;
    /** Past this depth, splits are median splits by count (bounded depth on any input). */
    static final int SAH_DEPTH = 48;
    /** Largest number of primitives a leaf reference can address. */
    static final int MAX_PRIMITIVES = 1 << 27;

    final float[] primBox;     // 6 per slot, rounded outward; moved with the slot's primitive
    final float[] centroid;    // 3 per slot
    final int[] order;         // primitive ids in leaf (slot) order
    final int count;

    /** Output: the root reference and box, and the inner nodes. */
    int root;
    final float[] rootBox = new float[6];
    float[] nodeBox = new float[0];
    int[] nodeChild = new int[0];
    int nodeCount;

    /** {@code box}: 6 doubles (min xyz, max xyz) per primitive. */
    BvhBuilder(double[] box) {
        this(rounded(box), box.length / 6);
    }

    /**
     * {@code box}: 6 floats (min xyz, max xyz) per primitive for the first {@code count}, each rounded
     * outward from the primitive's double box ({@link #down}, {@link #up}); the builder keeps the array
     * and reorders it.
     */
    BvhBuilder(float[] box, int count) {
        this.count = count;
        if (count > MAX_PRIMITIVES) {
            throw new IllegalArgumentException("too many primitives for one BVH: " + count + " (at most " + MAX_PRIMITIVES + ")");
        }
        primBox = box;
        centroid = new float[3 * count];
        order = new int[count];
        for (int i = 0; i < count; i++) {
            centroid[3 * i] = 0.5f * box[6 * i] + 0.5f * box[6 * i + 3];
            centroid[3 * i + 1] = 0.5f * box[6 * i + 1] + 0.5f * box[6 * i + 4];
            centroid[3 * i + 2] = 0.5f * box[6 * i + 2] + 0.5f * box[6 * i + 5];
            order[i] = i;
        }
    }

    /** Double boxes rounded outward to floats. */
    private static float[] rounded(double[] box) {
        float[] f = new float[box.length];
        for (int i = 0; i + 5 < box.length; i += 6) {
            for (int a = 0; a < 3; a++) {
                f[i + a] = down(box[i + a]);
                f[i + 3 + a] = up(box[i + 3 + a]);
            }
        }
        return f;
    }

    void build() {
        if (count == 0) {
            root = ~0;   // an empty leaf
            Arrays.fill(rootBox, Float.NaN);
            return;
        }
        float[] b = new float[6], c = new float[6];
        bounds(0, count, b, c);
        System.arraycopy(b, 0, rootBox, 0, 6);
        Nodes out = new Nodes(Math.max(16, count / 2));
        root = build(0, count, b, c, 0, out, new Scratch());
        nodeBox = Arrays.copyOf(out.box, 12 * out.count);
        nodeChild = Arrays.copyOf(out.child, 2 * out.count);
        nodeCount = out.count;
    }

    /** Growable inner-node storage of one (sub)tree. */
    static final class Nodes {
        float[] box;
        int[] child;
        int count;

        Nodes(int capacity) {
            box = new float[12 * capacity];
            child = new int[2 * capacity];
        }

        int add() {
            if (count == child.length / 2) {
                box = Arrays.copyOf(box, box.length * 2);
                child = Arrays.copyOf(child, child.length * 2);
            }
            return count++;
        }

        /** Appends {@code o}'s nodes, renumbering its inner references; returns the offset. */
        int append(Nodes o) {
            int off = count;
            while (count + o.count > child.length / 2) {
                box = Arrays.copyOf(box, box.length * 2);
                child = Arrays.copyOf(child, child.length * 2);
            }
            System.arraycopy(o.box, 0, box, 12 * off, 12 * o.count);
            for (int i = 0; i < 2 * o.count; i++) {
                int r = o.child[i];
                child[2 * off + i] = r >= 0 ? r + off : r;
            }
            count += o.count;
            return off;
        }
    }

    /** Per-thread scratch for binning. */
    static final class Scratch {
        final int[] binCount = new int[3 * BINS];
        final float[] binBox = new float[3 * BINS * 6];
        final float[] rightArea = new float[BINS];
        final int[] rightCount = new int[BINS];
        final float[] acc = new float[6];
        // result of the last split search
        int axis, bin, bins;
        float cost;
    }

    /** A subtree built on the fork/join pool, into its own node storage. */
    static final class Subtree extends RecursiveTask<Nodes> {
        private static final long serialVersionUID = 1L;
        final transient BvhBuilder b;
        final int start, end, depth;
        final float[] box, cent;
        int ref;

        Subtree(BvhBuilder b, int start, int end, float[] box, float[] cent, int depth) {
            this.b = b;
            this.start = start;
            this.end = end;
            this.box = box;
            this.cent = cent;
            this.depth = depth;
        }

        @Override
        protected Nodes compute() {
            Nodes out = new Nodes(Math.max(16, (end - start) / 2));
            ref = b.build(start, end, box, cent, depth, out, new Scratch());
            return out;
        }
    }

    /**
     * Builds the subtree over slots [start, end) with box {@code box} and centroid bounds {@code cent};
     * returns its reference (a node index in {@code out}, or a leaf).
     */
    int build(int start, int end, float[] box, float[] cent, int depth, Nodes out, Scratch s) {
        int n = end - start;
        if (n == 1) {
            return leaf(start, n);
        }
        int mid = -1;
        float[] lb, rb, lc, rc;   // the children's boxes and centroid bounds, made once a split is certain
        if (depth < SAH_DEPTH && findSplit(start, end, cent, s)) {
            float leafCost = n;
            if (n <= MAX_LEAF && leafCost <= s.cost) {
                return leaf(start, n);
            }
            lb = new float[6]; rb = new float[6]; lc = new float[6]; rc = new float[6];
            mid = partition(start, end, cent, s, lb, rb, lc, rc);
        } else if (n <= MAX_LEAF && depth < SAH_DEPTH) {
            return leaf(start, n);   // all centroids coincide: nothing to gain from splitting
        } else {
            lb = new float[6]; rb = new float[6]; lc = new float[6]; rc = new float[6];
        }
        if (mid < 0) {
            // no SAH split (coincident centroids or too deep): halve by count, balanced
            mid = start + n / 2;
            bounds(start, mid, lb, lc);
            bounds(mid, end, rb, rc);
        }
        int node = out.add();
        int left, right;
        if (n >= PARALLEL_MIN && depth < 8 && Runtime.getRuntime().availableProcessors() > 1) {
            Subtree lt = new Subtree(this, start, mid, lb, lc, depth + 1);
            lt.fork();
            Nodes rn = new Nodes(Math.max(16, (end - mid) / 2));
            int rref = build(mid, end, rb, rc, depth + 1, rn, s);
            Nodes ln = lt.join();
            int loff = out.append(ln);
            left = lt.ref >= 0 ? lt.ref + loff : lt.ref;
            int roff = out.append(rn);
            right = rref >= 0 ? rref + roff : rref;
        } else {
            left = build(start, mid, lb, lc, depth + 1, out, s);
            right = build(mid, end, rb, rc, depth + 1, out, s);
        }
        out.child[2 * node] = left;
        out.child[2 * node + 1] = right;
        System.arraycopy(lb, 0, out.box, 12 * node, 6);
        System.arraycopy(rb, 0, out.box, 12 * node + 6, 6);
        return node;
    }

    static int leaf(int start, int n) {
        return ~(start << 4 | n);
    }

    /** Bin index of a centroid coordinate; the same arithmetic in binning and partitioning. */
    private static int binOf(float c, float lo, float scale, int bins) {
        int b = (int) ((c - lo) * scale);
        return b < 0 ? 0 : b >= bins ? bins - 1 : b;
    }

    /** Finds the cheapest binned SAH split over all axes into {@code s}; false when there is none. */
    private boolean findSplit(int start, int end, float[] cent, Scratch s) {
        int[] cnt = s.binCount;
        float[] bb = s.binBox;
        // small nodes get fewer bins: the fixed cost of a search (clearing and sweeping the bins) would
        // otherwise dominate, there being about as many small nodes as primitives
        int nb = Math.min(BINS, Math.max(2, end - start));
        s.bins = nb;
        for (int i = 0; i < 3 * BINS; i++) {
            if (i % BINS >= nb) {
                continue;
            }
            cnt[i] = 0;
            int o = 6 * i;
            bb[o] = bb[o + 1] = bb[o + 2] = Float.POSITIVE_INFINITY;
            bb[o + 3] = bb[o + 4] = bb[o + 5] = Float.NEGATIVE_INFINITY;
        }
        float lx = cent[0], ly = cent[1], lz = cent[2];
        float ex = cent[3] - lx, ey = cent[4] - ly, ez = cent[5] - lz;
        float sx = ex > 0 ? nb * 0.99999f / ex : 0, sy = ey > 0 ? nb * 0.99999f / ey : 0, sz = ez > 0 ? nb * 0.99999f / ez : 0;
        if (sx == 0 && sy == 0 && sz == 0) {
            return false;
        }
        float[] pb = primBox, pc = centroid;
        // one pass bins all three axes (the box growing written out: C1 would not inline it)
        for (int i = start; i < end; i++) {
            int q = 6 * i, c = 3 * i;
            float x0 = pb[q], y0 = pb[q + 1], z0 = pb[q + 2], x1 = pb[q + 3], y1 = pb[q + 4], z1 = pb[q + 5];
            int bx = binOf(pc[c], lx, sx, nb), by = BINS + binOf(pc[c + 1], ly, sy, nb), bz = 2 * BINS + binOf(pc[c + 2], lz, sz, nb);
            cnt[bx]++;
            cnt[by]++;
            cnt[bz]++;
            int o = 6 * bx;
            if (x0 < bb[o]) bb[o] = x0;
            if (y0 < bb[o + 1]) bb[o + 1] = y0;
            if (z0 < bb[o + 2]) bb[o + 2] = z0;
            if (x1 > bb[o + 3]) bb[o + 3] = x1;
            if (y1 > bb[o + 4]) bb[o + 4] = y1;
            if (z1 > bb[o + 5]) bb[o + 5] = z1;
            o = 6 * by;
            if (x0 < bb[o]) bb[o] = x0;
            if (y0 < bb[o + 1]) bb[o + 1] = y0;
            if (z0 < bb[o + 2]) bb[o + 2] = z0;
            if (x1 > bb[o + 3]) bb[o + 3] = x1;
            if (y1 > bb[o + 4]) bb[o + 4] = y1;
            if (z1 > bb[o + 5]) bb[o + 5] = z1;
            o = 6 * bz;
            if (x0 < bb[o]) bb[o] = x0;
            if (y0 < bb[o + 1]) bb[o + 1] = y0;
            if (z0 < bb[o + 2]) bb[o + 2] = z0;
            if (x1 > bb[o + 3]) bb[o + 3] = x1;
            if (y1 > bb[o + 4]) bb[o + 4] = y1;
            if (z1 > bb[o + 5]) bb[o + 5] = z1;
        }
        float best = Float.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = -1;
        float[] rightArea = s.rightArea;
        int[] rightCount = s.rightCount;
        for (int a = 0; a < 3; a++) {
            if ((a == 0 ? sx : a == 1 ? sy : sz) == 0) {
                continue;
            }
            int base = a * BINS;
            // sweep from the right, then from the left (the growing box in locals: C1 keeps calls)
            float x0 = Float.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Float.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            int c = 0;
            for (int i = nb - 1; i > 0; i--) {
                int o = 6 * (base + i);
                if (bb[o] < x0) x0 = bb[o];
                if (bb[o + 1] < y0) y0 = bb[o + 1];
                if (bb[o + 2] < z0) z0 = bb[o + 2];
                if (bb[o + 3] > x1) x1 = bb[o + 3];
                if (bb[o + 4] > y1) y1 = bb[o + 4];
                if (bb[o + 5] > z1) z1 = bb[o + 5];
                c += cnt[base + i];
                float wx = x1 - x0, wy = y1 - y0, wz = z1 - z0;
                rightArea[i] = c > 0 ? wx * wy + wy * wz + wz * wx : 0;
                rightCount[i] = c;
            }
            x0 = y0 = z0 = Float.POSITIVE_INFINITY;
            x1 = y1 = z1 = Float.NEGATIVE_INFINITY;
            c = 0;
            for (int i = 0; i < nb - 1; i++) {
                int o = 6 * (base + i);
                if (bb[o] < x0) x0 = bb[o];
                if (bb[o + 1] < y0) y0 = bb[o + 1];
                if (bb[o + 2] < z0) z0 = bb[o + 2];
                if (bb[o + 3] > x1) x1 = bb[o + 3];
                if (bb[o + 4] > y1) y1 = bb[o + 4];
                if (bb[o + 5] > z1) z1 = bb[o + 5];
                c += cnt[base + i];
                int r = rightCount[i + 1];
                if (c == 0 || r == 0) {
                    continue;
                }
                float wx = x1 - x0, wy = y1 - y0, wz = z1 - z0;
                float cost = (wx * wy + wy * wz + wz * wx) * c + rightArea[i + 1] * r;
                if (cost < best) {
                    best = cost;
                    bestAxis = a;
                    bestBin = i;
                }
            }
        }
        if (bestAxis < 0) {
            return false;
        }
        // the parent's box is the union of any axis's bins
        float[] acc = s.acc;
        empty(acc);
        int base = bestAxis * BINS;
        for (int i = 0; i < nb; i++) {
            growBox(acc, bb, 6 * (base + i));
        }
        float parentArea = area(acc);
        s.axis = bestAxis;
        s.bin = bestBin;
        s.cost = parentArea > 0 ? TRAVERSAL_COST + best / parentArea : TRAVERSAL_COST + (end - start);
        return true;
    }

    /**
     * Partitions slots [start, end) at the split in {@code s}; fills the children's boxes (from the
     * bins) and centroid bounds (from the pass). Returns the first index of the right child.
     */
    private int partition(int start, int end, float[] cent, Scratch s, float[] lb, float[] rb, float[] lc, float[] rc) {
        int axis = s.axis, split = s.bin;
        float lo = cent[axis], ext = cent[3 + axis] - lo;
        int nb = s.bins;
        float scale = nb * 0.99999f / ext;
        float[] bb = s.binBox;
        empty(lb);
        empty(rb);
        for (int i = 0; i < nb; i++) {
            growBox(i <= split ? lb : rb, bb, 6 * (axis * BINS + i));
        }
        float[] pc = centroid, pb = primBox;
        int[] ord = order;
        float lcx0 = Float.POSITIVE_INFINITY, lcy0 = lcx0, lcz0 = lcx0, lcx1 = Float.NEGATIVE_INFINITY, lcy1 = lcx1, lcz1 = lcx1;
        float rcx0 = lcx0, rcy0 = lcx0, rcz0 = lcx0, rcx1 = lcx1, rcy1 = lcx1, rcz1 = lcx1;
        int i = start, j = end - 1;
        while (i <= j) {
            float cx = pc[3 * i], cy = pc[3 * i + 1], cz = pc[3 * i + 2];
            if (binOf(axis == 0 ? cx : axis == 1 ? cy : cz, lo, scale, nb) <= split) {
                if (cx < lcx0) lcx0 = cx;
                if (cy < lcy0) lcy0 = cy;
                if (cz < lcz0) lcz0 = cz;
                if (cx > lcx1) lcx1 = cx;
                if (cy > lcy1) lcy1 = cy;
                if (cz > lcz1) lcz1 = cz;
                i++;
            } else {
                if (cx < rcx0) rcx0 = cx;
                if (cy < rcy0) rcy0 = cy;
                if (cz < rcz0) rcz0 = cz;
                if (cx > rcx1) rcx1 = cx;
                if (cy > rcy1) rcy1 = cy;
                if (cz > rcz1) rcz1 = cz;
                // swap slots i and j: id, box and centroid
                int t = ord[i];
                ord[i] = ord[j];
                ord[j] = t;
                for (int k = 0; k < 6; k++) {
                    float f = pb[6 * i + k];
                    pb[6 * i + k] = pb[6 * j + k];
                    pb[6 * j + k] = f;
                }
                for (int k = 0; k < 3; k++) {
                    float f = pc[3 * i + k];
                    pc[3 * i + k] = pc[3 * j + k];
                    pc[3 * j + k] = f;
                }
                j--;
            }
        }
        lc[0] = lcx0; lc[1] = lcy0; lc[2] = lcz0; lc[3] = lcx1; lc[4] = lcy1; lc[5] = lcz1;
        rc[0] = rcx0; rc[1] = rcy0; rc[2] = rcz0; rc[3] = rcx1; rc[4] = rcy1; rc[5] = rcz1;
        return i;
    }

    /** Box and centroid bounds of slots [start, end). */
    private void bounds(int start, int end, float[] box, float[] cent) {
        empty(box);
        empty(cent);
        for (int i = start; i < end; i++) {
            growBox(box, primBox, 6 * i);
            growPoint(cent, centroid, 3 * i);
        }
    }

    private static void empty(float[] b) {
        b[0] = b[1] = b[2] = Float.POSITIVE_INFINITY;
        b[3] = b[4] = b[5] = Float.NEGATIVE_INFINITY;
    }

    private static void grow(float[] b, int o, float x0, float y0, float z0, float x1, float y1, float z1) {
        if (x0 < b[o]) b[o] = x0;
        if (y0 < b[o + 1]) b[o + 1] = y0;
        if (z0 < b[o + 2]) b[o + 2] = z0;
        if (x1 > b[o + 3]) b[o + 3] = x1;
        if (y1 > b[o + 4]) b[o + 4] = y1;
        if (z1 > b[o + 5]) b[o + 5] = z1;
    }

    private static void growBox(float[] b, float[] src, int so) {
        grow(b, 0, src[so], src[so + 1], src[so + 2], src[so + 3], src[so + 4], src[so + 5]);
    }

    private static void growPoint(float[] b, float[] src, int so) {
        float x = src[so], y = src[so + 1], z = src[so + 2];
        grow(b, 0, x, y, z, x, y, z);
    }

    private static float area(float[] b) {
        float x = b[3] - b[0], y = b[4] - b[1], z = b[5] - b[2];
        return x * y + y * z + z * x;
    }

    /** The largest float not above x. */
    static float down(double x) {
        float f = (float) x;
        return f > x ? Math.nextDown(f) : f;
    }

    /** The smallest float not below x. */
    static float up(double x) {
        float f = (float) x;
        return f < x ? Math.nextUp(f) : f;
    }
}
