package ray.surface;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import ray.accel.LaneKernel;
import ray.accel.LaneRays;
import ray.accel.RayQuery;

/**
 * {@link Triangle}'s watertight kernel for four rays at a time in the lanes of a vector
 * ({@link LaneKernel}): {@link Triangle#setupRay}'s set-up and the kernel's shear, edge functions,
 * parallel test and division, each lane doing the scalar kernel's operations in its order, so each ray's
 * t and barycentrics are the scalar kernel's bit for bit. The set-up picks the ray's axes (dominant axis,
 * and the order of the other two by its sign); four rays that share them are tested together, and four
 * that do not (at a boundary between dominant axes of the image) go through the scalar kernel ray by
 * ray. Loaded only with the Vector API's module.
 */
final class TriangleLanes extends LaneKernel {

    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_256;
    private static final DoubleVector ONE = DoubleVector.broadcast(S, 1.0);

    private final TriangleSet set;
    /** The set's triangles, 9 doubles each (v0, v1, v2). */
    private final double[] v;

    TriangleLanes(TriangleSet set, double[] v) {
        this.set = set;
        this.v = v;
    }

    /**
     * Ray k's axes as {@link Triangle#setupRay} picks them, in one number: 2 kz (its dominant axis) plus
     * 1 where the direction along kz is negative (then kx and ky are swapped).
     */
    private static int axes(LaneRays r, int k) {
        double dx = r.dx[k], dy = r.dy[k], dz = r.dz[k];
        double ax = Math.abs(dx), ay = Math.abs(dy), az = Math.abs(dz);
        int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
        double dkz = kz == 0 ? dx : kz == 1 ? dy : dz;
        return 2 * kz + (dkz < 0 ? 1 : 0);
    }

