package ray.accel;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import ray.IntersectionRecord;
import ray.Ray;
import ray.RayPacket;
import ray.Scene;
import ray.TraceContext;
import ray.surface.Surface;

/**
 * The scene's acceleration structure: one SAH BVH over every bounded primitive, flattened into arrays.
 * The BVH holds boxes and the tree, no primitive's math: primitives are kept by type in
 * {@link PrimitiveSet}s (built-in triangles and spheres packed in arrays and tested with the same
 * kernels as {@code Triangle.intersects} and {@code Sphere.intersects}; any other {@link Surface} with
 * finite {@link Surface#bounds()} through its own {@code intersects}). Surfaces without bounds are
 * tested against every ray. Zero-area triangles are left out. A scene object may stand for many
 * primitives ({@link Surface#collectPrimitives}).
 *
 * <p>Traversal: an inner node holds both children's boxes, so one visit tests both; the closest-hit
 * query descends into the nearer child first and keeps the farther one, with its entry distance, on
 * a stack, dropping it when a closer hit has been found meanwhile. The any-hit (shadow) query also
 * descends into the nearer child first (nearer occluders are found sooner: classic's shadow rays 1.2x,
 * mesh100k's 1.05x in docs/performance.md) and stops at the first hit; with an occluder-cache slot
 * ({@link #anyHit(Ray, TraceContext, int)}) it first tests the primitive that stopped the slot's last
 * shadowed query. Box tests use the ray's direction signs to pick the near and far slab planes (no
 * min/max) and leave the interval unchanged when a slab distance is NaN, so they stay conservative.
 * A leaf's slots are grouped by set, and each run of one set's slots is handed to that set. Where two
 * primitives are hit at exactly the same t, the one in the earlier leaf slot wins, whatever the order
 * they were tested in ({@link RayQuery#offer}; the kernels test candidates against
 * {@link RayQuery#candidateBound}, so none at exactly the best t is turned away by its own rounding). A long
 * render of a large tree may traverse it four boxes at a time instead ({@link Wide4}, {@link #WIDE}): the
 * same leaves, kernels and answers. Camera rays leaving the eye may be traced as a packet
 * ({@link #closestHits}): inner nodes tested once for the whole packet, leaves ray by ray, each ray's
 * answer its single query's.
 *
 * <p>Per-thread scratch (the traversal stack, the ray's set-up) is this class's {@link RayQuery}, kept
 * in the thread's {@link TraceContext#acceleratorScratch}.
 *
 * <p>Memory: 56 bytes per inner node (two float boxes and two references; about one inner node per
 * leaf), 8 bytes per leaf slot where the BVH holds more than one set (none where it holds one), and
 * what the sets pack (per triangle 72 bytes of vertices and a 4-byte reference to its {@code Surface})
 * ({@link #memoryBytes()}).
 */
public final class Bvh implements Accelerator {

    /** Count node visits and primitive tests in the RayQuery (-Dray.bvh.count=true; a constant the JIT folds). */
    static final boolean COUNT = Boolean.getBoolean("ray.bvh.count");
    /** Floats per inner node in {@link #node}. */
    static final int NODE = 14;
    /** Widens the far slab distance to cover rounding in the box test (pbrt: 1 + 2 gamma(3)). */
    static final double SLAB_SLACK = 1 + 8 * 0x1p-53;
    /**
     * Whether large trees are traversed four boxes at a time ({@link Wide4}): asked for by
     * {@code -Dray.bvh.wide=true} (the launcher passes it to a long render, with the Vector API's module)
     * and the module {@code jdk.incubator.vector} in the boot layer. Short renders run C1, where the
     * Vector API is many times slower than scalar code; they never ask.
     */
    static final boolean WIDE = Boolean.getBoolean("ray.bvh.wide")
            && ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent();
    /**
     * Inner nodes from which a tree is traversed wide when {@link #WIDE}: a small tree (classic's five
     * primitives) is one or two binary nodes, and there the wide traversal's set-up costs more than it saves.
     */
    static final int WIDE_NODES = Integer.getInteger("ray.bvh.wideNodes", 1024);

    private final Scene scene;
    private final int root;
    private final float[] rootBox;
    /**
     * Per inner node, {@value #NODE} floats: 6 of the first child's box (min xyz, max xyz), 6 of the
     * second's, then the two child references as float bits (node index, or {@code ~(first slot << 4 |
     * count)}): one array, so a visit reads one or two cache lines and the JIT checks its bounds once.
     */
    private final float[] node;
    /** The tree four children a node, where traversed wide (then {@link #node} is null), else null. */
    private final Wide4 wide;
    private final int nodeCount;
    /**
     * Per leaf slot starting a run of one set's slots: set number << 4 | run length (other slots: unused).
     * Null when there is one set: then a leaf is one run and slot i is the set's primitive i.
     */
    private final int[] slotRun;
    /** Per leaf slot: the primitive's index within its set (null when there is one set). */
    private final int[] slotIndex;
    private final PrimitiveSet[] sets;
    /** The set when there is only one, else null. */
    private final PrimitiveSet onlySet;
    /** Surfaces without bounds, tested against every ray (null when there are none). */
    private final PrimitiveSet unbounded;
    private final int primitives;
    private final long buildNanos;
    /**
     * Whether a build keeps its tree's {@link BvhBuilder#structureHash} ({@code -Dray.bvh.hash=true}, as
     * {@code gradle buildTimes} runs; a constant the JIT folds): a pass over the tree a render has no use for.
     */
    static final boolean HASH = Boolean.getBoolean("ray.bvh.hash");
    private final long structureHash;
    /** One {@link LightBuffer} per point light the build was given, where they pay; else null. */
    private final LightBuffer[] lightBuffers;

