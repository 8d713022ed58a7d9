/**
 * The course framework's entry point: {@code java RayTracer scene.txt [more.txt ...]} renders each
 * scene to a PNG beside it; with no arguments the Swing viewer opens. Everything lives in
 * {@link ray.app.Main}; this class stays in the default package so the original command works.
 */
public class RayTracer {
    public static void main(String[] args) {
        int status = ray.app.Main.runProcess(args);
        if (status != ray.app.Main.VIEWER_OPEN) {
            System.exit(status);
        }
    }
}
