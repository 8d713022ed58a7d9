package ray.accel;

import java.util.Arrays;

/**
 * A light buffer (Haines and Greenberg 1986) for one point light: the BVH's leaves as seen from the light's
 * position L, sorted into the cells of a cube around L by the directions their boxes cover. A shadow ray
 * that ends at L tests only the leaves of the cell its direction falls in that come nearer to L than the
 * ray's origin, nearest to the origin first (where a shadow ray's occluder most often is), each with the
 * tree's own box test and leaf test; the leaves within a small distance of L (the near list) are tested
 * by every ray.
 *
 * <p>The answer is the tree's, exactly. The tree finds a hit in a leaf when the ray enters the leaf's box
 * (and so, the boxes being nested, every box above it) and one of its primitives' kernels hits; the buffer
 * tests the same box with the same test, then the same primitives with the same kernels. So all that has
 * to hold is that every such leaf is among the ray's candidates:
 * <ul>
 * <li>A kernel's hit lies in its primitive's box, which lies in its leaf's.</li>
 * <li>The ray's points X = O + tD, 0 &lt;= t &lt;= tMax &lt;= 1, lie in the direction -D from L: O + D is L
 * up to the rounding of D = L - O, which {@link #serves} requires to be within 2^-40 of D's largest
 * component (else the tree answers). A point of the ray at 2^-7 of that or more from L is seen from L
 * within 2^-30 radians of -D, which moves it on a face of the cube by less than 2^-28.</li>
 * <li>A leaf's cells are those its box covers seen from L, widened by {@link #WIDEN} (2^-20) on every side,
 * on every face of the cube where the box has any direction, clamped to the face's edge: a leaf whose
 * box holds such a point is in the cell of -D.</li>
 * <li>The points nearer to L are the near list's: every leaf whose box comes within 2^-7 of D's largest
 * component of L.</li>
 * <li>The depth cut compares a lower bound of a box's distance from L with the ray's length, with a margin
 * of 2^-20 of it.</li>
 * <li>A box the tree's test enters holds a point of the ray up to that test's rounding, about 2^-50 of the
 * largest coordinate; {@link #serves} requires D's largest component to be at least 2^-12 of the largest
 * coordinate of O and L, so that this moves a point 2^-7 of D or more from L by less than 2^-31 radians.</li>
 * </ul>
 * {@code LightBufferTest} compares the answers with the tree's on seeded scenes and rays, and fails when
 * the widening or the near list is taken away.
 *
 * <p>Memory per light: a cell index of 6 n^2 ints (n from the leaves, {@link #cellsPerSide}), 12 bytes an
 * entry (about ten entries a leaf), 12 a leaf for the near list. Made by {@link Bvh} where they pay.
 */
final class LightBuffer {

    /** The point light's position, and its largest coordinate's magnitude. */
    final double lx, ly, lz, reach;
    /** Cells along a face's side. */
    private final int n;
    /** Per cell (face, row, column), where its entries start in {@link #leaf} and {@link #near2}; one more at the end. */
    private final int[] start;
    /** The leaves (indices into the tree's leaf arrays) of each cell, nearest to L first. */
    private final int[] leaf;
    /** Per entry, a lower bound of the squared distance from L to the leaf's box. */
    private final double[] near2;
    /**
     * Per leaf of the tree, its box (6 floats: min xyz, max xyz, the tree's own) and its reference's code
     * ({@code first slot << 4 | count}): shared by a tree's buffers.
     */
    private final float[] box;
    private final int[] code;
    /** Every leaf, nearest first, and its distance from L (a lower bound): the near list's order. */
    private final int[] byDistance;
    private final double[] distance;

    /**
     * How far a footprint is widened on a face, in the face's coordinates (-1 to 1): far beyond the 2^-28 by
     * which a direction of the ray, seen from L, can differ from -D's ({@link #serves}) and the rounding of
     * the cell's arithmetic, far below a cell.
     */
    static final double WIDEN = 0x1p-20;

    /**
     * Point lights a tree gets buffers for, the first ones it is given ({@link #lightsFor}): a shadow ray
     * looks for its light among them one by one, and each costs its memory.
     */
    static final int MAX_LIGHTS = 16;
    /**
     * Leaves times lights a tree's buffers may hold: about 130 bytes a leaf and light, so at most about
     * 140 MB (sixteen lights up to 65,536 leaves, one up to 2^20; none beyond).
     */
    static final long MAX_LEAF_LIGHTS = 1L << 20;

