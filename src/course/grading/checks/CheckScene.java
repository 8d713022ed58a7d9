import java.util.ArrayList;
import java.util.List;
import javax.vecmath.Vector3d;

/** Scene.trace (9), Scene.renderPixel (10) and Scene.renderAll (11), each alone (the grader's own surfaces and camera). */
public final class CheckScene {

    static final String T = "Scene.trace";
    static final String P = "Scene.renderPixel";
    static final String A = "Scene.renderAll";

    /** A surface hit at a fixed t by every ray (when t is in the ray's span), shaded in a fixed colour. */
    static final class HitAt extends Surface {
        final double t;

        HitAt(double t, Vector3d color) {
            this.t = t;
            this.material = new CheckShading.Flat(color);
        }

        @Override
        public boolean intersects(Ray ray, IntersectionRecord record, Scene scene) {
            if (t < ray.tMin || t > ray.tMax) {
                return false;
            }
            record.t = t;
            record.location.set(ray.evaluate(t));
            record.normal.set(0, 0, 1);
            record.surface = this;
            return true;
        }
    }

    static Ray camRay() {
        return new Ray(GraderSupport.v(0, 0, 10), GraderSupport.v(0, 0, -1));
    }

    static void closest(double... ts) {
        Scene s = new Scene();
        StringBuilder list = new StringBuilder();
        for (int i = 0; i < ts.length; i++) {
            s.surfaces.add(new HitAt(ts[i], GraderSupport.v(i, 0, 0)));
            list.append(i > 0 ? ", " : "").append("t = ").append(GraderSupport.str(ts[i]));
        }
        int best = 0;
        for (int i = 1; i < ts.length; i++) {
            if (ts[i] < ts[best]) {
                best = i;
            }
        }
        String situation = "surfaces hit at " + list + " (in this order in scene.surfaces)";
        Vector3d got = GraderSupport.call(T, situation, () -> s.trace(camRay()));
        if (got != null && !GraderSupport.near(got.x, best, 1e-9)) {
            int g = (int) Math.round(got.x);
            throw GraderSupport.fail(T + ": " + situation + ": must shade the CLOSEST hit (t = " + GraderSupport.str(ts[best]) + "); yours shaded "
                    + (g >= 0 && g < ts.length ? "the one at t = " + GraderSupport.str(ts[g]) + (g == ts.length - 1 ? " (the last one "
                    + "listed, not the closest: keep the hit with the smallest t)" : "") : "something else: " + GraderSupport.str(got)));
        }
        GraderSupport.expectVector(T, situation, "the colour (the closest surface's material's shade)", got, GraderSupport.v(best, 0, 0), 1e-9);
    }

    public static void closestHitWins() {
        closest(2, 5);
        closest(5, 2);
        closest(7, 3, 9, 4);
    }

    public static void missGivesBackground() {
        Scene s = new Scene();
        s.backgroundColor = GraderSupport.v(0.1, 0.2, 0.3);
        s.surfaces.add(new HitAt(-1, GraderSupport.v(1, 1, 1)));
        String situation = "a ray that hits nothing (the only surface is behind it), BGColor (0.1, 0.2, 0.3)";
        Vector3d got = GraderSupport.call(T, situation, () -> s.trace(camRay()));
        GraderSupport.expectVector(T, situation, "the colour (BGColor)", got, GraderSupport.v(0.1, 0.2, 0.3), 1e-12);
        got.set(9, 9, 9);
        GraderSupport.expectVector(T, situation + ", then the returned colour changed by the caller", "scene.backgroundColor (return a copy)",
                s.backgroundColor, GraderSupport.v(0.1, 0.2, 0.3), 0);
    }

    public static void depthLimit() {
        Scene s = new Scene();
        s.maxDepth = 2;
        s.surfaces.add(new HitAt(1, GraderSupport.v(1, 1, 1)));
        Ray deep = camRay();
        deep.depth = 3;
        String situation = "MaxDepth 2 and a ray of depth 3 that would hit a white surface";
        Vector3d got = GraderSupport.call(T, situation, () -> s.trace(deep));
        GraderSupport.expectVector(T, situation, "the colour (black: rays deeper than MaxDepth are not followed)", got,
                GraderSupport.v(0, 0, 0), 1e-12);
        Ray ok = camRay();
        ok.depth = 2;
        String situation2 = "MaxDepth 2 and a ray of depth 2 that hits a white surface";
        got = GraderSupport.call(T, situation2, () -> s.trace(ok));
        GraderSupport.expectVector(T, situation2, "the colour (depth 2 is still followed)", got, GraderSupport.v(1, 1, 1), 1e-12);
    }

    /** A camera that hands out rays whose direction is the image point asked for, and counts them. */
    static final class Recorder extends Camera {
        final List<double[]> asked = new ArrayList<>();

