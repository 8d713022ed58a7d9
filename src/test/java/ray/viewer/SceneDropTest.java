package ray.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.StringSelection;
import java.awt.datatransfer.Transferable;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JPanel;
import javax.swing.TransferHandler.TransferSupport;
import org.junit.jupiter.api.Test;

/** Drag and drop, headless: a dropped file list opens its first file; text is not taken. */
class SceneDropTest {

    private final List<Path> opened = new ArrayList<>();
    private final List<String> errors = new ArrayList<>();
    private final SceneDrop drop = new SceneDrop(opened::add, errors::add);

    private static Transferable files(File... f) {
        return new Transferable() {
            @Override
            public DataFlavor[] getTransferDataFlavors() {
                return new DataFlavor[] {DataFlavor.javaFileListFlavor};
            }

            @Override
            public boolean isDataFlavorSupported(DataFlavor flavor) {
                return DataFlavor.javaFileListFlavor.equals(flavor);
            }

            @Override
            public Object getTransferData(DataFlavor flavor) {
                return List.of(f);
            }
        };
    }

    @Test
    void droppedFilesOpenTheFirst() {
        TransferSupport s = new TransferSupport(new JPanel(), files(new File("/s/a.txt"), new File("/s/b.txt")));
        assertTrue(drop.canImport(s));
        assertTrue(drop.importData(s));
        assertEquals(List.of(Path.of("/s/a.txt")), opened);
        assertTrue(errors.isEmpty());
    }

    @Test
    void textIsNotAScene() {
        TransferSupport s = new TransferSupport(new JPanel(), new StringSelection("/s/a.txt"));
        assertFalse(drop.canImport(s));
        assertFalse(drop.importData(s));
        assertFalse(drop.importData(new TransferSupport(new JPanel(), files())), "an empty list opens nothing");
        assertTrue(opened.isEmpty());
    }
}
