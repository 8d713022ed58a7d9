package ray.viewer;

import java.awt.Component;
import java.io.File;
import java.nio.file.Path;
import javax.swing.JFileChooser;
import javax.swing.JOptionPane;
import javax.swing.filechooser.FileNameExtensionFilter;

/** The viewer's file dialogs: choosing a scene, and saving the image shown by {@link SaveRules}. */
final class Dialogs {

    private Dialogs() {
    }

    static Path chooseScene(Component parent, File dir) {
        JFileChooser fc = new JFileChooser(dir);
        fc.setDialogTitle("Open scene");
        fc.setFileFilter(new FileNameExtensionFilter("Scene files (*.txt)", "txt"));
        return fc.showOpenDialog(parent) == JFileChooser.APPROVE_OPTION ? fc.getSelectedFile().toPath() : null;
    }

    /** A PNG to compare the render with; the chooser starts in the scene's {@code reference-images/} when there is one. */
    static Path chooseReference(Component parent, File dir) {
        File refs = new File(dir, "reference-images"), up = new File(dir.getParentFile() == null ? dir : dir.getParentFile(), "reference-images");
        JFileChooser fc = new JFileChooser(refs.isDirectory() ? refs : up.isDirectory() ? up : dir);
        fc.setDialogTitle("Open reference image");
        fc.setFileFilter(new FileNameExtensionFilter("PNG images (*.png)", "png"));
        return fc.showOpenDialog(parent) == JFileChooser.APPROVE_OPTION ? fc.getSelectedFile().toPath() : null;
    }

    /**
     * Asks where to save {@code shown}'s image (suggesting {@code <scene>.png} beside the scene, or
     * {@code <scene>-partial.png} for a stopped render's), asks before replacing a file, refuses the
     * scene files, and writes. Returns the status line to show ({@code Saved /abs/path.png}), or null
     * when nothing was saved.
     */
    static String save(Component parent, RenderJob shown, Path currentScene) {
        boolean partial = shown.partial();
        JFileChooser fc = new JFileChooser();
        fc.setDialogTitle(partial ? "Save partial image as PNG" : "Save image as PNG");
        FileNameExtensionFilter png = new FileNameExtensionFilter("PNG images (*.png)", "png");
        fc.addChoosableFileFilter(png);
        fc.setFileFilter(png);
        fc.setSelectedFile(SaveRules.suggestedTarget(shown.file(), partial).toFile());
        while (fc.showSaveDialog(parent) == JFileChooser.APPROVE_OPTION) {
            Path target = SaveRules.withPngExtension(fc.getSelectedFile().toPath()).toAbsolutePath();
            String refused = SaveRules.refusal(target, shown.file());
            if (refused == null && currentScene != null) {
                refused = SaveRules.refusal(target, currentScene);
            }
            if (refused != null) {
                JOptionPane.showMessageDialog(parent, "Not saved: " + refused + ".", "Cannot save here", JOptionPane.WARNING_MESSAGE);
                continue;
            }
            if (SaveRules.check(target, shown.file()) == SaveRules.Verdict.ASK_TO_REPLACE && !confirmReplace(parent, target)) {
                continue;
            }
            try {
                SaveRules.save(shown.imageToSave(), target, shown.file());
                return partial ? "Saved the partial image (stopped at " + StatusText.percent(shown.progress().fraction())
                        + ", unfinished tiles black) as " + target : "Saved " + target;
            } catch (SaveRules.SaveException e) {
                JOptionPane.showMessageDialog(parent, e.getMessage(), "Cannot save", JOptionPane.ERROR_MESSAGE);
                return e.getMessage();
            }
        }
        return null;
    }

    private static boolean confirmReplace(Component parent, Path target) {
        Object[] options = {"Replace", "Cancel"};
        int answer = JOptionPane.showOptionDialog(parent, target.getFileName() + " already exists in " + target.getParent()
                        + ".\nReplace it?", "Replace file?", JOptionPane.YES_NO_OPTION, JOptionPane.WARNING_MESSAGE, null,
                options, options[1]);
        return answer == 0;
    }
}
