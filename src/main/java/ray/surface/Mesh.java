package ray.surface;

import java.util.List;
import ray.IntersectionRecord;
import ray.Ray;
import ray.Scene;
import ray.TraceContext;
import ray.accel.Aabb;
import ray.accel.Bvh;

/**
 * A triangle mesh from a Wavefront OBJ file (read by the parser, {@code ray.parse.ObjFile}, which hands
 * the triangles over through {@link #setTriangles}: faces of more than three corners are split into fans). Its triangles go into the scene's BVH one by one ({@link #collectPrimitives}),
 * packed and tested with {@link Triangle}'s watertight kernel, so a mesh of millions of triangles is
 * traced in logarithmic time.
 *
 * <pre>
 * Surface Mesh
 * String file model.obj   # relative to the scene file's folder
 * ref material white
 * int smooth 1            # 1 (default): interpolate the file's vertex normals (vn) where it has them
 * int twoSided 0          # 0 (default): one-sided like Triangle; 1: seen from both sides
 * </pre>
 *
 * Faces face the side from which their corners run counter-clockwise (Triangle's
 * {@code (v1 - v0) x (v2 - v0)}). A one-sided mesh is hit only from that side; a two-sided one from
 * both, with {@code frontFace} false and the normal turned to the ray on the back. Smooth normals are
 * the corners' {@code vn} weighted by the hit's barycentric coordinates, on the side of the facet the
 * ray sees. A mesh is closed ({@link #isClosed}, so a CSG operand) when it is two-sided and every
 * edge belongs to exactly two faces running along it in opposite directions.
 */
public class Mesh extends Surface {

    /** The OBJ file, relative to the scene file's folder. */
    public String file;
    /** 1: interpolate the file's vertex normals where it has them; 0: flat facets. */
    public int smooth = 1;
    /** 0: one-sided; 1: seen from both sides. */
    public int twoSided = 0;

    private String shown;
    private float[] positions = new float[0], normals = new float[0];
    private int[] triangles = new int[0];
    /** Per corner the normal index, or -1; null for flat shading. */
    private int[] cornerNormals;
    private Aabb box;
    private String openReason;
    private boolean topologyChecked;
    /** For {@link #intersects} called directly (a CSG operand): a BVH over this mesh alone, made on first use. */
    private volatile Bvh own;
    private final ThreadLocal<TraceContext> ownContext = new ThreadLocal<>();

    @Override
    public void init() {
        if (file == null || file.isBlank()) {
            throw new IllegalArgumentException("no OBJ file (expected 'String file <name>.obj', relative to the scene file)");
        }
        if (smooth != 0 && smooth != 1) {
            throw new IllegalArgumentException("smooth is " + smooth + " (expected 0 for flat facets or 1 for smooth normals)");
        }
        if (twoSided != 0 && twoSided != 1) {
            throw new IllegalArgumentException("twoSided is " + twoSided + " (expected 0 for one-sided or 1 for two-sided)");
        }
    }

    /**
     * Takes the triangles read from {@code file} (shown as {@code source} in messages): float xyz
     * positions and normals, three position indices per triangle and, per corner, a normal index or -1
     * ({@code cornerNormals} null for a file without normals). Throws IllegalArgumentException for a file
     * without faces, or an open mesh whose material needs an inside ({@code Material.needsInside()}).
     */
    public void setTriangles(float[] positions, float[] normals, int[] triangles, int[] cornerNormals, String source) {
        if (triangles.length == 0) {
            throw new IllegalArgumentException("the OBJ file " + source + " has no faces (expected at least one 'f' line)");
        }
        shown = source;
        this.positions = positions;
        this.normals = unit(normals);
        this.triangles = triangles;
        this.cornerNormals = smooth == 1 ? cornerNormals : null;
        // only referenced vertices count: a file may hold vertices no face uses
        Aabb b = new Aabb();
        for (int c : triangles) {
            b.include(positions[3 * c], positions[3 * c + 1], positions[3 * c + 2]);
        }
        box = b;
        topologyChecked = false;
        own = null;
        if (material != null && material.needsInside() && !isClosed()) {
            throw new IllegalArgumentException("a Mesh with a " + material.getClass().getSimpleName() + " must be closed: "
                    + notClosedReason() + " (glass needs an inside)");
        }
    }