    @Override
    public void closestHits(LaneRays r, int[] slotOf) {
        double[] tv = v, bt = r.bestT, bi = r.bestIndex, b0 = r.hit0, b1 = r.hit1, b2 = r.hit2;
        int m = tv.length / 9;
        for (int k = 0; k < r.n; k += LaneRays.WIDTH) {
            int axes = axes(r, k);
            if (axes != axes(r, k + 1) || axes != axes(r, k + 2) || axes != axes(r, k + 3)) {
                scalar(r, k, slotOf, m);
                continue;
            }
            int kz = axes >> 1, kx = kz == 2 ? 0 : kz + 1, ky = kx == 2 ? 0 : kx + 1;
            if ((axes & 1) != 0) {
                int tmp = kx;
                kx = ky;
                ky = tmp;
            }
            double[] dkx = component(kx, r.dx, r.dy, r.dz), dky = component(ky, r.dx, r.dy, r.dz),
                    dkz = component(kz, r.dx, r.dy, r.dz);
            DoubleVector dz = DoubleVector.fromArray(S, dkz, k);
            DoubleVector sx = DoubleVector.fromArray(S, dkx, k).div(dz), sy = DoubleVector.fromArray(S, dky, k).div(dz),
                    sz = ONE.div(dz);
            // the origin negated: v - o as v + (-o), the same number
            DoubleVector nx = DoubleVector.fromArray(S, component(kx, r.ox, r.oy, r.oz), k).neg(),
                    ny = DoubleVector.fromArray(S, component(ky, r.ox, r.oy, r.oz), k).neg(),
                    nz = DoubleVector.fromArray(S, component(kz, r.ox, r.oy, r.oz), k).neg();
            DoubleVector tMin = DoubleVector.fromArray(S, r.tMin, k), bound = DoubleVector.fromArray(S, r.bound, k);
            // the nearest hit so far in the thread's arrays, not in vectors carried round the loop (SphereLanes)
            java.util.Arrays.fill(bt, Double.POSITIVE_INFINITY);
            java.util.Arrays.fill(bi, -1);
            for (int i = 0, o = 0; i < m; i++, o += 9) {
                // vertices relative to the origin, in the ray's axis order
                DoubleVector bx = nx.add(tv[o + 3 + kx]), by = ny.add(tv[o + 3 + ky]), bz = nz.add(tv[o + 3 + kz]);
                DoubleVector cx = nx.add(tv[o + 6 + kx]), cy = ny.add(tv[o + 6 + ky]), cz = nz.add(tv[o + 6 + kz]);
                DoubleVector pbx = sx.mul(bz), pby = sy.mul(bz), pcx = sx.mul(cz), pcy = sy.mul(cz);
                DoubleVector qbx = bx.sub(pbx), qby = by.sub(pby), qcx = cx.sub(pcx), qcy = cy.sub(pcy);
                DoubleVector u = qcx.mul(qby).sub(qcy.mul(qbx));
                VectorMask<Double> live = u.compare(VectorOperators.LT, 0).not();
                if (!live.anyTrue()) {
                    continue;
                }
                DoubleVector ax = nx.add(tv[o + kx]), ay = ny.add(tv[o + ky]), az = nz.add(tv[o + kz]);
                DoubleVector pax = sx.mul(az), pay = sy.mul(az);
                DoubleVector qax = ax.sub(pax), qay = ay.sub(pay);
                DoubleVector w0 = qax.mul(qcy).sub(qay.mul(qcx));
                DoubleVector w1 = qbx.mul(qay).sub(qby.mul(qax));
                live = live.and(w0.compare(VectorOperators.LT, 0).not()).and(w1.compare(VectorOperators.LT, 0).not());
                DoubleVector det = u.add(w0).add(w1);
                live = live.and(det.compare(VectorOperators.GT, 0));
                if (!live.anyTrue()) {
                    continue;
                }
                DoubleVector tScaled = sz.mul(u.mul(az).add(w0.mul(bz)).add(w1.mul(cz)));
                live = live.and(tScaled.compare(VectorOperators.LT, tMin.mul(det)).not())
                        .and(tScaled.compare(VectorOperators.GT, bound.mul(det)).not());
                // the parallel test: det within its rounding error of 0
                DoubleVector mAx = ax.abs().add(pax.abs()), mAy = ay.abs().add(pay.abs());
                DoubleVector mBx = bx.abs().add(pbx.abs()), mBy = by.abs().add(pby.abs());
                DoubleVector mCx = cx.abs().add(pcx.abs()), mCy = cy.abs().add(pcy.abs());
                DoubleVector err = mCx.mul(mBy).add(mCy.mul(mBx)).add(mAx.mul(mCy)).add(mAy.mul(mCx)).add(mBx.mul(mAy))
                        .add(mBy.mul(mAx)).mul(Triangle.PARALLEL);
                live = live.and(det.compare(VectorOperators.LE, err).not());
                DoubleVector inv = ONE.div(det);
                DoubleVector t = tScaled.mul(inv);
                DoubleVector best = DoubleVector.fromArray(S, bt, 0);
                VectorMask<Double> nearer = live.and(t.compare(VectorOperators.LT, best));
                if (!nearer.anyTrue()) {
                    continue;
                }
                best.blend(t, nearer).intoArray(bt, 0);
                DoubleVector.fromArray(S, bi, 0).blend(DoubleVector.broadcast(S, (double) i), nearer).intoArray(bi, 0);
                DoubleVector.fromArray(S, b0, 0).blend(u.mul(inv), nearer).intoArray(b0, 0);
                DoubleVector.fromArray(S, b1, 0).blend(w0.mul(inv), nearer).intoArray(b1, 0);
                DoubleVector.fromArray(S, b2, 0).blend(w1.mul(inv), nearer).intoArray(b2, 0);
            }
            for (int j = 0, end = Math.min(LaneRays.WIDTH, r.n - k); j < end; j++) {
                int i = (int) bi[j];
                if (i >= 0) {
                    RayQuery q = r.queries[k + j];
                    if (q.offer(bt[j], set, i, slotOf[i])) {
                        double[] h = q.hitData;
                        h[0] = b0[j];
                        h[1] = b1[j];
                        h[2] = b2[j];
                    }
                }
            }
        }
    }

    /** Rays k..k+3 (those of the packet) that do not share their axes: the scalar kernel, ray by ray. */
    private void scalar(LaneRays r, int k, int[] slotOf, int m) {
        for (int j = k, end = Math.min(k + LaneRays.WIDTH, r.n); j < end; j++) {
            RayQuery q = r.queries[j];
            for (int i = 0; i < m; i++) {
                set.closestHit(i, i + 1, slotOf[i], q);
            }
        }
    }

    private static double[] component(int axis, double[] x, double[] y, double[] z) {
        return axis == 0 ? x : axis == 1 ? y : z;
    }
}
