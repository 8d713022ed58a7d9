import java.io.File;
import javax.vecmath.Vector3d;

/** How the grader renders a scene with the submission's classes: the framework's parser, then Scene.renderAll. */
public final class GraderRender {

    private GraderRender() {
    }

    public static Vector3d[][] render(String scene) throws Exception {
        Scene s = Parser.parse(new File(scene));
        s.camera.recalculate();     // as the framework does once after reading a scene
        return s.renderAll();
    }
}