    private Bvh(Scene scene, BvhBuilder b, List<Surface> bounded, List<Surface> unboundedList, long buildNanos, int wideNodes,
                double[] pointLights, double raysPerLight) {
        this.scene = scene;
        this.root = b.root;
        this.rootBox = b.rootBox;
        this.nodeCount = b.nodeChild.length / 2;
        float[] binary = pack(b.nodeBox, b.nodeChild);
        this.lightBuffers = lightBuffers(binary, pointLights, raysPerLight);
        this.wide = root >= 0 && nodeCount >= wideNodes ? new Wide4(binary, root, nodeCount) : null;
        this.node = wide == null ? binary : null;
        this.buildNanos = buildNanos;
        this.structureHash = HASH ? b.structureHash() : 0;
        this.primitives = bounded.size() + unboundedList.size();
        int n = b.order.length;
        // the set of each primitive, numbered in order of first appearance (deterministic)
        Map<PrimitiveSet.Type, Integer> typeIds = new IdentityHashMap<>();
        List<PrimitiveSet.Type> types = new ArrayList<>();
        int[] typeOf = new int[bounded.size()];
        int[] count = new int[4];
        PrimitiveSet.Type lastType = null;
        int lastId = -1;
        for (int i = 0; i < typeOf.length; i++) {
            PrimitiveSet.Type t = typeOf(bounded.get(i));
            if (t != lastType) {          // a scene is mostly long runs of one type: one map lookup per run
                Integer id = typeIds.get(t);
                if (id == null) {
                    id = types.size();
                    typeIds.put(t, id);
                    types.add(t);
                    if (id == count.length) {
                        count = Arrays.copyOf(count, 2 * id);
                    }
                }
                lastType = t;
                lastId = id;
            }
            typeOf[i] = lastId;
            count[lastId]++;
        }
        int[] order = b.order, leaves = leaves(root, b.nodeChild);
        groupLeavesByType(order, typeOf, leaves);
        // each set's surfaces in slot order, so a run of slots is a run of indices in its set
        Surface[][] members = new Surface[types.size()][];
        for (int t = 0; t < members.length; t++) {
            members[t] = new Surface[count[t]];
            count[t] = 0;
        }
        int[] run = new int[n], index = new int[n];
        for (int i = 0; i < n; i++) {
            int p = order[i], t = typeOf[p];
            int k = count[t]++;
            index[i] = k;
            members[t][k] = bounded.get(p);
        }
        sets = new PrimitiveSet[types.size()];
        for (int t = 0; t < sets.length; t++) {
            sets[t] = types.get(t).pack(Arrays.asList(members[t]));
            sets[t].id(t);
        }
        for (int leaf : leaves) {
            for (int i = leaf >>> 4, end = i + (leaf & 15); i < end; ) {
                int t = typeOf[order[i]], j = i + 1;
                while (j < end && typeOf[order[j]] == t) {
                    j++;
                }
                run[i] = t << 4 | (j - i);
                i = j;
            }
        }
        boolean one = sets.length == 1;
        onlySet = one ? sets[0] : null;
        slotRun = one ? null : run;
        slotIndex = one ? null : index;
        if (unboundedList.isEmpty()) {
            unbounded = null;
        } else {
            unbounded = SurfaceSet.TYPE.pack(unboundedList);
            unbounded.id(sets.length);
        }
    }

    /**
     * The light buffers of the points at {@code pointLights} over the leaves of the tree whose nodes are
     * {@code binary} ({@link #NODE} floats a node), sharing the leaves' boxes and references; null when there is no point, where they do not pay ({@link #build(List, Scene, double[], double)}; any
     * tree when {@code raysPerLight} is infinite, the empty one aside), or for more leaves than a buffer takes.
     */
    private LightBuffer[] lightBuffers(float[] binary, double[] pointLights, double raysPerLight) {
        int leaves = root < 0 ? 1 : nodeCount + 1;   // a binary tree of k inner nodes has k + 1 leaves
        boolean pays = raysPerLight == Double.POSITIVE_INFINITY
                || nodeCount >= LIGHT_BUFFER_NODES && raysPerLight >= LIGHT_BUFFER_RAYS_PER_LEAF * leaves;
        if (!LIGHT_BUFFERS || pointLights == null || pointLights.length < 3 || !pays || root == ~0
                || leaves > LightBuffer.INDEX_MASK) {   // root ~0: no primitive
            return null;
        }
        // a squared distance between a light and a box must stay finite (a NaN coordinate fails too)
        for (float f : rootBox) {
            if (!(Math.abs(f) <= LightBuffer.REACH)) {
                return null;
            }
        }
        for (double c : pointLights) {
            if (!(Math.abs(c) <= LightBuffer.REACH)) {
                return null;
            }
        }
        float[] box = new float[6 * leaves];
        int[] code = new int[leaves];
        int k = 0;
        if (root < 0) {
            System.arraycopy(rootBox, 0, box, 0, 6);
            code[k++] = ~root;
        } else {
            for (int i = 0; i < nodeCount; i++) {
                for (int c = 0; c < 2; c++) {
                    int ref = Float.floatToRawIntBits(binary[NODE * i + 12 + c]);
                    if (ref < 0) {
                        System.arraycopy(binary, NODE * i + 6 * c, box, 6 * k, 6);
                        code[k++] = ~ref;
                    }
                }
            }
        }
        float[] leafBox = Arrays.copyOf(box, 6 * k);
        int[] leafCode = Arrays.copyOf(code, k);
        LightBuffer[] out = new LightBuffer[LightBuffer.lightsFor(pointLights.length / 3, k)];
        if (out.length == 0) {
            return null;
        }
        for (int l = 0; l < out.length; l++) {
            out[l] = new LightBuffer(pointLights[3 * l], pointLights[3 * l + 1], pointLights[3 * l + 2], leafBox, leafCode);
        }
        return out;
    }

