package ray.viewer;

import java.awt.Color;
import java.awt.Component;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.image.BufferedImage;
import java.util.Locale;
import java.util.function.BiConsumer;
import javax.swing.JComponent;
import javax.swing.JScrollPane;
import javax.swing.JViewport;
import javax.swing.Scrollable;
import javax.swing.SwingConstants;
import javax.swing.SwingUtilities;
import ray.render.Image;

/**
 * The image, at the {@link Zoom}'s scale, inside a scroll pane: fitted to the view (kept fitted as the
 * window is resized) or at a fixed scale (scroll bars when larger), zoomed about the cursor. At 1:1 and
 * exposure 0 every pixel on screen is the PNG's pixel (the same 8-bit values, from {@link Image#toByte});
 * other scales use nearest-neighbour so no colour is invented.
 *
 * <p>Three things can be shown: the render (A), a reference image (B) and their difference as a heat map
 * with its scale ({@link Compare}). The exposure scales the linear values of A and B by 2^EV before they
 * become 8-bit. The pixel under the cursor is reported (position, the render's linear value and its
 * 8-bit value, the reference's and the difference) through {@link #onInfo}. Used on the event thread only.
 */
final class ImageView extends JComponent implements Scrollable {
    private static final long serialVersionUID = 1L;

    /** What is drawn. */
    enum Mode { RENDER, REFERENCE, DIFFERENCE }

    final Zoom zoom = new Zoom();
    /** The render's linear values: the image being filled (finished tiles only) or the finished one. */
    private transient Image linear;
    /** The render as shown (exposure applied). */
    private transient BufferedImage shown;
    /** The render at exposure 0 (the PNG's bytes), what the reference is compared with. */
    private transient BufferedImage bytes;
    private transient BufferedImage reference;
    private String referenceName;
    private transient BufferedImage referenceShown;
    private transient Compare compare;
    private transient BufferedImage heat;
    private boolean compareStale = true;
    /** The render is finished (not one in progress). */
    private boolean complete;
    private Mode mode = Mode.RENDER;
    private double exposure;
    private transient Point pointer;
    private transient BiConsumer<String, String> info = (p, v) -> { };

    ImageView() {
        setOpaque(true);
        setBackground(new Color(0x2b2b2b));
        // Ctrl+wheel zooms about the cursor; the plain wheel still scrolls (handed on to the scroll pane)
        addMouseWheelListener(e -> {
            if (e.isControlDown() && shown != null) {
                if (e.getWheelRotation() < 0) {
                    zoomIn(e.getPoint());
                } else if (e.getWheelRotation() > 0) {
                    zoomOut(e.getPoint());
                }
            } else {
                Component pane = SwingUtilities.getAncestorOfClass(JScrollPane.class, this);
                if (pane != null) {
                    pane.dispatchEvent(SwingUtilities.convertMouseEvent(this, e, pane));
                }
            }
        });
        MouseAdapter hover = new MouseAdapter() {
            @Override
            public void mouseMoved(MouseEvent e) {
                pointer = e.getPoint();
                report();
            }

            @Override
            public void mouseDragged(MouseEvent e) {
                mouseMoved(e);
            }

            @Override
            public void mouseExited(MouseEvent e) {
                pointer = null;
                report();
            }
        };
        addMouseListener(hover);
        addMouseMotionListener(hover);
    }

    /**
     * Where the view's report goes: the pixel under the cursor (else the comparison with the reference,
     * else ""), and the zoom, what is shown and the exposure.
     */
    void onInfo(BiConsumer<String, String> c) {
        info = c;
        report();
    }

    /** True when there is an image (finished or in progress) to look at. */
    boolean hasImage() {
        return shown != null;
    }

    /** The render as drawn (exposure applied). */
    BufferedImage image() {
        return shown;
    }

    Mode mode() {
        return mode;
    }

    double exposure() {
        return exposure;
    }

    boolean hasReference() {
        return reference != null;
    }

    /** A black image the size of {@code filling}, whose finished tiles {@link #copyTile} then shows. */
    void reset(Image filling) {
        linear = filling;
        complete = false;
        bytes = new BufferedImage(filling.width, filling.height, BufferedImage.TYPE_INT_RGB);
        // at exposure 0 what is shown is the PNG's bytes: one image, written once per tile
        shown = exposure == 0 ? bytes : new BufferedImage(filling.width, filling.height, BufferedImage.TYPE_INT_RGB);
        compareStale = true;
        changed();
    }

