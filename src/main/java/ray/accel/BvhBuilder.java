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

    /**
     * 6 per slot, the box rounded outward to floats and kept as {@link #key}s (min x, y, z, max x, y, z); moved
     * with the slot's primitive.
     */
    final int[] primKey;
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
     * {@code key}: 6 per primitive for the first {@code count}, the {@link #key}s of its box (min xyz, max
     * xyz) rounded outward to floats ({@link #down}, {@link #up}); the builder keeps the array and reorders it.
     */
    BvhBuilder(int[] key, int count) {
        this.count = count;
        if (count > MAX_PRIMITIVES) {
            throw new IllegalArgumentException("too many primitives for one BVH: " + count + " (at most " + MAX_PRIMITIVES + ")");
        }
        primKey = key;
        centroid = new float[3 * count];
        order = new int[count];
        for (int i = 0; i < count; i++) {
            int o = 6 * i;
            centroid[3 * i] = 0.5f * unkey(key[o]) + 0.5f * unkey(key[o + 3]);
            centroid[3 * i + 1] = 0.5f * unkey(key[o + 1]) + 0.5f * unkey(key[o + 4]);
            centroid[3 * i + 2] = 0.5f * unkey(key[o + 2]) + 0.5f * unkey(key[o + 5]);
            order[i] = i;
        }
    }

    /** Double boxes rounded outward to floats, as keys. */
    private static int[] rounded(double[] box) {
        int[] k = new int[box.length];
        for (int i = 0; i + 5 < box.length; i += 6) {
            for (int a = 0; a < 3; a++) {
                k[i + a] = key(down(box[i + a]));
                k[i + 3 + a] = key(up(box[i + 3 + a]));
            }
        }
        return k;
    }

    /**
     * A float as an int that orders as the float does: the bits of a float of either zero as 0, of a
     * positive one as they are, of a negative one with the bits below the sign flipped (then a larger
     * magnitude is a smaller int). So the builder's minima and maxima are int minima and maxima, which the
     * JIT compiles to conditional moves where a float comparison is a branch: binning a node's primitives
     * compares each box with three bins' boxes, and those branches, taken at random as the boxes come, were
     * the largest part of the build (docs/performance.md, issue 20, sessions 32 and 33). Not for
     * NaN, which no box holds ({@link Bvh#build} takes finite boxes only). Both zeros are 0, so a bound of
     * -0 comes back as +0: the same value in every box test, and the tree is the one float comparisons
     * build.
     */
    static int key(float f) {
        int b = Float.floatToRawIntBits(f == 0 ? 0f : f);
        return b ^ ((b >> 31) & 0x7fffffff);
    }

    /** The float of a {@link #key}. */
    static float unkey(int k) {
        return Float.intBitsToFloat(k ^ ((k >> 31) & 0x7fffffff));
    }

    /** The key of +infinity, above every box's; of -infinity, below. */
    private static final int KEY_MAX = key(Float.POSITIVE_INFINITY), KEY_MIN = key(Float.NEGATIVE_INFINITY);

    /** The slots' boxes as floats, 6 a slot (min xyz, max xyz), for the tests. */
    float[] primBoxes() {
        float[] f = new float[6 * count];
        for (int i = 0; i < f.length; i++) {
            f[i] = unkey(primKey[i]);
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
        bounds(0, count, b, 0, c, 0);
        System.arraycopy(b, 0, rootBox, 0, 6);
        Part tree = part(0, count, c, 0, 0, new Scratch());
        nodeCount = tree.size;
        nodeBox = new float[12 * nodeCount];
        nodeChild = new int[2 * nodeCount];
        root = tree.write(nodeBox, nodeChild, 0);
    }

    /**
     * A hash of the tree built: the root and its box, every node's two boxes (their floats' bits) and
     * references, and which primitive each leaf slot holds. Equal trees hash equal, and the render's
     * answers, its tie rule included, depend on nothing else the build makes; so a change to the builder
     * that means to build the same trees shows it by equal hashes before and after ({@link Bvh#structureHash},
     * {@code gradle buildTimes}). Not used by a render.
     */
    long structureHash() {
        long h = 17;
        h = 31 * h + root;
        for (float f : rootBox) {
            h = 31 * h + Float.floatToRawIntBits(f);
        }
        for (int i = 0; i < 12 * nodeCount; i++) {
            h = 31 * h + Float.floatToRawIntBits(nodeBox[i]);
        }
        for (int i = 0; i < 2 * nodeCount; i++) {
            h = 31 * h + nodeChild[i];
        }
        for (int i = 0; i < count; i++) {
            h = 31 * h + order[i];
        }
        return h;
    }

    /** Growable inner-node storage of one subtree, its nodes numbered from 0. */
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
    }

    /**
     * A built subtree: the nodes of one thread's subtree ({@link Nodes} and its root reference), or, above
     * the subtrees built in parallel, a node (its children's boxes) and its two parts. Each node is copied
     * once, when the whole tree is laid out ({@link #write}), not once per level of the parallel build.
     */
    static final class Part {
        final Nodes nodes;
        final int ref;
        final float[] box;
        final Part left, right;
        /** Inner nodes in this part. */
        final int size;

        Part(Nodes nodes, int ref) {
            this.nodes = nodes;
            this.ref = ref;
            box = null;
            left = right = null;
            size = nodes.count;
        }

        Part(float[] kids, Part left, Part right) {
            nodes = null;
            ref = 0;
            box = Arrays.copyOf(kids, 12);    // the children's boxes, as a node holds them
            this.left = left;
            this.right = right;
            size = 1 + left.size + right.size;
        }

        /** Writes this part's nodes in depth-first order from node {@code at}; returns its root reference. */
        int write(float[] outBox, int[] outChild, int at) {
            if (nodes != null) {
                System.arraycopy(nodes.box, 0, outBox, 12 * at, 12 * size);
                for (int i = 0; i < 2 * size; i++) {
                    int r = nodes.child[i];
                    outChild[2 * at + i] = r >= 0 ? r + at : r;
                }
                return ref >= 0 ? ref + at : ref;
            }
            System.arraycopy(box, 0, outBox, 12 * at, 12);
            outChild[2 * at] = left.write(outBox, outChild, at + 1);
            outChild[2 * at + 1] = right.write(outBox, outChild, at + 1 + left.size);
            return at;
        }
    }

    /** Per-thread scratch for binning, and each depth's split: the children's boxes and centroid bounds. */
    static final class Scratch {
        final int[] binCount = new int[3 * BINS];
        final int[] binKey = new int[3 * BINS * 6];
        final float[] rightArea = new float[BINS];
        final int[] rightCount = new int[BINS];
        // result of the last split search
        int axis, bin, bins;
        float cost;
        /** Per depth: left box, right box, left centroid bounds, right centroid bounds ({@link #LB} ...). */
        float[][] kids = new float[64][];

        /** The split arrays of {@code depth}: its children's own, kept while they are built (depth-first). */
        float[] kids(int depth) {
            if (depth >= kids.length) {
                kids = Arrays.copyOf(kids, 2 * depth);
            }
            float[] k = kids[depth];
            if (k == null) {
                k = kids[depth] = new float[24];
            }
            return k;
        }
    }

    /** Offsets in a {@link Scratch#kids} array. */
    static final int LB = 0, RB = 6, LC = 12, RC = 18;

    /** A subtree built on the fork/join pool, with its own scratch. */
    static final class Subtree extends RecursiveTask<Part> {
        private static final long serialVersionUID = 1L;
        final transient BvhBuilder b;
        final int start, end, depth, co;
        final float[] cent;

        Subtree(BvhBuilder b, int start, int end, float[] cent, int co, int depth) {
            this.b = b;
            this.start = start;
            this.end = end;
            this.cent = cent;
            this.co = co;
            this.depth = depth;
        }

        @Override
        protected Part compute() {
            return b.part(start, end, cent, co, depth, new Scratch());
        }
    }

    /**
     * Builds the subtree over slots [start, end) with centroid bounds {@code cent[co, co + 6)}: while it
     * is large, its node here and its two halves on two threads; below that, one thread's {@link Nodes}.
     */
    Part part(int start, int end, float[] cent, int co, int depth, Scratch s) {
        int n = end - start;
        if (n >= PARALLEL_MIN && depth < 8 && Runtime.getRuntime().availableProcessors() > 1) {
            float[] k = s.kids(depth);
            int mid = split(start, end, cent, co, depth, s, k);
            if (mid >= 0) {
                Subtree lt = new Subtree(this, start, mid, k, LC, depth + 1);
                lt.fork();
                Part right = part(mid, end, k, RC, depth + 1, s);
                Part left = lt.join();
                return new Part(k, left, right);
            }
        }
        Nodes out = new Nodes(Math.max(16, n / 2));
        int ref = build(start, end, cent, co, depth, out, s);
        return new Part(out, ref);
    }

    /**
     * Builds the subtree over slots [start, end) with centroid bounds {@code cent[co, co + 6)} into
     * {@code out}; returns its reference (a node index in {@code out}, or a leaf).
     */
    int build(int start, int end, float[] cent, int co, int depth, Nodes out, Scratch s) {
        float[] k = s.kids(depth);
        int mid = split(start, end, cent, co, depth, s, k);
        if (mid < 0) {
            return mid;     // a leaf
        }
        int node = out.add();
        int left = build(start, mid, k, LC, depth + 1, out, s);
        int right = build(mid, end, k, RC, depth + 1, out, s);
        out.child[2 * node] = left;
        out.child[2 * node + 1] = right;
        System.arraycopy(k, LB, out.box, 12 * node, 12);   // left box, then right box
        return node;
    }

    /**
     * Decides slots [start, end): a leaf reference (negative) when they stay one leaf; else partitions
     * them and returns the first slot of the right child, the children's boxes and centroid bounds in
     * {@code k} ({@link #LB}, {@link #RB}, {@link #LC}, {@link #RC}).
     */
    private int split(int start, int end, float[] cent, int co, int depth, Scratch s, float[] k) {
        int n = end - start;
        if (n == 1) {
            return leaf(start, n);
        }
        int mid = -1;
        if (depth < SAH_DEPTH && findSplit(start, end, cent, co, s)) {
            float leafCost = n;
            if (n <= MAX_LEAF && leafCost <= s.cost) {
                return leaf(start, n);
            }
            mid = partition(start, end, cent, co, s, k);
        } else if (n <= MAX_LEAF && depth < SAH_DEPTH) {
            return leaf(start, n);   // all centroids coincide: nothing to gain from splitting
        }
        if (mid < 0) {
            // no SAH split (coincident centroids or too deep): halve by count, balanced
            mid = start + n / 2;
            bounds(start, mid, k, LB, k, LC);
            bounds(mid, end, k, RB, k, RC);
        }
        return mid;
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
    boolean findSplit(int start, int end, float[] cent, int co, Scratch s) {
        int[] cnt = s.binCount, bk = s.binKey;
        // small nodes get fewer bins: the fixed cost of a search (clearing and sweeping the bins) would
        // otherwise dominate, there being about as many small nodes as primitives
        int nb = Math.min(BINS, Math.max(2, end - start));
        s.bins = nb;
        for (int a = 0; a < 3 * BINS; a += BINS) {
            for (int i = a; i < a + nb; i++) {
                cnt[i] = 0;
                int o = 6 * i;
                bk[o] = bk[o + 1] = bk[o + 2] = KEY_MAX;
                bk[o + 3] = bk[o + 4] = bk[o + 5] = KEY_MIN;
            }
        }
        float lx = cent[co], ly = cent[co + 1], lz = cent[co + 2];
        float ex = cent[co + 3] - lx, ey = cent[co + 4] - ly, ez = cent[co + 5] - lz;
        float sx = ex > 0 ? nb * 0.99999f / ex : 0, sy = ey > 0 ? nb * 0.99999f / ey : 0, sz = ez > 0 ? nb * 0.99999f / ez : 0;
        if (sx == 0 && sy == 0 && sz == 0) {
            return false;
        }
        int[] pk = primKey;
        float[] pc = centroid;
        // one pass bins all three axes; each bin's box grows by conditional moves on keys (written out three
        // times: C1 would not inline a helper this size). Math.min and max, not a ternary: C2 compiles an int
        // ternary by its profile, to a branch where one side is rare (most primitives do not grow a bin's
        // box, and the rest mispredict), while its Math.min is a conditional move always; C1 inlines Math.min
        // and compiles it as it does the ternary
        for (int i = start; i < end; i++) {
            int q = 6 * i, c = 3 * i;
            int x0 = pk[q], y0 = pk[q + 1], z0 = pk[q + 2], x1 = pk[q + 3], y1 = pk[q + 4], z1 = pk[q + 5];
            int bx = binOf(pc[c], lx, sx, nb), by = BINS + binOf(pc[c + 1], ly, sy, nb), bz = 2 * BINS + binOf(pc[c + 2], lz, sz, nb);
            cnt[bx]++;
            cnt[by]++;
            cnt[bz]++;
            int o = 6 * bx;
            bk[o] = Math.min(x0, bk[o]);
            bk[o + 1] = Math.min(y0, bk[o + 1]);
            bk[o + 2] = Math.min(z0, bk[o + 2]);
            bk[o + 3] = Math.max(x1, bk[o + 3]);
            bk[o + 4] = Math.max(y1, bk[o + 4]);
            bk[o + 5] = Math.max(z1, bk[o + 5]);
            o = 6 * by;
            bk[o] = Math.min(x0, bk[o]);
            bk[o + 1] = Math.min(y0, bk[o + 1]);
            bk[o + 2] = Math.min(z0, bk[o + 2]);
            bk[o + 3] = Math.max(x1, bk[o + 3]);
            bk[o + 4] = Math.max(y1, bk[o + 4]);
            bk[o + 5] = Math.max(z1, bk[o + 5]);
            o = 6 * bz;
            bk[o] = Math.min(x0, bk[o]);
            bk[o + 1] = Math.min(y0, bk[o + 1]);
            bk[o + 2] = Math.min(z0, bk[o + 2]);
            bk[o + 3] = Math.max(x1, bk[o + 3]);
            bk[o + 4] = Math.max(y1, bk[o + 4]);
            bk[o + 5] = Math.max(z1, bk[o + 5]);
        }
        float best = Float.POSITIVE_INFINITY, parentArea = Float.NaN;
        int bestAxis = -1, bestBin = -1;
        float[] rightArea = s.rightArea;
        int[] rightCount = s.rightCount;
        for (int a = 0; a < 3; a++) {
            if ((a == 0 ? sx : a == 1 ? sy : sz) == 0) {
                continue;
            }
            int base = a * BINS;
            // sweep from the right, then from the left, the growing box in locals (C1 keeps calls) as keys, by
            // the same conditional moves as the binning; a key's float is the bins' float (keys order as
            // floats, and a bin never holds -0), so the areas are those of the floats' boxes
            int x0 = KEY_MAX, y0 = x0, z0 = x0, x1 = KEY_MIN, y1 = x1, z1 = x1;
            int c = 0;
            for (int i = nb - 1; i > 0; i--) {
                int o = 6 * (base + i);
                x0 = Math.min(x0, bk[o]);
                y0 = Math.min(y0, bk[o + 1]);
                z0 = Math.min(z0, bk[o + 2]);
                x1 = Math.max(x1, bk[o + 3]);
                y1 = Math.max(y1, bk[o + 4]);
                z1 = Math.max(z1, bk[o + 5]);
                c += cnt[base + i];
                float wx = unkey(x1) - unkey(x0), wy = unkey(y1) - unkey(y0), wz = unkey(z1) - unkey(z0);
                rightArea[i] = c > 0 ? wx * wy + wy * wz + wz * wx : 0;
                rightCount[i] = c;
            }
            x0 = y0 = z0 = KEY_MAX;
            x1 = y1 = z1 = KEY_MIN;
            c = 0;
            for (int i = 0; i < nb - 1; i++) {
                int o = 6 * (base + i);
                x0 = Math.min(x0, bk[o]);
                y0 = Math.min(y0, bk[o + 1]);
                z0 = Math.min(z0, bk[o + 2]);
                x1 = Math.max(x1, bk[o + 3]);
                y1 = Math.max(y1, bk[o + 4]);
                z1 = Math.max(z1, bk[o + 5]);
                c += cnt[base + i];
                int r = rightCount[i + 1];
                if (c == 0 || r == 0) {
                    continue;
                }
                float wx = unkey(x1) - unkey(x0), wy = unkey(y1) - unkey(y0), wz = unkey(z1) - unkey(z0);
                float cost = (wx * wy + wy * wz + wz * wx) * c + rightArea[i + 1] * r;
                if (cost < best) {
                    best = cost;
                    bestAxis = a;
                    bestBin = i;
                }
            }
            if (parentArea != parentArea) {
                // the parent's box is the union of any axis's bins: the left sweep's (0 .. nb - 2) and the last
                int o = 6 * (base + nb - 1);
                x0 = Math.min(x0, bk[o]);
                y0 = Math.min(y0, bk[o + 1]);
                z0 = Math.min(z0, bk[o + 2]);
                x1 = Math.max(x1, bk[o + 3]);
                y1 = Math.max(y1, bk[o + 4]);
                z1 = Math.max(z1, bk[o + 5]);
                float wx = unkey(x1) - unkey(x0), wy = unkey(y1) - unkey(y0), wz = unkey(z1) - unkey(z0);
                parentArea = wx * wy + wy * wz + wz * wx;
            }
        }
        if (bestAxis < 0) {
            return false;
        }
        s.axis = bestAxis;
        s.bin = bestBin;
        s.cost = parentArea > 0 ? TRAVERSAL_COST + best / parentArea : TRAVERSAL_COST + (end - start);
        return true;
    }

    /**
     * Partitions slots [start, end) at the split in {@code s}; fills the children's boxes (from the
     * bins) and centroid bounds (from the pass). Returns the first index of the right child.
     */
    private int partition(int start, int end, float[] cent, int co, Scratch s, float[] k) {
        int axis = s.axis, split = s.bin;
        float lo = cent[co + axis], ext = cent[co + 3 + axis] - lo;
        int nb = s.bins;
        float scale = nb * 0.99999f / ext;
        binUnion(s.binKey, axis * BINS, 0, split + 1, k, LB);   // the children's boxes, from the split axis's bins
        binUnion(s.binKey, axis * BINS, split + 1, nb, k, RB);
        float[] pc = centroid;
        int[] pk = primKey, ord = order;
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
                for (int q = 0; q < 6; q++) {
                    int f = pk[6 * i + q];
                    pk[6 * i + q] = pk[6 * j + q];
                    pk[6 * j + q] = f;
                }
                for (int q = 0; q < 3; q++) {
                    float f = pc[3 * i + q];
                    pc[3 * i + q] = pc[3 * j + q];
                    pc[3 * j + q] = f;
                }
                j--;
            }
        }
        k[LC] = lcx0; k[LC + 1] = lcy0; k[LC + 2] = lcz0; k[LC + 3] = lcx1; k[LC + 4] = lcy1; k[LC + 5] = lcz1;
        k[RC] = rcx0; k[RC + 1] = rcy0; k[RC + 2] = rcz0; k[RC + 3] = rcx1; k[RC + 4] = rcy1; k[RC + 5] = rcz1;
        return i;
    }

    /** The union of bins [from, to) from bin {@code base} on of the keys {@code bk}, as floats into {@code box[o, o + 6)}. */
    private static void binUnion(int[] bk, int base, int from, int to, float[] box, int o) {
        int x0 = KEY_MAX, y0 = x0, z0 = x0, x1 = KEY_MIN, y1 = x1, z1 = x1;
        for (int i = from; i < to; i++) {
            int b = 6 * (base + i);
            x0 = Math.min(x0, bk[b]);
            y0 = Math.min(y0, bk[b + 1]);
            z0 = Math.min(z0, bk[b + 2]);
            x1 = Math.max(x1, bk[b + 3]);
            y1 = Math.max(y1, bk[b + 4]);
            z1 = Math.max(z1, bk[b + 5]);
        }
        box[o] = unkey(x0);
        box[o + 1] = unkey(y0);
        box[o + 2] = unkey(z0);
        box[o + 3] = unkey(x1);
        box[o + 4] = unkey(y1);
        box[o + 5] = unkey(z1);
    }

    /** Box and centroid bounds of slots [start, end), into {@code box[bo, bo + 6)} and {@code cent[co, co + 6)}. */
    void bounds(int start, int end, float[] box, int bo, float[] cent, int co) {
        empty(box, bo);
        empty(cent, co);
        int[] pk = primKey;
        for (int i = start; i < end; i++) {
            int o = 6 * i;
            grow(box, bo, unkey(pk[o]), unkey(pk[o + 1]), unkey(pk[o + 2]), unkey(pk[o + 3]), unkey(pk[o + 4]), unkey(pk[o + 5]));
            growPoint(cent, co, centroid, 3 * i);
        }
    }

    private static void empty(float[] b, int o) {
        b[o] = b[o + 1] = b[o + 2] = Float.POSITIVE_INFINITY;
        b[o + 3] = b[o + 4] = b[o + 5] = Float.NEGATIVE_INFINITY;
    }

    private static void grow(float[] b, int o, float x0, float y0, float z0, float x1, float y1, float z1) {
        if (x0 < b[o]) b[o] = x0;
        if (y0 < b[o + 1]) b[o + 1] = y0;
        if (z0 < b[o + 2]) b[o + 2] = z0;
        if (x1 > b[o + 3]) b[o + 3] = x1;
        if (y1 > b[o + 4]) b[o + 4] = y1;
        if (z1 > b[o + 5]) b[o + 5] = z1;
    }

    private static void growPoint(float[] b, int o, float[] src, int so) {
        float x = src[so], y = src[so + 1], z = src[so + 2];
        grow(b, o, x, y, z, x, y, z);
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