    /** The normals scaled to length 1 (an OBJ's need not be), so each corner weighs only by its barycentric. */
    private static float[] unit(float[] n) {
        float[] u = new float[n.length];
        for (int i = 0; i < n.length; i += 3) {
            double x = n[i], y = n[i + 1], z = n[i + 2], len = Math.sqrt(x * x + y * y + z * z);
            u[i] = (float) (x / len);
            u[i + 1] = (float) (y / len);
            u[i + 2] = (float) (z / len);
        }
        return u;
    }

    public int triangleCount() {
        return triangles.length / 3;
    }

    /** One primitive per triangle. */
    @Override
    public long primitiveCount() {
        return triangleCount();
    }

    /** Corner {@code k} (0..2) of triangle {@code t}, into {@code out}. */
    public void corner(int t, int k, javax.vecmath.Vector3d out) {
        out.set(coordinate(t, k, 0), coordinate(t, k, 1), coordinate(t, k, 2));
    }

    /** Coordinate {@code c} (0..2) of corner {@code k} (0..2) of triangle {@code t}. */
    double coordinate(int t, int k, int c) {
        return positions[3 * triangles[3 * t + k] + c];
    }

    @Override
    public Aabb bounds() {
        return box == null ? new Aabb(0, 0, 0, 0, 0, 0) : new Aabb(box.minX, box.minY, box.minZ, box.maxX, box.maxY, box.maxZ);
    }

    /** Two-sided, and every edge in exactly two faces running along it in opposite directions. */
    @Override
    public boolean isClosed() {
        return notClosedReason() == null;
    }

    /** Why the mesh is not closed, or null when it is. */
    public synchronized String notClosedReason() {
        if (twoSided != 1) {
            return "it is one-sided, and a closed mesh needs 'int twoSided 1'";
        }
        if (!topologyChecked) {
            String edge = MeshTopology.openEdge(positions, triangles);
            openReason = edge == null ? null : (shown == null ? "" : shown + ": ") + edge;
            topologyChecked = true;
        }
        return openReason;
    }

    /** Each triangle is its own primitive in the BVH. */
    @Override
    public void collectPrimitives(List<Surface> out) {
        for (int t = 0, n = triangleCount(); t < n; t++) {
            out.add(new MeshTriangle(this, t));
        }
    }

