package ray.viewer;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;
import ray.Scene;
import ray.parse.Parser;
import ray.parse.SceneFormatException;
import ray.render.Image;
import ray.render.PngWriter;
import ray.render.ProgressListener;
import ray.render.RenderCancelledException;
import ray.render.Renderer;

/**
 * The viewer: open a scene file and watch it render tile by tile; save the result as a PNG.
 * {@code raytracer} with no arguments opens it.
 */
public final class ViewingFrame extends JFrame {
    private static final long serialVersionUID = 1L;

    private final ImagePanel panel = new ImagePanel();
    private final JLabel status = new JLabel("Open a scene file (File > Open, Ctrl+O).");
    private transient Renderer running;
    private transient Image last;
    private File lastDir = new File(".");

    public ViewingFrame() {
        super("RayTracer viewer");
        setDefaultCloseOperation(JFrame.EXIT_ON_CLOSE);
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.add(item("Open scene...", KeyEvent.VK_O, this::chooseScene));
        file.add(item("Save image as PNG...", KeyEvent.VK_S, this::saveImage));
        file.add(item("Quit", KeyEvent.VK_Q, this::dispose));
        bar.add(file);
        setJMenuBar(bar);
        add(panel, BorderLayout.CENTER);
        add(status, BorderLayout.SOUTH);
        panel.setPreferredSize(new Dimension(640, 480));
        pack();
    }

    /** Opens a viewer window (on the Swing thread), rendering {@code scene} if it is not null. */
    public static void open(Path scene) {
        SwingUtilities.invokeLater(() -> {
            ViewingFrame f = new ViewingFrame();
            f.setVisible(true);
            if (scene != null) {
                f.lastDir = scene.toAbsolutePath().getParent().toFile();
                f.load(scene);
            }
        });
    }

    private JMenuItem item(String text, int key, Runnable action) {
        JMenuItem i = new JMenuItem(text);
        i.setAccelerator(KeyStroke.getKeyStroke(key, java.awt.Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx()));
        i.addActionListener(e -> action.run());
        return i;
    }

    private void chooseScene() {
        JFileChooser fc = new JFileChooser(lastDir);
        fc.setFileFilter(new FileNameExtensionFilter("Scene files (*.txt)", "txt"));
        if (fc.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) {
            lastDir = fc.getSelectedFile().getParentFile();
            load(fc.getSelectedFile().toPath());
        }
    }

    /** Parses {@code file} and starts rendering it in the background; errors go to a dialog. */
    public void load(Path file) {
        List<String> warnings = new ArrayList<>();
        Scene scene;
        try {
            scene = Parser.parse(file, warnings);
        } catch (SceneFormatException e) {
            status.setText(e.getMessage());
            JOptionPane.showMessageDialog(this, e.getMessage(), "Cannot read scene", JOptionPane.ERROR_MESSAGE);
            return;
        }
        if (running != null) {
            running.cancel();
        }
        setTitle("RayTracer viewer - " + file.getFileName());
        panel.reset(scene.width, scene.height);
        pack();
        Renderer r = new Renderer(scene).listener(new ProgressListener() {
            @Override
            public void tileDone(Image image, int x0, int y0, int x1, int y1, int done, int total) {
                panel.copyTile(image, x0, y0, x1, y1);
                SwingUtilities.invokeLater(() -> status.setText(String.format("%s: %d%%", file.getFileName(), 100 * done / total)));
            }
        });
        running = r;
        long start = System.nanoTime();
        Thread t = new Thread(() -> {
            try {
                Image img = r.render();
                double s = (System.nanoTime() - start) / 1e9;
                SwingUtilities.invokeLater(() -> {
                    last = img;
                    status.setText(String.format("%s: done in %.2f s, %s%s", file.getFileName(), s, r.stats(),
                            warnings.isEmpty() ? "" : "; " + String.join("; ", warnings)));
                });
            } catch (RenderCancelledException e) {
                // a newer scene replaced this one
            } catch (RuntimeException | OutOfMemoryError e) {
                SwingUtilities.invokeLater(() -> status.setText(file.getFileName() + ": render failed: " + e));
            }
        }, "viewer-render");
        t.setDaemon(true);
        t.start();
    }

    private void saveImage() {
        if (last == null) {
            JOptionPane.showMessageDialog(this, "Nothing rendered yet.");
            return;
        }
        JFileChooser fc = new JFileChooser(lastDir);
        if (fc.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            try {
                PngWriter.write(last, fc.getSelectedFile().toPath());
            } catch (java.io.IOException e) {
                JOptionPane.showMessageDialog(this, e.getMessage(), "Cannot save", JOptionPane.ERROR_MESSAGE);
            }
        }
    }

    /** Shows the image as it is being rendered; tiles are copied in from the render threads. */
    static final class ImagePanel extends JComponent {
        private static final long serialVersionUID = 1L;
        private transient BufferedImage shown = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);

        void reset(int w, int h) {
            shown = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
            setPreferredSize(new Dimension(w, h));
            revalidate();
            repaint();
        }

        void copyTile(Image image, int x0, int y0, int x1, int y1) {
            BufferedImage b = shown;
            if (b.getWidth() != image.width || b.getHeight() != image.height) {
                return;
            }
            for (int y = y0; y < y1; y++) {
                for (int x = x0; x < x1; x++) {
                    int i = 3 * (y * image.width + x);
                    b.setRGB(x, y, Image.toByte(image.rgb[i]) << 16 | Image.toByte(image.rgb[i + 1]) << 8
                            | Image.toByte(image.rgb[i + 2]));
                }
            }
            repaint(x0, y0, x1 - x0, y1 - y0);
        }

        @Override
        protected void paintComponent(Graphics g) {
            g.drawImage(shown, 0, 0, null);
        }
    }
}