    /** How many of {@code lights} point lights a tree of {@code leaves} leaves gets buffers for: the first ones. */
    static int lightsFor(int lights, int leaves) {
        return (int) Math.min(Math.min(lights, MAX_LIGHTS), MAX_LEAF_LIGHTS / Math.max(1, leaves));
    }

    /**
     * The largest coordinate of a light or a box a buffer is made with: every squared distance between
     * them stays finite.
     */
    static final double REACH = 0x1p500;

    /** The low bits of a sort key that hold a leaf's index: a buffer takes at most this many leaves. */
    static final long INDEX_MASK = (1L << 22) - 1;

    /** Cells along a face's side for a tree of {@code leaves} leaves: about 16 cells a leaf on the cube, at most 192. */
    static int cellsPerSide(int leaves) {
        Integer forced = Integer.getInteger("ray.lightBuffer.cells");
        if (forced != null) {
            return Math.max(1, Math.min(1024, forced));
        }
        return (int) Math.max(4, Math.min(192, Math.ceil(Math.sqrt(16.0 * leaves / 6))));
    }

    /**
     * The buffer of the point at ({@code x}, {@code y}, {@code z}) over the leaves whose boxes are
     * {@code box[6i..6i+5]} (min xyz, max xyz) and whose references' codes are {@code code[i]}.
     */
    LightBuffer(double x, double y, double z, float[] box, int[] code) {
        this.box = box;
        this.code = code;
        int count = code.length;
        lx = x;
        ly = y;
        lz = z;
        reach = Math.max(Math.abs(x), Math.max(Math.abs(y), Math.abs(z)));
        n = cellsPerSide(count);
        // each leaf's squared distance from L, rounded down to 30 bits of mantissa, with the leaf's index
        // in the 22 bits below: one sort of longs orders the leaves by that bound (a non-negative double's
        // bits order as the double)
        double[] d2 = new double[count];
        long[] key = new long[count];
        for (int i = 0; i < count; i++) {
            double dx = gap(box[6 * i], box[6 * i + 3], x), dy = gap(box[6 * i + 1], box[6 * i + 4], y),
                    dz = gap(box[6 * i + 2], box[6 * i + 5], z);
            long bits = Double.doubleToRawLongBits((dx * dx + dy * dy + dz * dz) * (1 - 0x1p-40)) & ~INDEX_MASK;
            d2[i] = Double.longBitsToDouble(bits);   // a lower bound
            key[i] = bits | i;
        }
        Arrays.sort(key);
        byDistance = new int[count];
        distance = new double[count];
        for (int k = 0; k < count; k++) {
            int i = (int) (key[k] & INDEX_MASK);
            byDistance[k] = i;
            distance[k] = Math.sqrt(d2[i]) * (1 - 0x1p-40);
        }
        // two passes over the leaves, nearest first, so each cell's entries come out sorted by distance
        int cells = 6 * n * n;
        int[] count0 = new int[cells + 1];
        int[] range = new int[4];
        for (int k = 0; k < count; k++) {
            place(box, byDistance[k], range, count0, null, null, 0);
        }
        for (int c = 0; c < cells; c++) {
            count0[c + 1] += count0[c];
        }
        start = count0;
        leaf = new int[start[cells]];
        near2 = new double[start[cells]];
        int[] fill = Arrays.copyOf(start, cells);
        for (int k = 0; k < count; k++) {
            int i = byDistance[k];
            place(box, i, range, null, fill, leaf, d2[i]);
        }
    }

    /**
     * Leaf {@code i} in each cell of its footprint ({@link #footprint}): counted in {@code counts[cell + 1]}
     * when {@code fill} is null, else written at {@code fill[cell]} (then advanced) into {@code into} and
     * {@link #near2} with {@code d2}.
     */
    private void place(float[] box, int i, int[] range, int[] counts, int[] fill, int[] into, double d2) {
        for (int face = 0; face < 6; face++) {
            if (footprint(box, 6 * i, face, range)) {
                for (int r = range[2]; r <= range[3]; r++) {
                    for (int c = range[0]; c <= range[1]; c++) {
                        int cell = (face * n + r) * n + c;
                        if (fill == null) {
                            counts[cell + 1]++;
                        } else {
                            int e = fill[cell]++;
                            into[e] = i;
                            near2[e] = d2;
                        }
                    }
                }
            }
        }
    }

