package ray.parse;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import ray.Scene;
import ray.surface.Surface;

/**
 * What the parser does once the last line is read: the scene must have its size and a camera and fit
 * its sampler's pixel budget; a camera without an aspect ratio takes the image's; CSG operands leave
 * the list of rendered surfaces (they render through their CSG); the objects' plausibility warnings and
 * one line for all zero-area triangles join the warnings.
 */
final class PostPass {

    private PostPass() {
    }

    /**
     * Finishes {@code scene}; {@code globalLines} holds each global's line, {@code endLine} is the
     * file's last line (where a missing setting is reported).
     */
    static Scene finish(String file, Scene scene, SceneObjects objects, Map<String, Integer> globalLines, int endLine,
            List<String> warnings) throws SceneFormatException {
        for (String side : new String[] {"Width", "Height"}) {
            if (!globalLines.containsKey(side)) {
                throw new SceneFormatException(file, endLine, "no " + side + " (expected '" + side + " <pixels>', e.g. '" + side
                        + (side.equals("Width") ? " 640')" : " 480')"));
            }
        }
        if (scene.camera == null) {
            throw new SceneFormatException(file, endLine, "no camera (expected a 'Camera Camera' object)");
        }
        // the pixel limit of the scene's own sampler (a film costs more than the grid; the render checks
        // again with a sampler the command line or the viewer chose: ray.render.Renderer)
        String tooLarge = ray.settings.PixelBudget.refusal(scene.width, scene.height, scene.sampler);
        if (tooLarge != null) {
            throw new SceneFormatException(file, globalLines.get("Width"), tooLarge);
        }
        if (Double.isNaN(scene.camera.aspect)) {
            scene.camera.aspect = (double) scene.width / scene.height;
            scene.camera.recalculate();
        }
        if (!objects.operands.isEmpty()) {
            List<Surface> rendered = new ArrayList<>(scene.surfaces.size());
            for (Surface s : scene.surfaces) {
                if (!objects.operands.contains(s)) {
                    rendered.add(s);
                }
            }
            scene.surfaces = rendered;
        }
        warnings.addAll(objects.plausibility);
        if (objects.degenerate > 0) {
            warnings.add(file + ":" + objects.firstDegenerateLine + ": warning: zero-area triangle, never hit"
                    + (objects.degenerate > 1 ? " (and " + (objects.degenerate - 1) + " more)" : ""));
        }
        return scene;
    }
}
