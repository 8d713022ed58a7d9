package ray.viewer;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.UnsupportedFlavorException;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.TransferHandler;

/** Dropping a scene file onto the window opens it (the first file, if several are dropped). */
final class SceneDrop extends TransferHandler {
    private static final long serialVersionUID = 1L;

    private final transient Consumer<Path> open;
    private final transient Consumer<String> error;

    SceneDrop(Consumer<Path> open, Consumer<String> error) {
        this.open = open;
        this.error = error;
    }

    @Override
    public boolean canImport(TransferSupport s) {
        return s.isDataFlavorSupported(DataFlavor.javaFileListFlavor);
    }

    @Override
    public boolean importData(TransferSupport s) {
        if (!canImport(s)) {
            return false;
        }
        try {
            List<?> files = (List<?>) s.getTransferable().getTransferData(DataFlavor.javaFileListFlavor);
            if (files.isEmpty() || !(files.get(0) instanceof File f)) {
                return false;
            }
            open.accept(f.toPath());
            return true;
        } catch (UnsupportedFlavorException | IOException e) {
            error.accept("Cannot open the dropped file: " + ErrorTexts.reason(e));
            return false;
        }
    }
}
