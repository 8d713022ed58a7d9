package ray.viewer;

import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import javax.swing.JComponent;
import javax.swing.JScrollPane;
import javax.swing.Scrollable;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;
import ray.render.Image;

/**
 * The image, at the {@link Zoom}'s scale, inside a scroll pane: fitted to the view or at a fixed scale
 * (scroll bars when larger). At 1:1 every pixel on screen is the PNG's pixel (the same 8-bit values,
 * from {@link Image#toByte}); other scales use nearest-neighbour so no colour is invented.
 * Used on the event thread only.
 */
final class ImageView extends JComponent implements Scrollable {
    private static final long serialVersionUID = 1L;

    final Zoom zoom = new Zoom();
    private transient BufferedImage shown;

    ImageView() {
        setOpaque(true);
        setBackground(new Color(0x2b2b2b));
        // Ctrl+wheel zooms; the plain wheel still scrolls (handed on to the scroll pane)
        addMouseWheelListener(e -> {
            if (e.isControlDown() && shown != null) {
                if (e.getWheelRotation() < 0) {
                    zoomIn();
                } else if (e.getWheelRotation() > 0) {
                    zoomOut();
                }
            } else {
                Component pane = SwingUtilities.getAncestorOfClass(JScrollPane.class, this);
                if (pane != null) {
                    pane.dispatchEvent(SwingUtilities.convertMouseEvent(this, e, pane));
                }
            }
        });
    }

    /** True when there is an image (finished or in progress) to look at. */
    boolean hasImage() {
        return shown != null;
    }

    BufferedImage image() {
        return shown;
    }

    /** A black image of {@code w x h} that tiles are then copied into. */
    void reset(int w, int h) {
        shown = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        changed();
    }

    /** Shows a whole finished image. */
    void show(Image image) {
        shown = image == null ? null : image.toBufferedImage();
        changed();
    }

    void copyTile(Image image, int x0, int y0, int x1, int y1) {
        BufferedImage b = shown;
        if (b == null || b.getWidth() != image.width || b.getHeight() != image.height) {
            return;
        }
        int[] row = new int[x1 - x0];
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int i = 3 * (y * image.width + x);
                row[x - x0] = Image.toByte(image.rgb[i]) << 16 | Image.toByte(image.rgb[i + 1]) << 8 | Image.toByte(image.rgb[i + 2]);
            }
            b.setRGB(x0, y, x1 - x0, 1, row, 0, row.length);
        }
        double s = scale();
        Rectangle at = imageBounds();
        repaint(at.x + (int) Math.floor(x0 * s) - 1, at.y + (int) Math.floor(y0 * s) - 1,
                (int) Math.ceil((x1 - x0) * s) + 2, (int) Math.ceil((y1 - y0) * s) + 2);
    }

    /** The scale the image is drawn at now. */
    double scale() {
        if (shown == null) {
            return 1;
        }
        Dimension view = getParent() != null ? getParent().getSize() : getSize();
        return zoom.scale(shown.getWidth(), shown.getHeight(), view.width, view.height);
    }

    void zoomIn() {
        zoom.in(scale());
        changed();
    }

    void zoomOut() {
        zoom.out(scale());
        changed();
    }

    void actualSize() {
        zoom.actualSize();
        changed();
    }

    void fitToView() {
        zoom.fitToView();
        changed();
    }

    private void changed() {
        revalidate();
        repaint();
    }

    /** Where the image is drawn: centred when smaller than the component. */
    Rectangle imageBounds() {
        if (shown == null) {
            return new Rectangle();
        }
        double s = scale();
        int w = (int) Math.round(shown.getWidth() * s), h = (int) Math.round(shown.getHeight() * s);
        return new Rectangle(Math.max(0, (getWidth() - w) / 2), Math.max(0, (getHeight() - h) / 2), w, h);
    }

    @Override
    public Dimension getPreferredSize() {
        if (shown == null || zoom.fit()) {
            return new Dimension(320, 240);
        }
        Rectangle r = imageBounds();
        return new Dimension(r.width, r.height);
    }

    @Override
    protected void paintComponent(Graphics g) {
        g.setColor(getBackground());
        g.fillRect(0, 0, getWidth(), getHeight());
        if (shown == null) {
            return;
        }
        Rectangle r = imageBounds();
        Graphics2D g2 = (Graphics2D) g.create();
        g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g2.drawImage(shown, r.x, r.y, r.width, r.height, null);
        g2.dispose();
    }

    // Scrollable: fitted, the image follows the view's size; zoomed, it scrolls.
    @Override
    public Dimension getPreferredScrollableViewportSize() {
        return getPreferredSize();
    }

    @Override
    public int getScrollableUnitIncrement(Rectangle visible, int orientation, int direction) {
        return 16;
    }

    @Override
    public int getScrollableBlockIncrement(Rectangle visible, int orientation, int direction) {
        return orientation == SwingConstants.HORIZONTAL ? visible.width * 9 / 10 : visible.height * 9 / 10;
    }

    @Override
    public boolean getScrollableTracksViewportWidth() {
        return zoom.fit() || getParent() != null && getParent().getWidth() > getPreferredSize().width;
    }

    @Override
    public boolean getScrollableTracksViewportHeight() {
        return zoom.fit() || getParent() != null && getParent().getHeight() > getPreferredSize().height;
    }
}
