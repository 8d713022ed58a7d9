package ray.accel;

import java.util.Arrays;

/**
 * Builds a bounding volume hierarchy by the surface area heuristic, with centroids binned into
 * {@value #BINS} buckets per axis (Wald, "On fast Construction of SAH-based Bounding Volume
 * Hierarchies", 2007): O(n log n) time. The result is flat: nodes in depth-first order, a node's
 * first child right after it, boxes as floats rounded outward so they stay conservative.
 */
final class BvhBuilder {

    static final int BINS = 16;
    static final int MAX_LEAF = 8;
    /** Cost of visiting a node relative to one primitive test. */
    static final double TRAVERSAL_COST = 1.0;

    private final double[] box;       // primitive boxes, 6 per primitive
    private final double[] centroid;  // 3 per primitive
    final int[] order;                // primitive ids in leaf order

    float[] nodeBox = new float[6 * 64];
    int[] nodeInfo = new int[2 * 64];
    int nodeCount;

    private final double[] binBox = new double[6 * BINS];
    private final int[] binCount = new int[BINS];
    private final double[] rightArea = new double[BINS];
    private final int[] rightCount = new int[BINS];

    BvhBuilder(double[] box) {
        this.box = box;
        int n = box.length / 6;
        centroid = new double[3 * n];
        order = new int[n];
        for (int i = 0; i < n; i++) {
            for (int a = 0; a < 3; a++) {
                centroid[3 * i + a] = 0.5 * (box[6 * i + a] + box[6 * i + 3 + a]);
            }
            order[i] = i;
        }
    }

    void build() {
        if (order.length > 0) {
            build(0, order.length, 0);
        }
        nodeBox = Arrays.copyOf(nodeBox, 6 * nodeCount);
        nodeInfo = Arrays.copyOf(nodeInfo, 2 * nodeCount);
    }

    /** Builds the subtree over order[start, end) and returns its node index. */
    private int build(int start, int end, int depth) {
        int node = newNode();
        double[] b = bounds(start, end, box, 6, 3);
        setBox(node, b);
        int n = end - start;
        double[] cb = bounds(start, end, centroid, 3, 0);
        int axis = 0;
        double extent = -1;
        for (int a = 0; a < 3; a++) {
            double e = cb[3 + a] - cb[a];
            if (e > extent) {
                extent = e;
                axis = a;
            }
        }
        if (n == 1 || !(extent > 0) || depth > 100) {
            // identical centroids (or absurd depth): split by count if too many for one leaf
            if (n <= MAX_LEAF || depth > 100) {
                return leaf(node, start, n);
            }
            return inner(node, axis, start, start + n / 2, end, depth);
        }
        int mid = sahSplit(start, end, cb, b, n);
        if (mid < 0) {
            return leaf(node, start, n);
        }
        // an inner node stores its split axis so traversal can visit the nearer child first
        return inner(node, lastAxis, start, mid, end, depth);
    }

    private int lastAxis;

    /** Partitions order[start, end) at the cheapest binned SAH split; -1 when a leaf is cheaper. */
    private int sahSplit(int start, int end, double[] cb, double[] b, int n) {
        double bestCost = Double.POSITIVE_INFINITY;
        int bestAxis = -1, bestBin = -1;
        double parentArea = area(b, 0);
        for (int a = 0; a < 3; a++) {
            double lo = cb[a], ext = cb[3 + a] - lo;
            if (!(ext > 0)) {
                continue;
            }
            double scale = BINS / ext;
            Arrays.fill(binCount, 0);
            for (int i = 0; i < BINS; i++) {
                emptyBox(binBox, 6 * i);
            }
            for (int i = start; i < end; i++) {
                int p = order[i];
                int bin = Math.min(BINS - 1, (int) ((centroid[3 * p + a] - lo) * scale));
                binCount[bin]++;
                grow(binBox, 6 * bin, box, 6 * p);
            }
            // sweep from the right, then from the left
            double[] acc = new double[6];
            emptyBox(acc, 0);
            int cnt = 0;
            for (int i = BINS - 1; i > 0; i--) {
                grow(acc, 0, binBox, 6 * i);
                cnt += binCount[i];
                rightArea[i] = cnt > 0 ? area(acc, 0) : 0;
                rightCount[i] = cnt;
            }
            emptyBox(acc, 0);
            cnt = 0;
            for (int i = 0; i < BINS - 1; i++) {
                grow(acc, 0, binBox, 6 * i);
                cnt += binCount[i];
                int rc = rightCount[i + 1];
                if (cnt == 0 || rc == 0) {
                    continue;
                }
                double cost = TRAVERSAL_COST + (area(acc, 0) * cnt + rightArea[i + 1] * rc) / parentArea;
                if (cost < bestCost) {
                    bestCost = cost;
                    bestAxis = a;
                    bestBin = i;
                }
            }
        }
        if (bestAxis < 0 || (n <= MAX_LEAF && bestCost >= n)) {
            if (n <= MAX_LEAF) {
                return -1;
            }
            // no useful split found for a big set: fall back to the median on the widest axis
            return medianFallback(start, end, cb);
        }
        lastAxis = bestAxis;
        double lo = cb[bestAxis], scale = BINS / (cb[3 + bestAxis] - lo);
        int i = start, j = end - 1;
        while (i <= j) {
            int p = order[i];
            int bin = Math.min(BINS - 1, (int) ((centroid[3 * p + bestAxis] - lo) * scale));
            if (bin <= bestBin) {
                i++;
            } else {
                order[i] = order[j];
                order[j--] = p;
            }
        }
        return i;
    }