    private static PrimitiveSet.Type typeOf(Surface s) {
        PrimitiveSet.Type t = s.packedType();
        return t == null ? SurfaceSet.TYPE : t;
    }

    /** The builder's boxes and child references, interleaved per node ({@link #node}). */
    private static float[] pack(float[] box, int[] child) {
        int n = child.length / 2;
        float[] out = new float[NODE * n];
        for (int i = 0; i < n; i++) {
            System.arraycopy(box, 12 * i, out, NODE * i, 12);
            for (int c = 0; c < 2; c++) {
                int ref = child[2 * i + c];
                float bits = Float.intBitsToFloat(ref);   // a leaf's reference may be a NaN's bits
                if (Float.floatToRawIntBits(bits) != ref) {
                    throw new IllegalStateException("this JVM does not keep a float's NaN bits: " + ref);
                }
                out[NODE * i + 12 + c] = bits;
            }
        }
        return out;
    }

    /** Every leaf of the tree under {@code root}, as {@code first slot << 4 | count}. */
    private static int[] leaves(int root, int[] nodeChild) {
        int[] out = new int[nodeChild.length / 2 + 1];
        int n = 0;
        if (root < 0) {
            out[n++] = ~root;
        }
        for (int c : nodeChild) {
            if (c < 0) {
                out[n++] = ~c;
            }
        }
        return Arrays.copyOf(out, n);
    }

    /** Stable-sorts each leaf's slots by set, so a leaf is a few runs of one set each. */
    private static void groupLeavesByType(int[] order, int[] typeOf, int[] leaves) {
        for (int leaf : leaves) {
            int first = leaf >>> 4;
            for (int i = first + 1, end = first + (leaf & 15); i < end; i++) {   // insertion sort: <= 15 slots
                int p = order[i], j = i;
                while (j > first && typeOf[order[j - 1]] > typeOf[p]) {
                    order[j] = order[j - 1];
                    j--;
                }
                order[j] = p;
            }
        }
    }

    /**
     * Builds the BVH over the primitives of {@code sceneSurfaces} ({@link Surface#collectPrimitives}),
     * leaving out those that can never be hit.
     */
    public static Bvh build(List<Surface> sceneSurfaces, Scene scene) {
        return build(sceneSurfaces, scene, WIDE ? WIDE_NODES : Integer.MAX_VALUE);
    }

    /**
     * {@link #build(List, Scene)} with a light buffer ({@link LightBuffer}) for each point light at
     * {@code pointLights[3k..3k+2]} (null or empty: none), where they pay: the tree has
     * {@link #LIGHT_BUFFER_NODES} inner nodes or more, and a render's {@code raysPerLight} (the shadow rays it
     * may cast toward one light: its camera rays, a shadow ray each at their hits) are at least
     * {@link #LIGHT_BUFFER_RAYS_PER_LEAF} a leaf. The shadow rays that end at one of them then test only the
     * leaves seen from it in their direction.
     */
    public static Bvh build(List<Surface> sceneSurfaces, Scene scene, double[] pointLights, double raysPerLight) {
        // finite: an infinite count is the tests' way to buffers for any tree, never a render's
        return build(sceneSurfaces, scene, WIDE ? WIDE_NODES : Integer.MAX_VALUE, pointLights,
                Math.min(raysPerLight, Double.MAX_VALUE));
    }

    /**
     * Inner nodes from which a tree gets light buffers: in a small tree a shadow ray's traversal costs less
     * than finding its cell (classic's one node: 1.25x the CPU with buffers; scenes/mesh.txt's 177: 1.05x;
     * scenes/showcase.txt's 252: 0.93-0.94x; spheres10k's 2,430: 0.91-0.98x).
     */
    static final int LIGHT_BUFFER_NODES = Integer.getInteger("ray.lightBuffer.nodes", 200);
    /**
     * Shadow rays a light per leaf from which the light buffers pay for their making (about 50 bytes of
     * entries a leaf and light, a few milliseconds a light for ten thousand leaves): mesh100k's 480,000 camera
     * rays over 30,000 leaves (16 a leaf) did not, 7.7 M (256 a leaf) did, and spheres10k's 480,000 over 2,500.
     */
    static final int LIGHT_BUFFER_RAYS_PER_LEAF = Integer.getInteger("ray.lightBuffer.raysPerLeaf", 64);

    /** Whether light buffers are made at all ({@code -Dray.lightBuffer=false}: never, to compare). */
    static final boolean LIGHT_BUFFERS = !"false".equals(System.getProperty("ray.lightBuffer"));

    /**
     * {@link #build(List, Scene)}, traversed wide ({@link Wide4}) when the tree has at least
     * {@code wideNodes} inner nodes (the module {@code jdk.incubator.vector} must then be present).
     */
    static Bvh build(List<Surface> sceneSurfaces, Scene scene, int wideNodes) {
        return build(sceneSurfaces, scene, wideNodes, null, 0);
    }

