package ray.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Point;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.List;
import java.util.UUID;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import javax.imageio.ImageIO;
import javax.swing.JScrollPane;
import javax.swing.JViewport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import ray.render.Image;

/**
 * The viewer's image view as real Swing components laid out without a screen (a scroll pane sized by
 * hand): zoom about the cursor, fit kept on resize, the pixel under the cursor, exposure, the comparison
 * with a reference; and the small parts behind Watch, Open recent and a partial Save.
 */
class ImageViewTest {

    /** A w x h gradient with a distinct value per pixel. */
    static Image gradient(int w, int h) {
        Image img = new Image(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int i = 3 * (y * w + x);
                img.rgb[i] = x / (double) w;
                img.rgb[i + 1] = y / (double) h;
                img.rgb[i + 2] = 0.25;
            }
        }
        return img;
    }

    /** Swing components are used on the event thread (a layout queued by revalidate() would race the test otherwise). */
    static void onEventThread(Runnable r) throws Exception {
        Throwable[] failure = {null};
        javax.swing.SwingUtilities.invokeAndWait(() -> {
            try {
                r.run();
            } catch (Throwable t) {
                failure[0] = t;
            }
        });
        if (failure[0] instanceof Error e) {
            throw e;
        }
        if (failure[0] instanceof Exception e) {
            throw e;
        }
    }

    /** The view in a scroll pane of {@code w x h}, laid out. */
    static JScrollPane pane(ImageView v, int w, int h) {
        JScrollPane sp = new JScrollPane(v);
        sp.setBorder(null);
        resize(sp, w, h);
        return sp;
    }

    static void resize(JScrollPane sp, int w, int h) {
        sp.setSize(w, h);
        sp.doLayout();
        sp.getViewport().doLayout();
        sp.doLayout();
        sp.getViewport().doLayout();
    }

    /** Where image pixel (x, y)'s centre is, in the viewport's visible coordinates. */
    private static Point onScreen(ImageView v, double x, double y) {
        Rectangle r = v.imageBounds();
        Point pos = ((JViewport) v.getParent()).getViewPosition();
        return new Point((int) Math.round(r.x + x * v.scale()) - pos.x, (int) Math.round(r.y + y * v.scale()) - pos.y);
    }

    @Test
    void zoomKeepsThePixelUnderTheCursorInPlace() throws Exception {
        onEventThread(this::zoomKeepsThePixelUnderTheCursorInPlaceBody);
    }

    private void zoomKeepsThePixelUnderTheCursorInPlaceBody() {
        ImageView v = new ImageView();
        v.show(gradient(400, 300));
        JScrollPane sp = pane(v, 400, 300);
        assertEquals(1.0, v.scale());
        Point cursor = new Point(300, 220);                        // the image point under it: (300, 220)
        Point before = v.pixelAt(cursor);
        for (int i = 0; i < 3; i++) {
            Point inView = new Point(cursor.x + ((JViewport) v.getParent()).getViewPosition().x,
                    cursor.y + ((JViewport) v.getParent()).getViewPosition().y);
            v.zoomIn(inView);
            sp.getViewport().doLayout();
        }
        assertEquals(Math.pow(2, 1.5), v.scale(), 1e-9, "three steps in");
        Point pos = sp.getViewport().getViewPosition();
        assertTrue(pos.x > 0 && pos.y > 0, "scrolled towards the cursor, not the top-left corner: " + pos);
        Point after = v.pixelAt(new Point(cursor.x + pos.x, cursor.y + pos.y));
        assertNotNull(after);
        assertTrue(Math.abs(after.x - before.x) <= 1 && Math.abs(after.y - before.y) <= 1,
                "the pixel under the cursor moved from " + before + " to " + after);
        // out again about the same place: back to 1:1 with no scrolling
        for (int i = 0; i < 3; i++) {
            v.zoomOut(new Point(cursor.x + sp.getViewport().getViewPosition().x, cursor.y + sp.getViewport().getViewPosition().y));
            sp.getViewport().doLayout();
        }
        assertEquals(1.0, v.scale());
        assertTrue(v.viewText().startsWith("100%"), v.viewText());
    }

    @Test
    void keyboardZoomKeepsTheViewsCentre() throws Exception {
        onEventThread(this::keyboardZoomKeepsTheViewsCentreBody);
    }

    private void keyboardZoomKeepsTheViewsCentreBody() {
        ImageView v = new ImageView();
        v.show(gradient(400, 300));
        JScrollPane sp = pane(v, 400, 300);
        v.zoomIn();                                          // scroll bars appear: the view's extent shrinks
        sp.getViewport().doLayout();
        java.awt.Dimension extent = sp.getViewport().getExtentSize();
        Point pos = sp.getViewport().getViewPosition();
        Point before = v.pixelAt(new Point(pos.x + extent.width / 2, pos.y + extent.height / 2));
        v.zoomIn();
        sp.getViewport().doLayout();
        pos = sp.getViewport().getViewPosition();
        Point after = v.pixelAt(new Point(pos.x + extent.width / 2, pos.y + extent.height / 2));
        assertTrue(Math.abs(after.x - before.x) <= 1 && Math.abs(after.y - before.y) <= 1,
                "the pixel at the view's centre moved from " + before + " to " + after);
        assertEquals("200%", v.viewText());
    }

    @Test
    void fitIsKeptWhenTheWindowIsResized() throws Exception {
        onEventThread(this::fitIsKeptWhenTheWindowIsResizedBody);
    }

    private void fitIsKeptWhenTheWindowIsResizedBody() {
        ImageView v = new ImageView();
        v.show(gradient(800, 600));
        JScrollPane sp = pane(v, 400, 300);
        assertEquals(0.5, v.scale(), 1e-12);
        assertEquals("50% (fit)", v.viewText());
        resize(sp, 200, 150);
        assertEquals(0.25, v.scale(), 1e-12, "fit follows a smaller window");
        v.fitToView();
        resize(sp, 1600, 1200);
        assertEquals(2.0, v.scale(), 1e-12, "after Zoom to fit, fit follows a larger window");
        assertEquals(new Rectangle(0, 0, 1600, 1200), v.imageBounds());
        assertFalse(sp.getHorizontalScrollBar().isVisible() && sp.getHorizontalScrollBar().getMaximum() > 1600);
    }

    @Test
    void thePixelUnderTheCursorReportsPositionLinearAndEightBitValues() throws Exception {
        onEventThread(this::thePixelUnderTheCursorReportsPositionLinearAndEightBitValuesBody);
    }

    private void thePixelUnderTheCursorReportsPositionLinearAndEightBitValuesBody() {
        ImageView v = new ImageView();
        Image img = gradient(40, 30);
        img.rgb[3 * (7 * 40 + 12)] = 0.5;
        v.show(img);
        pane(v, 400, 300);                                   // a small image is shown 1:1, centred
        Rectangle r = v.imageBounds();
        assertEquals(new Rectangle(180, 135, 40, 30), r);
        assertNull(v.pixelAt(new Point(179, 140)), "left of the image");
        assertEquals(new Point(12, 7), v.pixelAt(new Point(192, 142)));
        assertEquals("x 12 y 7 · linear 0.500 0.233 0.250 · 8-bit 128 60 64", v.pixelText(12, 7));
        String[] seen = {null};
        v.onInfo((pixel, view) -> seen[0] = pixel + "  |  " + view);
        v.dispatchEvent(new java.awt.event.MouseEvent(v, java.awt.event.MouseEvent.MOUSE_MOVED, 0, 0, 192, 142, 0, false));
        assertEquals("x 12 y 7 · linear 0.500 0.233 0.250 · 8-bit 128 60 64  |  100% (fit)", seen[0]);
    }

    @Test
    void exposureScalesLinearValuesAndZeroIsThePngsPixels() {
        ImageView v = new ImageView();
        Image img = gradient(40, 30);
        img.rgb[0] = 0.1;
        img.rgb[1] = 0.3;
        img.rgb[2] = 0.6;
        v.show(img);
        assertEquals(Image.toByte(0.1) << 16 | Image.toByte(0.3) << 8 | Image.toByte(0.6), v.image().getRGB(0, 0) & 0xffffff);
        v.exposure(1);
        assertEquals(Image.toByte(0.2) << 16 | Image.toByte(0.6) << 8 | 255, v.image().getRGB(0, 0) & 0xffffff,
                "one stop brighter doubles the linear value before it becomes 8-bit (and clamps)");
        assertTrue(v.viewText().endsWith("EV +1.0"), v.viewText());
        v.exposure(-2.3);
        assertEquals(-2.5, v.exposure(), "half stops");
        v.exposure(0);
        BufferedImage png = img.toBufferedImage();
        for (int y = 0; y < 30; y++) {
            for (int x = 0; x < 40; x++) {
                assertEquals(png.getRGB(x, y), v.image().getRGB(x, y), "exposure 0 shows the PNG's pixels exactly");
            }
        }
    }

    @Test
    void exposureDuringARenderKeepsUnfinishedTilesBlack() {
        ImageView v = new ImageView();
        Image filling = new Image(40, 30);
        v.reset(filling);
        Image full = gradient(40, 30);
        for (int y = 0; y < 10; y++) {
            System.arraycopy(full.rgb, 3 * y * 40, filling.rgb, 3 * y * 40, 3 * 40);
        }
        v.copyTile(filling, 0, 0, 40, 10);
        v.exposure(2);
        assertEquals(0, v.image().getRGB(5, 20) & 0xffffff, "not rendered yet: black at any exposure");
        assertTrue((v.image().getRGB(30, 5) & 0xffffff) != 0);
        for (int y = 10; y < 20; y++) {
            System.arraycopy(full.rgb, 3 * y * 40, filling.rgb, 3 * y * 40, 3 * 40);
        }
        v.copyTile(filling, 0, 10, 40, 20);
        assertEquals(Image.toByte(4 * full.rgb[3 * (15 * 40 + 5)]), v.image().getRGB(5, 15) >> 16 & 255, "a new tile at the exposure set");
    }

    @Test
    void compareCountsPixelsOffByMoreThanOneStepAndPaintsAScale() {
        Image render = gradient(40, 30);
        BufferedImage ref = render.toBufferedImage();
        ref.setRGB(1, 1, ref.getRGB(1, 1) ^ 0x000001);            // off by one step: rounding, not counted
        int was = ref.getRGB(2, 2) >> 16 & 255, red = 255 - was;        // far off in red
        ref.setRGB(2, 2, ref.getRGB(2, 2) & 0xff00ffff | red << 16);
        int g = ref.getRGB(3, 3) >> 8 & 255;
        ref.setRGB(3, 3, ref.getRGB(3, 3) & 0xffff00ff | (g >= 3 ? g - 3 : g + 3) << 8);     // 3 steps in green
        ImageView v = new ImageView();
        v.show(render);
        v.reference(ref, "ref.png");
        Compare c = v.compare();
        assertNotNull(c);
        assertEquals(2, c.overOneStep());
        assertEquals(Math.abs(red - was), c.max());
        assertEquals(1, c.steps(1, 1));
        assertEquals(0, c.steps(0, 0));
        assertEquals(String.format(java.util.Locale.ROOT, "2 of 1,200 pixels (0.2%%) off by more than 1 step; largest %d steps", c.max()),
                c.summary());
        BufferedImage heat = c.heatMap();
        assertEquals(0, heat.getRGB(0, 0) & 0xffffff, "equal: black");
        assertEquals(Compare.colour(1), heat.getRGB(2, 2) & 0xffffff, "the largest difference: the scale's top");
        assertTrue((Compare.colour(1) & 0xff) > 0xb0 && (Compare.colour(1) >> 16) > 0xf0, "the top is near white");
        // A/B and the difference; without a reference only the render
        v.mode(ImageView.Mode.DIFFERENCE);
        assertEquals(ImageView.Mode.DIFFERENCE, v.mode());
        v.toggle();
        assertEquals(ImageView.Mode.RENDER, v.mode());
        v.toggle();
        assertEquals(ImageView.Mode.REFERENCE, v.mode());
        assertTrue(v.pixelText(3, 3).endsWith(" · off 3 steps"), v.pixelText(3, 3));
        v.reference(null, null);
        v.mode(ImageView.Mode.REFERENCE);
        assertEquals(ImageView.Mode.RENDER, v.mode());
        // an identical reference, and one of another size
        v.reference(render.toBufferedImage(), "same.png");
        assertEquals("same.png: identical to the reference", v.referenceSummary());
        v.reference(new BufferedImage(20, 10, BufferedImage.TYPE_INT_RGB), "small.png");
        assertEquals("small.png: the reference is 20x10, the render 40x30: not compared", v.referenceSummary());
        assertNull(v.compare());
    }

    @Test
    void aScenesOwnReferenceImageIsFound(@TempDir Path dir) throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Path refs = Files.createDirectories(dir.resolve("reference-images"));
        Path scene = Files.writeString(scenes.resolve("ball.txt"), "");
        assertNull(Compare.referenceFor(scene));
        ImageIO.write(new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB), "png", refs.resolve("ball.png").toFile());
        assertEquals(refs.resolve("ball.png"), Compare.referenceFor(scene), "scenes/x.txt -> reference-images/x.png");
        Path beside = Files.createDirectories(scenes.resolve("reference-images"));
        ImageIO.write(new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB), "png", beside.resolve("ball.png").toFile());
        assertEquals(beside.resolve("ball.png"), Compare.referenceFor(scene), "one beside the scene comes first");
    }

    @Test
    void watchingNothingIsAllowedAndASameSizeEditInTheSameTickIsSeen(@TempDir Path dir) throws IOException {
        FileWatch w = new FileWatch();
        w.watch(null);                                             // Watch turned on with no scene: was a NullPointerException
        assertFalse(w.changed());
        assertNull(w.file());
        Path f = Files.writeString(dir.resolve("s.txt"), "BGColor [0.1 0.2 0.3]");
        FileTime t = Files.getLastModifiedTime(f);
        w.watch(f);
        Files.writeString(f, "BGColor [0.1 0.6 0.3]");           // same size ...
        Files.setLastModifiedTime(f, t);                          // ... and the same time stamp (a coarse clock)
        assertTrue(w.changed(), "an edit that keeps size and time is still seen");
        assertFalse(w.changed());
    }

    @Test
    void openRecentDropsFilesThatNoLongerExist(@TempDir Path dir) throws IOException, BackingStoreException {
        Preferences node = Preferences.userRoot().node("raytracer-test/" + UUID.randomUUID());
        try {
            RecentFiles r = new RecentFiles(node);
            Path a = Files.writeString(dir.resolve("a.txt"), ""), b = Files.writeString(dir.resolve("b.txt"), "");
            r.add(a);
            r.add(b);
            assertEquals(List.of(b, a), r.list());
            Files.delete(b);
            assertEquals(List.of(a), new RecentFiles(node).list(), "a file that is gone is not offered");
            assertEquals(0, r.prune(), "and it was dropped from the store as the list was read");
            assertEquals(a.toString(), node.get("0", null));
            assertNull(node.get("1", null));
        } finally {
            node.removeNode();
        }
    }

    @Test
    void aPartialImageIsSuggestedUnderItsOwnName() {
        Path scene = Path.of("dir", "ball.txt");
        assertEquals("ball.png", SaveRules.suggestedTarget(scene, false).getFileName().toString());
        assertEquals("ball-partial.png", SaveRules.suggestedTarget(scene, true).getFileName().toString());
    }
}