    private int medianFallback(int start, int end, double[] cb) {
        int axis = 0;
        for (int a = 1; a < 3; a++) {
            if (cb[3 + a] - cb[a] > cb[3 + axis] - cb[axis]) {
                axis = a;
            }
        }
        lastAxis = axis;
        final int ax = axis;
        Integer[] sub = new Integer[end - start];
        for (int i = 0; i < sub.length; i++) {
            sub[i] = order[start + i];
        }
        Arrays.sort(sub, (p, q) -> Double.compare(centroid[3 * p + ax], centroid[3 * q + ax]));
        for (int i = 0; i < sub.length; i++) {
            order[start + i] = sub[i];
        }
        return start + sub.length / 2;
    }

    private int inner(int node, int axis, int start, int mid, int end, int depth) {
        build(start, mid, depth + 1);
        int right = build(mid, end, depth + 1);
        nodeInfo[2 * node] = right;
        nodeInfo[2 * node + 1] = -(axis + 1);
        return node;
    }

    private int leaf(int node, int start, int n) {
        nodeInfo[2 * node] = start;
        nodeInfo[2 * node + 1] = n;
        return node;
    }

    private int newNode() {
        if (nodeCount == nodeInfo.length / 2) {
            nodeInfo = Arrays.copyOf(nodeInfo, nodeInfo.length * 2);
            nodeBox = Arrays.copyOf(nodeBox, nodeBox.length * 2);
        }
        return nodeCount++;
    }

    private void setBox(int node, double[] b) {
        for (int a = 0; a < 3; a++) {
            nodeBox[6 * node + a] = down(b[a]);
            nodeBox[6 * node + 3 + a] = up(b[3 + a]);
        }
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

    /** Bounds of the entries of {@code data} (stride, max part at offset maxOff) over order[start, end). */
    private double[] bounds(int start, int end, double[] data, int stride, int maxOff) {
        double[] b = new double[6];
        emptyBox(b, 0);
        for (int i = start; i < end; i++) {
            int o = stride * order[i];
            for (int a = 0; a < 3; a++) {
                b[a] = Math.min(b[a], data[o + a]);
                b[3 + a] = Math.max(b[3 + a], data[o + maxOff + a]);
            }
        }
        return b;
    }

    private static void emptyBox(double[] b, int o) {
        for (int a = 0; a < 3; a++) {
            b[o + a] = Double.POSITIVE_INFINITY;
            b[o + 3 + a] = Double.NEGATIVE_INFINITY;
        }
    }

    private static void grow(double[] b, int o, double[] src, int so) {
        for (int a = 0; a < 3; a++) {
            b[o + a] = Math.min(b[o + a], src[so + a]);
            b[o + 3 + a] = Math.max(b[o + 3 + a], src[so + 3 + a]);
        }
    }

    private static double area(double[] b, int o) {
        double x = b[o + 3] - b[o], y = b[o + 4] - b[o + 1], z = b[o + 5] - b[o + 2];
        return x * y + y * z + z * x;
    }
}