    /**
     * {@link #build(List, Scene, int)} with light buffers at {@code pointLights}, made where they pay for a
     * render of {@code raysPerLight} shadow rays a light ({@link #build(List, Scene, double[], double)}), or
     * whatever the tree's size when {@code raysPerLight} is infinite (the tests' way to reach them).
     */
    static Bvh build(List<Surface> sceneSurfaces, Scene scene, int wideNodes, double[] pointLights, double raysPerLight) {
        long t0 = System.nanoTime();
        List<Surface> surfaces = new ArrayList<>(sceneSurfaces.size());
        for (Surface s : sceneSurfaces) {
            s.addPrimitives(surfaces);
        }
        List<Surface> bounded = new ArrayList<>(surfaces.size());
        List<Surface> unbounded = new ArrayList<>();
        // rounded outward to floats here, kept as the builder keeps them (BvhBuilder.key): no double copy of every box
        int[] box = new int[6 * surfaces.size()];
        Aabb scratch = new Aabb();
        for (Surface s : surfaces) {
            if (s.isDegenerate()) {
                continue;
            }
            Aabb a = typeOf(s).bounds(s, scratch);   // a built-in type writes it into scratch: no box per primitive
            if (a == null) {     // a user's bounds() returning null: blamed on it, not on the BVH's build
                throw new BadBoundsException(s.getClass());
            }
            if (a.isFinite()) {
                int i = bounded.size();
                box[6 * i] = BvhBuilder.key(BvhBuilder.down(a.minX));
                box[6 * i + 1] = BvhBuilder.key(BvhBuilder.down(a.minY));
                box[6 * i + 2] = BvhBuilder.key(BvhBuilder.down(a.minZ));
                box[6 * i + 3] = BvhBuilder.key(BvhBuilder.up(a.maxX));
                box[6 * i + 4] = BvhBuilder.key(BvhBuilder.up(a.maxY));
                box[6 * i + 5] = BvhBuilder.key(BvhBuilder.up(a.maxZ));
                bounded.add(s);
            } else {
                unbounded.add(s);
            }
        }
        BvhBuilder b = new BvhBuilder(box, bounded.size());
        b.build();
        return new Bvh(scene, b, bounded, unbounded, System.nanoTime() - t0, wideNodes, pointLights, raysPerLight);
    }

    /** The light buffers, or null (tests). */
    LightBuffer[] lightBuffers() {
        return lightBuffers;
    }

    /** Whether this tree is traversed four boxes at a time ({@link Wide4}). */
    boolean isWide() {
        return wide != null;
    }

    /** Inner nodes (a tree of one leaf has none). */
    public int nodeCount() {
        return nodeCount;
    }

    public int primitiveCount() {
        return primitives;
    }

    /** Wall time of {@link #build}, nanoseconds. */
    public long buildNanos() {
        return buildNanos;
    }

    /**
     * The hash of the tree as built ({@link BvhBuilder#structureHash}: node boxes and references, and the
     * primitive of each leaf slot), when the JVM runs with {@code -Dray.bvh.hash=true}; 0 otherwise.
     */
    public long structureHash() {
        return structureHash;
    }

    /** Bytes held by the tree and its packed primitives (not the scene's Surface objects). */
    public long memoryBytes() {
        long m = (wide != null ? wide.memoryBytes() : 4L * node.length)
                + (slotRun == null ? 0 : 4L * slotRun.length + 4L * slotIndex.length);
        if (lightBuffers != null) {
            m += lightBuffers[0].leafBytes();   // the leaves' boxes and references, shared by the buffers
            for (LightBuffer lb : lightBuffers) {
                m += lb.memoryBytes();
            }
        }
        for (PrimitiveSet s : sets) {
            m += s.memoryBytes();
        }
        return m;
    }

    /** This thread's query scratch for this BVH (made on first use, or when the scene was rebuilt). */
    private RayQuery query(TraceContext ctx) {
        Object o = ctx.acceleratorScratch;
        if (o instanceof RayQuery) {
            RayQuery q = (RayQuery) o;
            if (q.owner == this) {
                return q;
            }
        }
        return newQuery(ctx);
    }

    /** {@link #query}'s first use on a thread (kept out of it so C1 inlines the common path). */
    private RayQuery newQuery(TraceContext ctx) {
        RayQuery q = new RayQuery(this, scene, sets.length + 1);
        ctx.acceleratorScratch = q;
        return q;
    }

    /** Inner nodes visited by this thread's queries (counted only with -Dray.bvh.count=true). */
    public long nodeVisits(TraceContext ctx) {
        return query(ctx).nodeVisits;
    }

    /** Primitives tested by this thread's queries (counted only with -Dray.bvh.count=true). */
    public long primitiveTests(TraceContext ctx) {
        return query(ctx).primitiveTests;
    }

