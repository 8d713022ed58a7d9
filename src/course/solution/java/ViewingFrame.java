import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.vecmath.Vector3d;

/**
 * The viewer: opens a scene file and shows your {@link Scene#renderPixel} results as they come in,
 * row by row. File &gt; Open (Ctrl+O), File &gt; Render again (F5), File &gt; Save PNG (Ctrl+S).
 * {@code java RayTracer} with no arguments opens it. Given: not one of the methods you write.
 */
public class ViewingFrame extends JFrame {
    private static final long serialVersionUID = 1L;

    private final ImagePanel panel = new ImagePanel();
    private final JLabel status = new JLabel("File > Open a scene (Ctrl+O)");
    private File sceneFile;
    private Thread worker;
    /** Increased for each render: a render whose number is no longer current stops. */
    private volatile int generation;

    public ViewingFrame() {
        super("RayTracer");
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        JMenuBar bar = new JMenuBar();
        JMenu menu = new JMenu("File");
        menu.add(item("Open...", KeyEvent.VK_O, () -> choose()));
        menu.add(item("Render again", KeyEvent.VK_F5, () -> openScene(sceneFile)));
        menu.add(item("Save PNG...", KeyEvent.VK_S, () -> save()));
        menu.add(item("Quit", KeyEvent.VK_Q, () -> dispose()));
        bar.add(menu);
        setJMenuBar(bar);
        add(new JScrollPane(panel), BorderLayout.CENTER);
        add(status, BorderLayout.SOUTH);
        setSize(660, 560);
    }

    /** Opens a viewer window, rendering {@code scene} if it is not null. */
    public static void open(File scene) {
        SwingUtilities.invokeLater(() -> {
            ViewingFrame f = new ViewingFrame();
            f.setVisible(true);
            if (scene != null) {
                f.openScene(scene);
            }
        });
    }

    private JMenuItem item(String text, int key, Runnable action) {
        JMenuItem i = new JMenuItem(text);
        i.setAccelerator(key == KeyEvent.VK_F5 ? KeyStroke.getKeyStroke(key, 0)
                : KeyStroke.getKeyStroke(key, java.awt.Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx()));
        i.addActionListener(e -> action.run());
        return i;
    }

    private void choose() {
        JFileChooser c = new JFileChooser(sceneFile != null ? sceneFile.getParentFile() : new File("scenes"));
        c.setFileFilter(new FileNameExtensionFilter("Scene files (*.txt)", "txt"));
        if (c.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            openScene(c.getSelectedFile());
        }
    }

    /** Reads {@code file} and renders it in the background, pixel by pixel, showing each row as it is done. */
    public void openScene(File file) {
        if (file == null) {
            return;
        }
        sceneFile = file;
        int mine = ++generation;
        setTitle("RayTracer - " + file.getName());
        status.setText("Reading " + file.getPath() + "...");
        worker = new Thread(() -> render(file, mine), "render");
        worker.setDaemon(true);
        worker.start();
    }

    private void render(File file, int mine) {
        Scene scene;
        try {
            scene = Parser.parse(file);
            RayTracer.prepare(scene);
        } catch (Parser.SceneFormatException e) {
            show(mine, e.getMessage());
            return;
        } catch (RayTracer.RenderException e) {
            show(mine, file.getPath() + ": " + e.getMessage());
            return;
        }
        BufferedImage image = new BufferedImage(scene.width, scene.height, BufferedImage.TYPE_INT_RGB);
        SwingUtilities.invokeLater(() -> panel.setImage(image));
        long start = System.nanoTime();
        for (int y = 0; y < scene.height; y++) {
            for (int x = 0; x < scene.width; x++) {
                if (mine != generation) {
                    return;
                }
                try {
                    Vector3d c = RayTracer.renderPixelChecked(scene, x, y);
                    image.setRGB(x, y, RayTracer.rgb(c));
                } catch (RayTracer.RenderException e) {
                    image.setRGB(x, y, 0xFF00FF);
                    panel.repaint();
                    show(mine, file.getPath() + ": " + e.getMessage());
                    return;
                }
            }
            int row = y + 1;
            if (mine == generation) {
                SwingUtilities.invokeLater(() -> {
                    panel.repaint();
                    status.setText(String.format("Rendering: row %d of %d", row, scene.height));
                });
            }
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        show(mine, String.format("%s: %d x %d pixels in %.1f s", file.getName(), scene.width, scene.height, seconds));
    }

    private void show(int mine, String text) {
        SwingUtilities.invokeLater(() -> {
            if (mine == generation) {
                status.setText(text);
            }
        });
    }

    private void save() {
        BufferedImage image = panel.image;
        if (image == null) {
            return;
        }
        JFileChooser c = new JFileChooser(sceneFile != null ? sceneFile.getParentFile() : null);
        if (c.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            try {
                javax.imageio.ImageIO.write(image, "png", c.getSelectedFile());
            } catch (IOException e) {
                JOptionPane.showMessageDialog(this, "Cannot save: " + e.getMessage());
            }
        }
    }

    /** Shows the image at 1:1, centred. */
    private static final class ImagePanel extends JComponent {
        private static final long serialVersionUID = 1L;
        BufferedImage image;

        void setImage(BufferedImage i) {
            image = i;
            setPreferredSize(new Dimension(i.getWidth(), i.getHeight()));
            revalidate();
            repaint();
        }

        @Override
        protected void paintComponent(Graphics g) {
            g.setColor(Color.DARK_GRAY);
            g.fillRect(0, 0, getWidth(), getHeight());
            if (image != null) {
                g.drawImage(image, Math.max(0, (getWidth() - image.getWidth()) / 2), Math.max(0, (getHeight() - image.getHeight()) / 2), null);
            }
        }
    }
}