    /** How far {@code p} lies outside [lo, hi] (0 inside). */
    private static double gap(float lo, float hi, double p) {
        return p < lo ? lo - p : p > hi ? p - hi : 0;
    }

    /**
     * The cells of face {@code face} (axis face / 2, the positive side when even) that the box at
     * {@code box[o..o+5]} covers seen from L, widened by {@link #WIDEN} and clamped to the face: columns
     * {@code range[0..1]}, rows {@code range[2..3]}; false when the box has no direction on that side.
     */
    private boolean footprint(float[] box, int o, int face, int[] range) {
        int a = face >> 1, ua = a == 0 ? 1 : 0, va = a == 2 ? 1 : 2;
        double la = a == 0 ? lx : a == 1 ? ly : lz;
        double zlo, zhi;
        if ((face & 1) == 0) {
            zlo = box[o + a] - la;
            zhi = box[o + 3 + a] - la;
        } else {
            zlo = la - box[o + 3 + a];
            zhi = la - box[o + a];
        }
        if (!(zhi > 0)) {
            return false;
        }
        double lu = ua == 0 ? lx : ly, lv = va == 1 ? ly : lz;
        return cells(box[o + ua] - lu, box[o + 3 + ua] - lu, zlo, zhi, range, 0)
                && cells(box[o + va] - lv, box[o + 3 + va] - lv, zlo, zhi, range, 2);
    }

    /**
     * The cells along one side of a face that directions (p, z), p in [p0, p1], z in [zlo, zhi] with z > 0,
     * fall in (p / z from -1 to 1 over n cells), widened by {@link #WIDEN}: {@code range[at..at+1]}; false when none.
     */
    private boolean cells(double p0, double p1, double zlo, double zhi, int[] range, int at) {
        double lo = p0 >= 0 ? p0 / zhi : zlo > 0 ? p0 / zlo : Double.NEGATIVE_INFINITY;
        double hi = p1 <= 0 ? p1 / zhi : zlo > 0 ? p1 / zlo : Double.POSITIVE_INFINITY;
        double c0 = Math.floor((lo - WIDEN + 1) * 0.5 * n), c1 = Math.floor((hi + WIDEN + 1) * 0.5 * n);
        if (c0 > n - 1 || c1 < 0) {
            return false;
        }
        range[at] = c0 < 0 ? 0 : (int) c0;
        range[at + 1] = c1 > n - 1 ? n - 1 : (int) c1;
        return true;
    }

    /**
     * The buffer of {@code buffers} that answers query {@code q}: a shadow ray from its origin O to the
     * buffer's point (O + D equal to it within 2^-40 of D's largest component, which itself is at least
     * 2^-12 of the largest coordinate of O and L), over 0 &lt;= tMin, tMax &lt;= 1; null for any other ray.
     */
    static LightBuffer serves(LightBuffer[] buffers, RayQuery q) {
        return serves(buffers, q, largest(q));
    }

    /** D's largest component's magnitude. */
    private static double largest(RayQuery q) {
        double adx = Math.abs(q.dx), ady = Math.abs(q.dy), adz = Math.abs(q.dz);
        double dm = adx >= ady ? adx : ady;
        return dm >= adz ? dm : adz;
    }

    /** {@link #serves(LightBuffer[], RayQuery)} for {@code dm}, D's largest component's magnitude. */
    private static LightBuffer serves(LightBuffer[] buffers, RayQuery q, double dm) {
        if (!(q.tMin >= 0 && q.tMax <= 1)) {
            return null;
        }
        double tol = 0x1p-40 * dm;
        double ex = q.ox + q.dx, ey = q.oy + q.dy, ez = q.oz + q.dz;
        for (LightBuffer b : buffers) {
            if (Math.abs(ex - b.lx) <= tol && Math.abs(ey - b.ly) <= tol && Math.abs(ez - b.lz) <= tol) {
                // comparisons, not Math.max: C1 calls that on every shadow ray rather than inlining it
                double m = b.reach, ax = Math.abs(q.ox), ay = Math.abs(q.oy), az = Math.abs(q.oz);
                m = m >= ax ? m : ax;
                m = m >= ay ? m : ay;
                m = m >= az ? m : az;
                return dm >= 0x1p-12 * m && dm > 0 ? b : null;
            }
        }
        return null;
    }