    @Override
    public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
        Bvh b = own;
        if (b == null) {
            b = ownBvh(scene);
        }
        TraceContext c = ownContext.get();
        if (c == null) {
            c = new TraceContext(0);
            ownContext.set(c);
        }
        return b.closestHit(ray, record, c);
    }

    private synchronized Bvh ownBvh(Scene scene) {
        if (own == null) {
            own = Bvh.build(List.of(this), scene);
        }
        return own;
    }

    /**
     * Completes a record {@link Triangle#fill} made for triangle {@code t} (point, facet normal, error):
     * the smooth normal from the barycentrics, the back side of a two-sided mesh, the surface, and for a
     * smooth hit the lift that spawned rays start from ({@link IntersectionRecord#lift}).
     */
    void finishHit(int t, double b0, double b1, double b2, boolean back, IntersectionRecord rec) {
        int[] cn = cornerNormals;
        boolean lifted = false;
        if (cn != null) {
            int n0 = 3 * cn[3 * t], n1 = 3 * cn[3 * t + 1], n2 = 3 * cn[3 * t + 2];
            if (n0 >= 0 && n1 >= 0 && n2 >= 0) {
                float[] n = normals;
                double x = b0 * n[n0] + b1 * n[n1] + b2 * n[n2];
                double y = b0 * n[n0 + 1] + b1 * n[n1 + 1] + b2 * n[n2 + 1];
                double z = b0 * n[n0 + 2] + b1 * n[n1 + 2] + b2 * n[n2 + 2];
                double len = Math.sqrt(x * x + y * y + z * z);
                if (len > 0 && len < Double.POSITIVE_INFINITY) {
                    // on the facet's front side (a file's normals may point in): only the facet says which side is hit
                    if (x * rec.normal.x + y * rec.normal.y + z * rec.normal.z < 0) {
                        len = -len;
                    }
                    rec.normal.set(x / len, y / len, z / len);
                    lifted = lift(t, b0, b1, b2, n0, n1, n2, (len < 0) != back ? -1 : 1, rec);
                }
            }
        }
        if (!lifted) {
            rec.liftSurface = null;
        }
        if (back) {
            rec.normal.negate();
            rec.frontFace = false;
        }
        rec.surface = this;
    }

    /**
     * Hanika's shadow-terminator fix ("Hacking the Shadow Terminator", Ray Tracing Gems II, ch. 4, 2021):
     * a flat facet under a smooth normal shadows itself near the terminator, so rays leave from the point
     * the corners' tangent planes (of their normals, {@code sign} turning them to the side the ray sees)
     * would have: each corner's vector to the hit, with its part below that corner's tangent plane taken
     * out, blended with the barycentrics. On a facet that curves away (a convex part) this lifts the point
     * off the flat facet by about the curved surface's height there; on a concave part it is the hit
     * itself. Stored as a displacement, used only by {@link IntersectionRecord}'s offset of spawned rays.
     */
    private boolean lift(int t, double b0, double b1, double b2, int n0, int n1, int n2, int sign, IntersectionRecord rec) {
        float[] n = normals;
        double px = rec.location.x, py = rec.location.y, pz = rec.location.z;
        // per corner k: b_k times the part of (p - corner) below the corner's tangent plane, along its normal
        int c0 = 3 * triangles[3 * t], c1 = 3 * triangles[3 * t + 1], c2 = 3 * triangles[3 * t + 2];
        double k0 = b0 * below(px, py, pz, c0, n0, sign), k1 = b1 * below(px, py, pz, c1, n1, sign),
                k2 = b2 * below(px, py, pz, c2, n2, sign);
        double lx = sign * (k0 * n[n0] + k1 * n[n1] + k2 * n[n2]);
        double ly = sign * (k0 * n[n0 + 1] + k1 * n[n1 + 1] + k2 * n[n2 + 1]);
        double lz = sign * (k0 * n[n0 + 2] + k1 * n[n1 + 2] + k2 * n[n2 + 2]);
        if (!(lx != 0 || ly != 0 || lz != 0) || !Double.isFinite(lx + ly + lz)) {
            return false;
        }
        rec.lift.set(lx, ly, lz);
        rec.liftSurface = this;
        rec.liftT = rec.t;
        return true;
    }

    /** -min(0, (p - corner) . n) / |n|^2 for corner position index {@code c} and normal index {@code m} ({@code sign} turning n). */
    private double below(double px, double py, double pz, int c, int m, int sign) {
        float[] n = normals;
        double nx = sign * n[m], ny = sign * n[m + 1], nz = sign * n[m + 2];
        double nn = nx * nx + ny * ny + nz * nz;
        double d = (px - positions[c]) * nx + (py - positions[c + 1]) * ny + (pz - positions[c + 2]) * nz;
        return d < 0 && nn > 0 ? -d / nn : 0;
    }

    boolean twoSided() {
        return twoSided == 1;
    }

    @Override
    public String toString() {
        return "Mesh[" + (shown != null ? shown : file) + ", " + triangleCount() + " triangles"
                + (twoSided == 1 ? ", two-sided" : "") + (cornerNormals != null ? ", smooth" : "") + "]";
    }
}