        @Override
        public Ray getRayThrough(double x, double y, double width, double height) {
            asked.add(new double[] {x, y, width, height});
            return new Ray(GraderSupport.v(0, 0, 0), GraderSupport.v(x, y, -1));
        }
    }

    /** A scene whose trace returns a colour made from the ray's image point (x, y): (x, y, x^2). */
    static final class PointColours extends Scene {
        @Override
        public Vector3d trace(Ray ray) {
            double x = ray.direction.x, y = ray.direction.y;
            return GraderSupport.v(x, y, x * x);
        }
    }

    public static void oneSampleAtCentre() {
        PointColours s = new PointColours();
        Recorder c = new Recorder();
        s.camera = c;
        s.width = 40;
        s.height = 30;
        s.samplesPerPixel = 1;
        String situation = "AASamples 1, pixel (3, 7) of a 40 x 30 image";
        Vector3d got = GraderSupport.call(P, situation, () -> s.renderPixel(3, 7));
        GraderSupport.expect(c.asked.size() == 1, P + ": " + situation + ": must ask the camera for 1 ray; yours asked for " + c.asked.size());
        double[] a = c.asked.get(0);
        GraderSupport.expect(a[2] == 40 && a[3] == 30, P + ": " + situation + ": must pass the image size (40, 30) to getRayThrough; yours passed ("
                + GraderSupport.str(a[2]) + ", " + GraderSupport.str(a[3]) + ")");
        GraderSupport.expectVector(P, situation, "the colour (the ray through the pixel's centre (3.5, 7.5))", got,
                GraderSupport.v(3.5, 7.5, 12.25), 1e-9);
    }

    public static void supersampling() {
        PointColours s = new PointColours();
        Recorder c = new Recorder();
        s.camera = c;
        s.width = 40;
        s.height = 30;
        s.samplesPerPixel = 3;
        String situation = "AASamples 3, pixel (3, 7)";
        Vector3d got = GraderSupport.call(P, situation, () -> s.renderPixel(3, 7));
        GraderSupport.expect(c.asked.size() == 9, P + ": " + situation + ": must average 3 x 3 = 9 samples; yours traced "
                + c.asked.size() + " ray" + (c.asked.size() == 1 ? " (one sample per pixel: supersampling is missing)" : "s"));
        // the mean of x^2 over the 3 x 3 grid of cell centres x = 3 + (i + 0.5) / 3
        double sq = 0;
        for (int i = 0; i < 3; i++) {
            double x = 3 + (i + 0.5) / 3;
            sq += x * x / 3;
        }
        GraderSupport.expectVector(P, situation, "the colour (the mean over the centres of a 3 x 3 grid of cells in the pixel)", got,
                GraderSupport.v(3.5, 7.5, sq), 1e-9);
    }

    /** A scene whose renderPixel colours each pixel by its position and counts calls. */
    static final class Positions extends Scene {
        int calls;

        @Override
        public Vector3d renderPixel(int x, int y) {
            calls++;
            return GraderSupport.v(x, y, 0);
        }
    }

    public static void wholeImage() {
        Positions s = new Positions();
        s.width = 5;
        s.height = 3;
        String situation = "a 5 x 3 image";
        Vector3d[][] img = GraderSupport.call(A, situation, s::renderAll);
        if (img == null) {
            throw GraderSupport.fail(A + ": " + situation + ": returned null instead of the image");
        }
        GraderSupport.expect(img.length == 5, A + ": " + situation + ": the array must be [width][height] = [5][3]; yours has "
                + img.length + " columns");
        for (int x = 0; x < 5; x++) {
            GraderSupport.expect(img[x] != null && img[x].length == 3, A + ": " + situation + ": column " + x + " must have 3 entries; yours has "
                    + (img[x] == null ? "none (null)" : img[x].length));
            for (int y = 0; y < 3; y++) {
                Vector3d p = img[x][y];
                if (p == null || !GraderSupport.near(p, GraderSupport.v(x, y, 0), 0)) {
                    String hint = p != null && GraderSupport.near(p, GraderSupport.v(x, 2 - y, 0), 0) ? " (upside down: y = 0 is the top row)"
                            : p != null && GraderSupport.near(p, GraderSupport.v(4 - x, y, 0), 0) ? " (mirrored left to right)" : "";
                    throw GraderSupport.fail(A + ": " + situation + ": image[" + x + "][" + y + "] must be renderPixel(" + x + ", " + y
                            + "); yours holds " + (p == null ? "null" : "renderPixel(" + (int) p.x + ", " + (int) p.y + ")") + hint);
                }
            }
        }
        GraderSupport.expect(s.calls == 15, A + ": " + situation + ": must call renderPixel once per pixel (15 times); yours called it "
                + s.calls + " times");
    }
}