    /**
     * The any-hit answer for query {@code q} of the buffer of {@code buffers} that {@link #serves} it: 1
     * when a leaf of {@code bvh} stops it, 0 when none does, -1 when no buffer serves it (the tree answers).
     * {@code ix..iz}: 1 / D, as the traversal has it; {@code slot}, {@code cache}: the occluder cache's.
     */
    static int anyHit(LightBuffer[] buffers, Bvh bvh, RayQuery q, int slot, boolean cache, double ix, double iy, double iz) {
        double dm = largest(q);
        LightBuffer b = serves(buffers, q, dm);
        return b == null ? -1 : b.anyHit(bvh, q, slot, cache, ix, iy, iz, dm) ? 1 : 0;
    }

    /**
     * Whether a leaf of {@code bvh} stops query {@code q} (a ray this buffer serves; {@code dm}: D's largest
     * component's magnitude): the leaves near L, then the leaves of the cell of -D nearer to L than O, each
     * box tested as the traversal tests it and each leaf entered handed to the tree's leaf test.
     */
    private boolean anyHit(Bvh bvh, RayQuery q, int slot, boolean cache, double ix, double iy, double iz, double dm) {
        double dx = q.dx, dy = q.dy, dz = q.dz;
        double ox = q.ox, oy = q.oy, oz = q.oz, tMin = q.tMin, tMax = q.tMax;
        boolean sx = ix < 0, sy = iy < 0, sz = iz < 0;
        double adx = Math.abs(dx), ady = Math.abs(dy), adz = Math.abs(dz);
        // the near list: every leaf within 2^-7 of D's largest component of L
        double nearLimit = 0x1p-7 * dm;
        for (int k = 0; k < distance.length && distance[k] <= nearLimit; k++) {
            if (hit(bvh, q, byDistance[k], slot, cache, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, tMax)) {
                return true;
            }
        }
        // the cell of -D: the face of its largest component, then its two others over that one
        int face, col, row;
        double u, v, m;
        if (adx >= ady && adx >= adz) {
            face = dx > 0 ? 1 : 0;
            m = adx;
            u = dy;
            v = dz;
        } else if (ady >= adz) {
            face = dy > 0 ? 3 : 2;
            m = ady;
            u = dx;
            v = dz;
        } else {
            face = dz > 0 ? 5 : 4;
            m = adz;
            u = dx;
            v = dy;
        }
        double s = -0.5 * n / m;   // -D's components over its largest, from -1..1 to 0..n
        col = (int) (u * s + 0.5 * n);
        row = (int) (v * s + 0.5 * n);
        col = col < 0 ? 0 : col >= n ? n - 1 : col;
        row = row < 0 ? 0 : row >= n ? n - 1 : row;
        int cell = (face * n + row) * n + col;
        // the cell's leaves that come nearer to L than O, nearest to O first (where a shadow ray's occluder
        // most often is): the cut found by bisection, then the entries before it backwards
        double limit = (dx * dx + dy * dy + dz * dz) * (1 + 0x1p-20);
        int first = start[cell], lo = first, hi = start[cell + 1];
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (near2[mid] <= limit) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        for (int e = lo - 1; e >= first; e--) {
            if (hit(bvh, q, leaf[e], slot, cache, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, tMax)) {
                return true;
            }
        }
        return false;
    }

    /**
     * Leaf {@code i} tested as the traversal tests it: its box, then (entered) its primitives. Named
     * {@code hit}, so the launcher's {@code CompileCommand=inline,ray.*::hit} keeps it inline under C1.
     */
    private boolean hit(Bvh bvh, RayQuery q, int i, int slot, boolean cache, boolean sx, boolean sy, boolean sz,
                        double ox, double oy, double oz, double ix, double iy, double iz, double tMin, double tMax) {
        if (Bvh.COUNT) {
            q.nodeVisits++;
        }
        return Bvh.slabs(box, 6 * i, sx, sy, sz, ox, oy, oz, ix, iy, iz, tMin, tMax) <= Double.MAX_VALUE
                && bvh.hit(code[i], q, slot, cache);
    }

    /** The leaves' boxes and references, which a tree's buffers share. */
    long leafBytes() {
        return 4L * box.length + 4L * code.length;
    }

    /** This buffer's own arrays. */
    long memoryBytes() {
        return 4L * start.length + 4L * leaf.length + 8L * near2.length + 12L * byDistance.length;
    }
}
