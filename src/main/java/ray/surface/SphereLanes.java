package ray.surface;

import jdk.incubator.vector.DoubleVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;
import ray.accel.LaneKernel;
import ray.accel.LaneRays;
import ray.accel.RayQuery;

/**
 * {@link Sphere#hit} for four rays at a time in the lanes of a vector ({@link LaneKernel}): each lane
 * does the scalar kernel's operations in its order (the leaving ray's exit, the clear miss, the
 * discriminant from the centre's distance to the line, the stable roots, a zero or NaN root), so each
 * ray's t is the scalar kernel's bit for bit; its early returns are masks, and a vector's rays leave
 * together where the scalar kernel would return for each. Loaded only with the Vector API's module.
 */
final class SphereLanes extends LaneKernel {

    private static final VectorSpecies<Double> S = DoubleVector.SPECIES_256;

    private final SphereSet set;
    /** The set's spheres, 4 doubles each (centre, radius). */
    private final double[] s;

    SphereLanes(SphereSet set, double[] s) {
        this.set = set;
        this.s = s;
    }

    @Override
    public void closestHits(LaneRays r, int[] slotOf) {
        double[] sv = s, bt = r.bestT, bi = r.bestIndex;
        int m = sv.length / 4;
        for (int k = 0; k < r.n; k += LaneRays.WIDTH) {
            DoubleVector ox = DoubleVector.fromArray(S, r.ox, k), oy = DoubleVector.fromArray(S, r.oy, k),
                    oz = DoubleVector.fromArray(S, r.oz, k);
            DoubleVector dx = DoubleVector.fromArray(S, r.dx, k), dy = DoubleVector.fromArray(S, r.dy, k),
                    dz = DoubleVector.fromArray(S, r.dz, k);
            DoubleVector tMin = DoubleVector.fromArray(S, r.tMin, k), tMax = DoubleVector.fromArray(S, r.tMax, k);
            DoubleVector a = dx.mul(dx).add(dy.mul(dy)).add(dz.mul(dz));
            // the ray's own exits: a zero, infinite or NaN direction; and what the leaving-ray exit needs of tMin
            VectorMask<Double> ray = a.compare(VectorOperators.GT, 0).and(a.compare(VectorOperators.NE, Double.POSITIVE_INFINITY));
            VectorMask<Double> tMinPos = tMin.compare(VectorOperators.GT, 0), tMinNonNeg = tMin.compare(VectorOperators.GE, 0);
            // the nearest hit so far lives in the thread's arrays, not in vectors carried round the loop: C2 (JDK
            // 17) keeps a vector that flows round a loop as an object on the heap
            java.util.Arrays.fill(bt, Double.POSITIVE_INFINITY);
            java.util.Arrays.fill(bi, -1);
            for (int i = 0, o = 0; i < m; i++, o += 4) {
                double cx = sv[o], cy = sv[o + 1], cz = sv[o + 2], rad = sv[o + 3];
                DoubleVector fx = ox.sub(cx), fy = oy.sub(cy), fz = oz.sub(cz);
                DoubleVector b = fx.mul(dx).add(fy.mul(dy)).add(fz.mul(dz));
                DoubleVector ff = fx.mul(fx).add(fy.mul(fy)).add(fz.mul(fz));
                DoubleVector c = ff.sub(rad * rad);
                // leaving from outside, heading away (Sphere.hit's first exit, with its tMin = 0 magnitudes)
                VectorMask<Double> leaving = b.compare(VectorOperators.GT, 0).and(c.compare(VectorOperators.GT, 0))
                        .and(tMinNonNeg).and(tMinPos.or(a.mul(ff).compare(VectorOperators.LE, 0x1p1000)
                                .and(c.compare(VectorOperators.GE, a.add(ff).mul(0x1p-900)))
                                .and(b.compare(VectorOperators.GE, a.mul(0x1p-900)))));
                VectorMask<Double> live = ray.and(leaving.not());
                // the clear miss
                DoubleVector qx = fy.mul(dz).sub(fz.mul(dy)), qy = fz.mul(dx).sub(fx.mul(dz)), qz = fx.mul(dy).sub(fy.mul(dx));
                DoubleVector cross = qx.mul(qx).add(qy.mul(qy)).add(qz.mul(qz));
                live = live.and(cross.compare(VectorOperators.GT, a.mul(ff.mul(1e-6).add(rad * rad * (1 + 1e-6)))).not());
                if (!live.anyTrue()) {
                    continue;
                }
                DoubleVector sc = b.div(a);
                DoubleVector lx = fx.sub(sc.mul(dx)), ly = fy.sub(sc.mul(dy)), lz = fz.sub(sc.mul(dz));
                DoubleVector dist = lx.mul(lx).add(ly.mul(ly)).add(lz.mul(lz)).sqrt();
                DoubleVector disc = dist.neg().add(rad).mul(dist.add(rad));
                live = live.and(disc.compare(VectorOperators.LT, 0).not());   // (no exit here: rare, and C2 traps on it)
                DoubleVector root = a.mul(disc).sqrt();
                // -(b + copySign(root, b)): the root takes b's sign bit (-0 included)
                VectorMask<Double> bNeg = b.viewAsIntegralLanes().compare(VectorOperators.LT, 0L).cast(S);
                DoubleVector q = b.add(root.blend(root.neg(), bNeg)).neg();
                VectorMask<Double> q0 = q.compare(VectorOperators.EQ, 0);
                DoubleVector t0 = c.div(q).blend(0, q0), t1 = q.div(a).blend(0, q0);
                VectorMask<Double> ordered = t0.compare(VectorOperators.LE, t1), reversed = t1.compare(VectorOperators.LT, t0);
                live = live.and(ordered.or(reversed));   // a NaN root: a miss
                DoubleVector near = t1.blend(t0, ordered), far = t0.blend(t1, ordered);
                VectorMask<Double> nearIn = near.compare(VectorOperators.GE, tMin).and(near.compare(VectorOperators.LE, tMax));
                VectorMask<Double> farIn = far.compare(VectorOperators.GE, tMin).and(far.compare(VectorOperators.LE, tMax));
                DoubleVector t = far.blend(near, nearIn);
                DoubleVector best = DoubleVector.fromArray(S, bt, 0);
                VectorMask<Double> nearer = live.and(nearIn.or(farIn)).and(t.compare(VectorOperators.LT, best));
                if (nearer.anyTrue()) {
                    best.blend(t, nearer).intoArray(bt, 0);
                    DoubleVector.fromArray(S, bi, 0).blend(DoubleVector.broadcast(S, (double) i), nearer).intoArray(bi, 0);
                }
            }
            for (int j = 0, end = Math.min(LaneRays.WIDTH, r.n - k); j < end; j++) {
                int i = (int) bi[j];
                if (i >= 0) {
                    RayQuery q = r.queries[k + j];
                    q.offer(bt[j], set, i, slotOf[i]);
                }
            }
        }
    }
}