    /** Shows a whole finished image (null: nothing). */
    void show(Image image) {
        linear = image;
        complete = image != null;
        if (image == null) {
            shown = bytes = null;
        } else {
            bytes = image.toBufferedImage();
            shown = exposure == 0 ? bytes : exposed(image);
        }
        compareStale = true;
        changed();
    }

    void copyTile(Image image, int x0, int y0, int x1, int y1) {
        BufferedImage b = shown;
        if (b == null || linear != image || b.getWidth() != image.width || b.getHeight() != image.height) {
            return;
        }
        double gain = Math.pow(2, exposure);
        boolean exposed = bytes != b;
        int[] row = exposed ? new int[x1 - x0] : null, raw = new int[x1 - x0];
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int i = 3 * (y * image.width + x);
                raw[x - x0] = rgb(image.rgb, i, 1);
                if (exposed) {
                    row[x - x0] = rgb(image.rgb, i, gain);
                }
            }
            bytes.setRGB(x0, y, x1 - x0, 1, raw, 0, raw.length);
            if (exposed) {
                b.setRGB(x0, y, x1 - x0, 1, row, 0, row.length);
            }
        }
        compareStale = true;
        if (mode != Mode.RENDER) {
            repaint();
            return;
        }
        double s = scale();
        Rectangle at = imageBounds();
        repaint(at.x + (int) Math.floor(x0 * s) - 1, at.y + (int) Math.floor(y0 * s) - 1,
                (int) Math.ceil((x1 - x0) * s) + 2, (int) Math.ceil((y1 - y0) * s) + 2);
    }

    private static int rgb(double[] rgb, int i, double gain) {
        return Image.toByte(gain * rgb[i]) << 16 | Image.toByte(gain * rgb[i + 1]) << 8 | Image.toByte(gain * rgb[i + 2]);
    }

    private BufferedImage exposed(Image image) {
        double gain = Math.pow(2, exposure);
        BufferedImage img = new BufferedImage(image.width, image.height, BufferedImage.TYPE_INT_RGB);
        int[] row = new int[image.width];
        for (int y = 0; y < image.height; y++) {
            for (int x = 0; x < image.width; x++) {
                row[x] = rgb(image.rgb, 3 * (y * image.width + x), gain);
            }
            img.setRGB(0, y, image.width, 1, row, 0, image.width);
        }
        return img;
    }

    /** Sets (or with null removes) the reference image; {@code name} names it in the report. */
    void reference(BufferedImage ref, String name) {
        reference = ref == null ? null : toRgb(ref);
        referenceName = name;
        referenceShown = null;
        compareStale = true;
        if (ref == null && mode != Mode.RENDER) {
            mode = Mode.RENDER;
        }
        changed();
    }

    private static BufferedImage toRgb(BufferedImage in) {
        BufferedImage out = new BufferedImage(in.getWidth(), in.getHeight(), BufferedImage.TYPE_INT_RGB);
        out.setRGB(0, 0, in.getWidth(), in.getHeight(), in.getRGB(0, 0, in.getWidth(), in.getHeight(), null, 0, in.getWidth()),
                0, in.getWidth());
        return out;
    }

    /** Shows the render, the reference or the difference (the last two only with a reference). */
    void mode(Mode m) {
        mode = reference == null ? Mode.RENDER : m;
        changed();
    }

    /** The A/B toggle: the render and the reference in turn (from the difference, the render). */
    void toggle() {
        mode(mode == Mode.RENDER ? Mode.REFERENCE : Mode.RENDER);
    }

    /** Sets the exposure in stops (EV, a multiple of 1/2 from -16 to +16); 0 shows the PNG's pixels. */
    void exposure(double ev) {
        exposure = Math.max(-16, Math.min(16, Math.round(ev * 2) / 2.0));
        referenceShown = null;
        if (linear != null && bytes != null) {
            shown = exposure == 0 ? bytes : exposed(linear);     // pixels not rendered yet are 0: black
        }
        changed();
    }

    /** The comparison of the render (at exposure 0) with the reference, or null (none, or not the same size). */
    Compare compare() {
        if (reference == null || bytes == null || Compare.sizeMismatch(bytes, reference) != null) {
            return null;
        }
        if (compareStale || compare == null) {
            compare = Compare.of(bytes, reference);
            heat = compare.heatMap();
            compareStale = false;
        }
        return compare;
    }

    /** One line on the reference: its name and the comparison's summary, or why there is none. */
    String referenceSummary() {
        if (reference == null) {
            return null;
        }
        String why = bytes == null ? null : Compare.sizeMismatch(bytes, reference);
        Compare c = why == null ? compare() : null;
        return referenceName + ": " + (why != null ? why : c == null ? "no render yet"
                : complete ? c.summary() : "compared once the render is done");
    }

    /** The image drawn now: the render, the reference (exposure applied) or the heat map. */
    private BufferedImage drawn() {
        if (mode == Mode.REFERENCE && reference != null) {
            if (referenceShown == null) {
                referenceShown = exposure == 0 ? reference : exposedReference();
            }
            return referenceShown;
        }
        if (mode == Mode.DIFFERENCE && compare() != null) {
            return heat;
        }
        return shown;
    }

    private BufferedImage exposedReference() {
        int w = reference.getWidth(), h = reference.getHeight();
        double gain = Math.pow(2, exposure);
        int[] p = reference.getRGB(0, 0, w, h, null, 0, w);
        for (int i = 0; i < p.length; i++) {
            int v = p[i];
            p[i] = Image.toByte(gain * (v >> 16 & 255) / 255.0) << 16 | Image.toByte(gain * (v >> 8 & 255) / 255.0) << 8
                    | Image.toByte(gain * (v & 255) / 255.0);
        }
        BufferedImage out = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        out.setRGB(0, 0, w, h, p, 0, w);
        return out;
    }

    /** The scale the image is drawn at now. */
    double scale() {
        if (shown == null) {
            return 1;
        }
        Dimension view = getParent() != null ? getParent().getSize() : getSize();
        return zoom.scale(shown.getWidth(), shown.getHeight(), view.width, view.height);
    }

    /** One step larger, keeping the image point under {@code at} (this component's coordinates) there; null: the view's centre. */
    void zoomIn(Point at) {
        zoomAbout(at, true);
    }

    void zoomOut(Point at) {
        zoomAbout(at, false);
    }

    void zoomIn() {
        zoomIn(null);
    }

    void zoomOut() {
        zoomOut(null);
    }

    private void zoomAbout(Point at, boolean in) {
        if (shown == null) {
            return;
        }
        JViewport vp = getParent() instanceof JViewport v ? v : null;
        Point anchor = at != null ? at : vp == null ? new Point(getWidth() / 2, getHeight() / 2) : centreOf(vp.getViewRect());
        Point inViewport = vp == null ? anchor : new Point(anchor.x - vp.getViewPosition().x, anchor.y - vp.getViewPosition().y);
        Rectangle before = imageBounds();
        double s0 = scale();
        double ix = Math.max(0, Math.min(shown.getWidth(), (anchor.x - before.x) / s0));
        double iy = Math.max(0, Math.min(shown.getHeight(), (anchor.y - before.y) / s0));
        if (in) {
            zoom.in(s0);
        } else {
            zoom.out(s0);
        }
        if (vp != null) {
            // the new size now, to place the view: the pane's layout too, since scroll bars that appear or go
            // change the viewport's extent (twice: a bar can bring the other one)
            JScrollPane sp = (JScrollPane) SwingUtilities.getAncestorOfClass(JScrollPane.class, this);
            for (int i = 0; i < 2; i++) {
                if (sp != null) {
                    sp.doLayout();
                }
                vp.doLayout();
            }
            Rectangle after = imageBounds();
            double s1 = scale();
            Dimension size = getSize(), extent = vp.getExtentSize();
            int x = (int) Math.round(after.x + ix * s1) - inViewport.x, y = (int) Math.round(after.y + iy * s1) - inViewport.y;
            vp.setViewPosition(new Point(Math.max(0, Math.min(size.width - extent.width, x)),
                    Math.max(0, Math.min(size.height - extent.height, y))));
        }
        changed();
    }

    private static Point centreOf(Rectangle r) {
        return new Point(r.x + r.width / 2, r.y + r.height / 2);
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
        report();
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

    /** The image pixel under {@code p} (this component's coordinates), or null when outside the image. */
    Point pixelAt(Point p) {
        if (shown == null || p == null) {
            return null;
        }
        Rectangle r = imageBounds();
        double s = scale();
        int x = (int) Math.floor((p.x - r.x) / s), y = (int) Math.floor((p.y - r.y) / s);
        return x < 0 || y < 0 || x >= shown.getWidth() || y >= shown.getHeight() ? null : new Point(x, y);
    }

    /** {@code 63% (fit) · render · EV +1.5}: the zoom, what is shown, the exposure unless 0. */
    String viewText() {
        if (shown == null) {
            return "";
        }
        String pct = String.format(Locale.ROOT, "%.0f%%", 100 * scale()) + (zoom.fit() ? " (fit)" : "");
        String what = reference == null ? "" : switch (mode) {
            case RENDER -> " · A: render";
            case REFERENCE -> " · B: reference";
            case DIFFERENCE -> " · difference";
        };
        String ev = exposure == 0 ? "" : String.format(Locale.ROOT, " · EV %+.1f", exposure);
        return pct + what + ev;
    }

    /**
     * The pixel at image position {@code (x, y)}: {@code x 12 y 34 · linear 0.512 0.200 0.100 · 8-bit 131 51 26},
     * then the reference's 8-bit value and the difference in steps when there is a reference.
     */
    String pixelText(int x, int y) {
        StringBuilder b = new StringBuilder().append("x ").append(x).append(" y ").append(y);
        if (linear != null) {
            int i = 3 * (y * linear.width + x);
            b.append(String.format(Locale.ROOT, " · linear %.3f %.3f %.3f", linear.rgb[i], linear.rgb[i + 1], linear.rgb[i + 2]));
        }
        if (bytes != null) {
            b.append(" · 8-bit ").append(channels(bytes.getRGB(x, y)));
        }
        if (reference != null && x < reference.getWidth() && y < reference.getHeight()) {
            b.append(" · reference ").append(channels(reference.getRGB(x, y)));
            Compare c = compare();
            if (c != null) {
                b.append(" · off ").append(c.steps(x, y)).append(c.steps(x, y) == 1 ? " step" : " steps");
            }
        }
        return b.toString();
    }

    private static String channels(int v) {
        return (v >> 16 & 255) + " " + (v >> 8 & 255) + " " + (v & 255);
    }

    private void report() {
        Point px = pixelAt(pointer);
        String ref = referenceSummary();
        info.accept(px != null ? pixelText(px.x, px.y) : ref == null ? "" : "Reference " + ref, viewText());
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
        BufferedImage img = drawn();
        if (img == null) {
            return;
        }
        Rectangle r = imageBounds();
        Graphics2D g2 = (Graphics2D) g.create();
        g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR);
        g2.drawImage(img, r.x, r.y, r.width, r.height, null);
        if (img == heat) {
            legend(g2, getVisibleRect());
        }
        g2.dispose();
    }

    /** The heat map's scale, bottom left of the visible part: the ramp from 0 to its top in 8-bit steps, and the count. */
    private void legend(Graphics2D g, Rectangle visible) {
        Compare c = compare();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setFont(getFont() != null ? getFont().deriveFont(Font.PLAIN, 12f) : new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        FontMetrics fm = g.getFontMetrics();
        String text = c.summary();
        int barW = 160, barH = 10, pad = 6, lineH = fm.getHeight();
        int w = Math.max(barW + 2 * pad, fm.stringWidth(text) + 2 * pad), h = barH + 2 * lineH + 3 * pad;
        int x = visible.x + 8, y = visible.y + visible.height - h - 8;
        g.setColor(new Color(0, 0, 0, 190));
        g.fillRect(x, y, w, h);
        for (int i = 0; i < barW; i++) {
            g.setColor(new Color(Compare.colour(i / (barW - 1.0))));
            g.fillRect(x + pad + i, y + pad, 1, barH);
        }
        g.setColor(Color.WHITE);
        int ty = y + pad + barH + fm.getAscent() + 2;
        g.drawString("0", x + pad, ty);
        String top = c.scaleTop() + " steps (8-bit)";
        g.drawString(top, x + pad + barW - fm.stringWidth(top), ty);
        g.drawString(text, x + pad, ty + lineH + pad / 2);
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