    @Override
    public boolean closestHit(Ray ray, IntersectionRecord rec, TraceContext ctx) {
        RayQuery q = query(ctx);
        q.start(ray, rec);
        if (unbounded != null) {
            unbounded.closestHit(0, unbounded.size(), Integer.MAX_VALUE, q);
        }
        double ox = q.ox, oy = q.oy, oz = q.oz, tMin = q.tMin;
        double ix = 1 / q.dx, iy = 1 / q.dy, iz = 1 / q.dz;
        // which of a box's two planes per axis is the near one, from the direction's signs
        boolean sx = ix < 0, sy = iy < 0, sz = iz < 0;
        // the root's own box only when the root is a leaf: an inner root's children are tested anyway,
        // and most rays (all shadow rays) are inside the scene's box
        if (root < 0 && !(slabs(rootBox, 0, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, q.tMax) <= Double.MAX_VALUE)) {
            return finish(q, rec);
        }
        if (wide != null) {
            return wide.closestHit(this, q, rec, ix, iy, iz);
        }
        float[] nb = node;
        int[] run = slotRun, index = slotIndex;
        PrimitiveSet[] ps = sets;
        PrimitiveSet one = onlySet;
        int[] stack = q.stack;
        double[] stackT = q.stackT;
        int sp = 0, ref = root;
        while (true) {
            if (ref >= 0) {
                // inner node: test both children, go to the nearer, keep the farther with its entry distance
                int o = NODE * ref;
                if (COUNT) {
                    q.nodeVisits++;
                }
                double best = q.tMax;
                double lo0 = slabs(nb, o, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, best);
                double lo1 = slabs(nb, o + 6, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, best);
                boolean h0 = lo0 <= Double.MAX_VALUE, h1 = lo1 <= Double.MAX_VALUE;
                if (h0 && h1) {
                    if (lo1 < lo0) {
                        stack[sp] = Float.floatToRawIntBits(nb[o + 12]);
                        stackT[sp++] = lo0;
                        ref = Float.floatToRawIntBits(nb[o + 13]);
                    } else {
                        stack[sp] = Float.floatToRawIntBits(nb[o + 13]);
                        stackT[sp++] = lo1;
                        ref = Float.floatToRawIntBits(nb[o + 12]);
                    }
                    continue;
                } else if (h0) {
                    ref = Float.floatToRawIntBits(nb[o + 12]);
                    continue;
                } else if (h1) {
                    ref = Float.floatToRawIntBits(nb[o + 13]);
                    continue;
                }
            } else {
                hit(~ref, q, one, run, index, ps);
            }
            // pop the nearest pending subtree that may still hold a closer hit. The stack test is sp <= 0,
            // not sp == 0 (the same for a count that never goes below 0), in every closest-hit traversal's
            // pop loop: C2 compiled this loop, which counts sp down to a != exit, as a counted loop guarded
            // by a loop-limit check, which some ray failed a moment into every long render; the trap threw
            // away the whole inlined traversal's code for a recompilation (JFR's jdk.Deoptimization reason
            // "loop_limit_check": 130-300 ms of C2 compilation in classichd, 80-300 ms in mesh1m). With
            // <= the exit needs no such check, and no render showed the trap again
            do {
                if (sp <= 0) {
                    return finish(q, rec);
                }
                ref = stack[--sp];
            } while (stackT[sp] > q.tMax * SLAB_SLACK);
        }
    }

    /**
     * The closest-hit tests of a leaf ({@code first slot << 4 | count}) for query {@code q}: each run of
     * one set's slots handed to its set, which offers its hits ({@link RayQuery#offer}). Named hit so the
     * launcher's {@code CompileCommand=inline,ray.*::hit} inlines it under C1 into both traversals, as
     * when its lines were written out in {@link #closestHit}; the traversal passes the tree's fields
     * it loaded once per query ({@link #onlySet}, {@link #slotRun}, {@link #slotIndex}, {@link #sets}),
     * which C1 would otherwise load again at every leaf.
     */
    private static void hit(int leaf, RayQuery q, PrimitiveSet one, int[] run, int[] index, PrimitiveSet[] ps) {
        int first = leaf >>> 4, end = first + (leaf & 15);
        if (COUNT) {
            q.primitiveTests += leaf & 15;
        }
        if (one != null) {
            one.closestHit(first, end, first, q);
        } else {
            for (int i = first; i < end; ) {
                int r = run[i], len = r & 15, from = index[i];
                ps[r >>> 4].closestHit(from, from + len, i, q);
                i += len;
            }
        }
    }

    /** {@link #hit(int, RayQuery, PrimitiveSet, int[], int[], PrimitiveSet[])} with this tree's sets ({@link Wide4}). */
    void hit(int leaf, RayQuery q) {
        hit(leaf, q, onlySet, slotRun, slotIndex, sets);
    }

    /** Inner nodes from which camera rays are traced in packets ({@link #packetsPay}). */
    static final int PACKET_NODES = Integer.getInteger("ray.bvh.packetNodes", 64);

    @Override
    public boolean packetsPay() {
        return nodeCount >= PACKET_NODES;
    }

    /**
     * The closest hit of each ray of a packet whose rays leave one point with the same direction signs
     * and no zero direction component (a block of camera rays), traced through the tree together: the
     * answers are {@link #closestHit}'s, ray for ray. Any other packet is traced ray by ray.
     *
     * <p>An inner node's two boxes are tested once for the whole packet ({@link #slabs(float[], int,
     * boolean, boolean, boolean, double, double, double, double, double, double, double, double, double,
     * double, double)}: over the range of the rays' inverse directions, against the largest t any ray
     * may still hit at), nearer child first as for one ray. At a leaf each ray tests the leaf's box with
     * its own span ({@link #slabs}) and, when it passes, the leaf's primitives with the same kernels and
     * {@link RayQuery#offer} as its single query, in its own {@link RayQuery}. Every box test is
     * conservative and the tie rule is independent of the order of tests, so each ray gets the closest
     * hit its own query finds.
     */
    @Override
    public void closestHits(RayPacket p, TraceContext ctx) {
        int n = p.size;
        RayQuery q = query(ctx);
        if (n < 2 || root < 0) {
            Accelerator.super.closestHits(p, ctx);   // ray by ray
            return;
        }
        RayQuery[] lanes = q.lanes(n);
        double[] lix = q.laneIx, liy = q.laneIy, liz = q.laneIz;
        Ray r0 = p.rays[0];
        double ox = r0.origin.x, oy = r0.origin.y, oz = r0.origin.z, tMin = r0.tMin;
        boolean sx = r0.direction.x < 0, sy = r0.direction.y < 0, sz = r0.direction.z < 0;
        double ixLo = Double.POSITIVE_INFINITY, ixHi = Double.NEGATIVE_INFINITY, iyLo = ixLo, iyHi = ixHi,
                izLo = ixLo, izHi = ixHi;
        boolean together = true;
        for (int k = 0; k < n; k++) {
            RayQuery l = lanes[k];
            l.start(p.rays[k], p.records[k]);
            double ix = 1 / l.dx, iy = 1 / l.dy, iz = 1 / l.dz;
            // one origin and span, one sign per axis, no infinite inverse (the interval test needs them)
            together &= l.ox == ox && l.oy == oy && l.oz == oz && l.tMin == tMin
                    && (ix < 0) == sx && (iy < 0) == sy && (iz < 0) == sz
                    && Math.abs(ix) <= Double.MAX_VALUE && Math.abs(iy) <= Double.MAX_VALUE && Math.abs(iz) <= Double.MAX_VALUE;
            lix[k] = ix;
            liy[k] = iy;
            liz[k] = iz;
            if (ix < ixLo) ixLo = ix;
            if (ix > ixHi) ixHi = ix;
            if (iy < iyLo) iyLo = iy;
            if (iy > iyHi) iyHi = iy;
            if (iz < izLo) izLo = iz;
            if (iz > izHi) izHi = iz;
        }
        if (!together) {
            Accelerator.super.closestHits(p, ctx);   // ray by ray
            return;
        }
        double far = Double.NEGATIVE_INFINITY;   // the largest t any ray of the packet may still hit at
        for (int k = 0; k < n; k++) {
            RayQuery l = lanes[k];
            if (unbounded != null) {
                unbounded.closestHit(0, unbounded.size(), Integer.MAX_VALUE, l);
            }
            far = Math.max(far, l.tMax);
        }
        if (wide != null) {
            wide.closestHits(this, q, lanes, n, ox, oy, oz, tMin, ixLo, ixHi, iyLo, iyHi, izLo, izHi, far);
            for (int k = 0; k < n; k++) {
                p.hit[k] = finish(lanes[k], p.records[k]);
            }
            return;
        }
        float[] nb = node;
        int[] run = slotRun, index = slotIndex;
        PrimitiveSet[] ps = sets;
        PrimitiveSet one = onlySet;
        int[] stack = q.stack, stackBox = q.stackBox;
        double[] stackT = q.stackT;
        int sp = 0, ref = root, box = 0;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                if (COUNT) {
                    q.nodeVisits++;
                }
                double lo0 = slabs(nb, o, sx, sy, sz, ox, oy, oz, ixLo, ixHi, iyLo, iyHi, izLo, izHi, tMin, far);
                double lo1 = slabs(nb, o + 6, sx, sy, sz, ox, oy, oz, ixLo, ixHi, iyLo, iyHi, izLo, izHi, tMin, far);
                boolean h0 = lo0 <= Double.MAX_VALUE, h1 = lo1 <= Double.MAX_VALUE;
                if (h0 && h1) {
                    if (lo1 < lo0) {
                        stack[sp] = Float.floatToRawIntBits(nb[o + 12]);
                        stackBox[sp] = o;
                        stackT[sp++] = lo0;
                        ref = Float.floatToRawIntBits(nb[o + 13]);
                        box = o + 6;
                    } else {
                        stack[sp] = Float.floatToRawIntBits(nb[o + 13]);
                        stackBox[sp] = o + 6;
                        stackT[sp++] = lo1;
                        ref = Float.floatToRawIntBits(nb[o + 12]);
                        box = o;
                    }
                    continue;
                } else if (h0) {
                    ref = Float.floatToRawIntBits(nb[o + 12]);
                    box = o;
                    continue;
                } else if (h1) {
                    ref = Float.floatToRawIntBits(nb[o + 13]);
                    box = o + 6;
                    continue;
                }
            } else {
                // each ray: the leaf's box with its own span, then the leaf's primitives
                double f = Double.NEGATIVE_INFINITY;
                for (int k = 0; k < n; k++) {
                    RayQuery l = lanes[k];
                    if (slabs(nb, box, sx, sy, sz, ox, oy, oz, lix[k], liy[k], liz[k], tMin, l.tMax) <= Double.MAX_VALUE) {
                        hit(~ref, l, one, run, index, ps);
                    }
                    if (l.tMax > f) {
                        f = l.tMax;
                    }
                }
                far = f;
            }
            do {
                if (sp <= 0) {   // not sp == 0: see closestHit's pop loop
                    for (int k = 0; k < n; k++) {
                        p.hit[k] = finish(lanes[k], p.records[k]);
                    }
                    return;
                }
                ref = stack[--sp];
                box = stackBox[sp];
            } while (stackT[sp] > far * SLAB_SLACK);
        }
    }

    /** Fills the record for the closest hit found (a set of user surfaces has filled it already). */
    static boolean finish(RayQuery q, IntersectionRecord rec) {
        PrimitiveSet s = q.hitSet;
        if (s == null) {
            return false;
        }
        s.fill(q.hitIndex, q, rec);
        return true;
    }

    @Override
    public boolean anyHit(Ray ray, TraceContext ctx) {
        return anyHit(ray, ctx, -1);
    }

    /**
     * The any-hit query with the occluder cache: the primitive that answered this thread's last query
     * of {@code slot}, then the rest of its leaf run (one set's primitives in one leaf), is tested first,
     * and a hit there ends the query; otherwise the traversal runs as always and remembers what it stops
     * at. The answer is the traversal's (the box tests are conservative, so whatever the cached run's own
     * tests hit, the traversal would reach too).
     */
    @Override
    public boolean anyHit(Ray ray, TraceContext ctx, int slot) {
        RayQuery q = query(ctx);
        q.startAny(ray);
        if (unbounded != null && unbounded.anyHit(0, unbounded.size(), q)) {
            return true;
        }
        boolean cache = slot >= 0 && slot < CACHE_SLOTS;
        if (cache) {
            int cs = q.occluderSet[slot];
            if (cs >= 0 && cachedRunHit(q, sets[cs], q.occluderIndex[slot], q.occluderFrom[slot], q.occluderTo[slot])) {
                return true;
            }
        }
        double ox = q.ox, oy = q.oy, oz = q.oz, tMin = q.tMin, tMax = q.tMax;
        double ix = 1 / q.dx, iy = 1 / q.dy, iz = 1 / q.dz;
        if (lightBuffers != null) {   // a shadow ray to a point light: the leaves seen from it that way
            int answer = LightBuffer.anyHit(lightBuffers, this, q, slot, cache, ix, iy, iz);
            if (answer >= 0) {
                return answer > 0 || unshadowed(q, slot, cache);
            }
        }
        boolean sx = ix < 0, sy = iy < 0, sz = iz < 0;
        if (root < 0 && !(slabs(rootBox, 0, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, tMax) <= Double.MAX_VALUE)) {
            return unshadowed(q, slot, cache);
        }
        if (wide != null) {
            return wide.anyHit(this, q, slot, cache, ix, iy, iz);
        }
        float[] nb = node;
        int[] run = slotRun, index = slotIndex;
        PrimitiveSet[] ps = sets;
        PrimitiveSet one = onlySet;
        int[] stack = q.stack;
        int sp = 0, ref = root;
        while (true) {
            if (ref >= 0) {
                int o = NODE * ref;
                if (COUNT) {
                    q.nodeVisits++;
                }
                double lo0 = slabs(nb, o, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, tMax);
                double lo1 = slabs(nb, o + 6, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, tMax);
                boolean h0 = lo0 <= Double.MAX_VALUE, h1 = lo1 <= Double.MAX_VALUE;
                if (h0) {
                    if (h1 && lo1 < lo0) {
                        stack[sp++] = Float.floatToRawIntBits(nb[o + 12]);
                        ref = Float.floatToRawIntBits(nb[o + 13]);
                        continue;
                    }
                    if (h1) {
                        stack[sp++] = Float.floatToRawIntBits(nb[o + 13]);
                    }
                    ref = Float.floatToRawIntBits(nb[o + 12]);
                    continue;
                } else if (h1) {
                    ref = Float.floatToRawIntBits(nb[o + 13]);
                    continue;
                }
            } else if (hit(~ref, q, slot, cache, one, run, index, ps)) {
                return true;
            }
            if (sp == 0) {
                return unshadowed(q, slot, cache);
            }
            ref = stack[--sp];
        }
    }

    /**
     * The end of an any-hit query that found nothing (both traversals'): the occluder cache of {@code slot}
     * (when {@code cache}) is emptied, so the next ray of that slot traverses at once. Returns false.
     */
    static boolean unshadowed(RayQuery q, int slot, boolean cache) {
        if (cache) {
            q.occluderSet[slot] = -1;
        }
        return false;
    }

    /**
     * The any-hit tests of a leaf ({@code first slot << 4 | count}) for query {@code q}: each run of one
     * set's slots handed to its set until one is hit, which is then remembered for occluder-cache slot
     * {@code slot} (when {@code cache}). Named hit for the launcher's C1 inlining, as the closest-hit one.
     */
    private boolean hit(int leaf, RayQuery q, int slot, boolean cache, PrimitiveSet one, int[] run, int[] index, PrimitiveSet[] ps) {
        int first = leaf >>> 4, end = first + (leaf & 15);
        if (COUNT) {
            q.primitiveTests += leaf & 15;
        }
        if (one != null) {
            if (one.anyHit(first, end, q)) {
                if (cache) {
                    remember(q, slot, 0, first, end - first);
                }
                return true;
            }
            return false;
        }
        for (int i = first; i < end; ) {
            int r = run[i], len = r & 15, from = index[i];
            if (ps[r >>> 4].anyHit(from, from + len, q)) {
                if (cache) {
                    remember(q, slot, r >>> 4, from, len);
                }
                return true;
            }
            i += len;
        }
        return false;
    }

    /** The any-hit {@code hit} with this tree's sets ({@link Wide4}). */
    boolean hit(int leaf, RayQuery q, int slot, boolean cache) {
        return hit(leaf, q, slot, cache, onlySet, slotRun, slotIndex, sets);
    }

    /**
     * The occluder cache's test: the remembered primitive {@code hit} first (the one that stopped the last
     * ray: most often it stops this one too), then the rest of its leaf run [from, to) (a neighbouring
     * ray is often stopped by a neighbouring primitive).
     */
    private static boolean cachedRunHit(RayQuery q, PrimitiveSet set, int hit, int from, int to) {
        if (COUNT) {
            q.primitiveTests++;
        }
        if (set.anyHit(hit, hit + 1, q)) {
            return true;
        }
        if (COUNT) {
            q.primitiveTests += to - from - 1;
        }
        return to - from > 1 && (set.anyHit(from, hit, q) || set.anyHit(hit + 1, to, q));
    }

    /**
     * Caches, for {@code slot}, the leaf run {@code from..from+len-1} of set {@code set} that stopped the
     * ray, and which of its primitives did.
     */
    private void remember(RayQuery q, int slot, int set, int from, int len) {
        int hit = from;
        for (int i = from; len > 1 && i < from + len; i++) {   // (a run of one: no test to repeat)
            if (COUNT) {
                q.primitiveTests++;
            }
            if (sets[set].anyHit(i, i + 1, q)) {
                hit = i;
                break;
            }
        }
        q.occluderSet[slot] = set;
        q.occluderIndex[slot] = hit;
        q.occluderFrom[slot] = from;
        q.occluderTo[slot] = from + len;
    }

    /**
     * The packet's slab test of the box at {@code b[o..o+5]}, for rays from one origin whose inverse
     * directions lie in [ixLo, ixHi] x [iyLo, iyHi] x [izLo, izHi] (finite, one sign per axis, told by
     * {@code sx, sy, sz}), over [tMin, tMax]: a lower bound of the rays' entry distances, or +infinity
     * when no ray of the packet can meet the box. Per axis the near plane's distance is the least of the
     * rays' and the far plane's the greatest: a plane distance (p - o) / d is monotonic in the inverse,
     * and so is its rounded product, so the bounds are the very values {@link #slabs} computes for the
     * rays at the ends of the range, and the interval holds every ray's interval.
     */
    private static double slabs(float[] b, int o, boolean sx, boolean sy, boolean sz,
                                double ox, double oy, double oz, double ixLo, double ixHi, double iyLo, double iyHi,
                                double izLo, double izHi, double tMin, double tMax) {
        double lo = tMin, hi = tMax, a, c, n, f;
        if (sx) {
            a = b[o + 3] - ox; c = b[o] - ox;
        } else {
            a = b[o] - ox; c = b[o + 3] - ox;
        }
        n = a >= 0 ? a * ixLo : a * ixHi;
        f = c >= 0 ? c * ixHi : c * ixLo;
        if (n > lo) lo = n;
        if (f < hi) hi = f;
        if (sy) {
            a = b[o + 4] - oy; c = b[o + 1] - oy;
        } else {
            a = b[o + 1] - oy; c = b[o + 4] - oy;
        }
        n = a >= 0 ? a * iyLo : a * iyHi;
        f = c >= 0 ? c * iyHi : c * iyLo;
        if (n > lo) lo = n;
        if (f < hi) hi = f;
        if (sz) {
            a = b[o + 5] - oz; c = b[o + 2] - oz;
        } else {
            a = b[o + 2] - oz; c = b[o + 5] - oz;
        }
        n = a >= 0 ? a * izLo : a * izHi;
        f = c >= 0 ? c * izHi : c * izLo;
        if (n > lo) lo = n;
        if (f < hi) hi = f;
        return lo <= hi * SLAB_SLACK ? lo : Double.POSITIVE_INFINITY;
    }

    /**
     * Slab test of the box at {@code b[o..o+5]} (min xyz, max xyz) against the ray over [tMin, tMax]: the
     * entry distance, or +infinity on a miss. Both planes of an axis are read at fixed offsets, the near
     * one told by the direction's sign ({@code sx}: x decreasing along the ray, so the max plane is the
     * near one); a NaN slab distance (origin on the plane, direction parallel) leaves the interval as it
     * was: conservative. The one box test of the BVH (the launcher lets C1 inline it).
     */
    static double slabs(float[] b, int o, boolean sx, boolean sy, boolean sz,
                                double ox, double oy, double oz, double ix, double iy, double iz,
                                double tMin, double tMax) {
        double lo = tMin, hi = tMax, n, f;
        if (sx) {
            n = (b[o + 3] - ox) * ix; f = (b[o] - ox) * ix;
        } else {
            n = (b[o] - ox) * ix; f = (b[o + 3] - ox) * ix;
        }
        if (n > lo) lo = n;
        if (f < hi) hi = f;
        if (sy) {
            n = (b[o + 4] - oy) * iy; f = (b[o + 1] - oy) * iy;
        } else {
            n = (b[o + 1] - oy) * iy; f = (b[o + 4] - oy) * iy;
        }
        if (n > lo) lo = n;
        if (f < hi) hi = f;
        if (sz) {
            n = (b[o + 5] - oz) * iz; f = (b[o + 2] - oz) * iz;
        } else {
            n = (b[o + 2] - oz) * iz; f = (b[o + 5] - oz) * iz;
        }
        if (n > lo) lo = n;
        if (f < hi) hi = f;
        return lo <= hi * SLAB_SLACK ? lo : Double.POSITIVE_INFINITY;
    }
}
