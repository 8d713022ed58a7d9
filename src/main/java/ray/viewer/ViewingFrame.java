package ray.viewer;

import java.awt.AWTError;
import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.GraphicsEnvironment;
import java.awt.HeadlessException;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.File;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.SwingUtilities;
import javax.swing.Timer;
import ray.render.Image;
import ray.settings.RenderSettings;

/**
 * The viewer's window: open a scene (menu, Ctrl+O, drag and drop, recent files) and watch it render,
 * stop, re-render, watch the file for changes, zoom and scroll, save the image shown as a PNG. The
 * work is done by a {@link RenderSession} on background threads; this class only shows its events.
 * {@code raytracer} with no arguments opens it; the process ends when the last window closes.
 */
public final class ViewingFrame extends JFrame {
    private static final long serialVersionUID = 1L;
    private static final String TITLE = "RayTracer viewer";
    private static int openWindows;

    final ImageView view = new ImageView();
    private final JLabel status = new JLabel("Open a scene file: File > Open (Ctrl+O), or drop one here.");
    /** Right of the status line: the zoom, what is shown, the exposure. */
    final JLabel info = new JLabel("");
    /** Above the status line: the pixel under the cursor (position, linear and 8-bit values, the reference's). */
    final JLabel pixel = new JLabel(" ");
    private final JTextArea error = new JTextArea();
    private final transient RenderSession session;
    /** The recent files, used on {@link #BACKGROUND} only (created there: the preferences' first use is slow). */
    private transient RecentFiles recent;
    /** Where the preferences are written: off the event thread (the first write loads an XML writer). */
    private static final ExecutorService BACKGROUND = Executors.newSingleThreadExecutor(r -> {
        Thread t = new Thread(r, "viewer-prefs");
        t.setDaemon(true);
        return t;
    });
    private final transient FileWatch watch = new FileWatch();
    private final transient ViewerMenus menus;
    private final Timer ticker;
    private final JScrollPane scroll;
    private File lastDir = new File(".").getAbsoluteFile();
    /** The scene the window is about (title, re-render, watch), whether its last attempt failed, and where its reference came from. */
    private Path shownFile;
    private boolean failed;
    private Path referenceScene;

    ViewingFrame() {
        this(new RenderSettings());
    }

    /** A window whose renders use {@code settings} over each scene's globals (the command line's render options). */
    ViewingFrame(RenderSettings settings) {
        super(TITLE);
        session = new RenderSession(SwingUtilities::invokeLater, new SessionEvents(), Runtime.getRuntime().availableProcessors(), settings);
        menus = new ViewerMenus(this);
        setJMenuBar(menus.bar());
        menus.bindExtraKeys(getRootPane());
        updateRecent(null);
        error.setEditable(false);
        error.setLineWrap(true);
        error.setWrapStyleWord(true);
        error.setForeground(new Color(0xb00020));
        error.setBorder(BorderFactory.createEmptyBorder(6, 8, 6, 8));
        error.setVisible(false);
        status.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        status.setMinimumSize(new Dimension(0, status.getPreferredSize().height));
        status.setPreferredSize(new Dimension(0, status.getPreferredSize().height));   // the text never sizes the window
        info.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        info.setHorizontalAlignment(JLabel.RIGHT);
        pixel.setBorder(BorderFactory.createEmptyBorder(3, 8, 0, 8));
        pixel.setPreferredSize(new Dimension(0, pixel.getPreferredSize().height));
        pixel.setMinimumSize(new Dimension(0, pixel.getPreferredSize().height));
        view.onInfo((p, v) -> {
            pixel.setText(p.isEmpty() ? " " : p);
            info.setText(v);
        });
        JPanel line = new JPanel(new BorderLayout());
        line.add(status, BorderLayout.CENTER);
        line.add(info, BorderLayout.EAST);
        JPanel lines = new JPanel(new BorderLayout());
        lines.add(pixel, BorderLayout.NORTH);
        lines.add(line, BorderLayout.SOUTH);
        JPanel south = new JPanel(new BorderLayout());
        south.add(error, BorderLayout.NORTH);
        south.add(lines, BorderLayout.SOUTH);
        scroll = new JScrollPane(view);
        scroll.setBorder(BorderFactory.createEmptyBorder());
        add(scroll, BorderLayout.CENTER);
        add(south, BorderLayout.SOUTH);
        setTransferHandler(new SceneDrop(this::load, this::showError));
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        addWindowListener(new Closing());
        ticker = new Timer(200, e -> tick());
        ticker.start();
        setSize(720, 560);
        setLocationByPlatform(true);
        updateActions();
    }

    /**
     * Opens a viewer window, rendering {@code scene} if it is not null, and returns once it is shown
     * (the render goes on in the background). Throws {@link HeadlessException} with a one-line reason
     * when there is no display to open it on: none configured, or one that cannot be reached.
     */
    public static void open(Path scene) throws HeadlessException {
        open(scene == null ? List.of() : List.of(scene), new RenderSettings());
    }

    /**
     * Opens one viewer window per scene (one empty window when there is none), each rendering its scene
     * with {@code settings} over the scene's globals ({@code raytracer --view --samples 4 a.txt b.txt});
     * returns once they are shown. Throws {@link HeadlessException} as {@link #open(Path)}.
     */
    public static void open(List<Path> scenes, RenderSettings settings) throws HeadlessException {
        if (GraphicsEnvironment.isHeadless()) {
            throw new HeadlessException("no display");
        }
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();   // connects to the display
            SwingUtilities.invokeAndWait(() -> {
                LookAndFeels.install();
                int i = 0;
                for (Path scene : scenes.isEmpty() ? java.util.Collections.<Path>singletonList(null) : scenes) {
                    ViewingFrame f = new ViewingFrame(settings);
                    if (i > 0) {
                        f.setLocation(40 * i, 40 * i);              // cascaded, each title visible
                    }
                    i++;
                    f.setVisible(true);
                    if (scene != null) {
                        f.load(scene);
                    }
                }
            });
        } catch (InvocationTargetException e) {
            Throwable cause = e.getCause();
            if (cause instanceof HeadlessException || cause instanceof AWTError || cause instanceof InternalError) {
                throw noDisplay(cause);
            }
            throw cause instanceof RuntimeException r ? r : new IllegalStateException(cause);
        } catch (AWTError | InternalError e) {
            throw noDisplay(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static HeadlessException noDisplay(Throwable e) {
        String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        return new HeadlessException(ray.Failures.oneLine("cannot open the display (" + why + ")"));
    }

    /** Closes every viewer window; the process then ends. */
    static void quitAll() {
        for (Window w : Window.getWindows()) {
            if (w instanceof ViewingFrame && w.isDisplayable()) {
                w.dispose();
            }
        }
    }

    /** Reads and renders {@code file} (in the background); the image shown stays until the new one starts. */
    void load(Path file) {
        lastDir = file.toAbsolutePath().getParent().toFile();
        if (menus.watch.isSelected()) {
            watch.watch(file);
        }
        session.open(file);
        updateRecent(file);
    }

    /** File > Open recent: a file that is gone is said so and dropped from the list. */
    void openRecent(Path file) {
        if (!java.nio.file.Files.isRegularFile(file)) {
            showError(file + " no longer exists; removed from Open recent");
            updateRecent(null);                 // the list drops missing files as it is read
            return;
        }
        load(file);
    }

    /** Puts {@code file} (if not null) first in the recent files and rebuilds the menu; the store's work in the background. */
    private void updateRecent(Path file) {
        BACKGROUND.execute(() -> {
            if (recent == null) {
                recent = RecentFiles.user();
            }
            if (file != null) {
                recent.add(file);
            }
            List<Path> l = recent.list();
            SwingUtilities.invokeLater(() -> menus.recentFiles(l));
        });
    }

    /** Close window: the render stops first, so closing does not wait for busy processors. */
    void close() {
        session.stop();
        dispose();
    }

    void chooseScene() {
        Path p = Dialogs.chooseScene(this, lastDir);
        if (p != null) {
            load(p);
        }
    }

    void rerender() {
        RenderJob job = session.current();
        if (job != null) {
            load(job.file());
        }
    }

    void stop() {
        session.stop();
    }

    /** Render > Watch file toggled: watches the scene of this window, or says there is none yet. */
    void watchChanged() {
        RenderJob job = session.current();
        if (menus.watch.isSelected() && job == null) {
            menus.watch.setSelected(false);
            setStatus("Watch file: open a scene first (File > Open); then saving it in an editor re-renders it.");
        }
        boolean on = menus.watch.isSelected();
        watch.watch(on ? job.file() : null);
        if (on) {
            setStatus("Watching " + job.file().getFileName() + ": saving it re-renders it.");
        }
        updateTitle();
    }

    /** File > Open reference image: a PNG to compare the render with (its own folder remembered). */
    void chooseReference() {
        Path p = Dialogs.chooseReference(this, lastDir);
        if (p != null) {
            loadReference(p);
            if (view.hasReference()) {
                show(ImageView.Mode.DIFFERENCE);
            }
        }
    }

    /** Reads {@code png} as the reference (null: none); a file that cannot be read is said so, and none is kept. */
    private void loadReference(Path png) {
        if (png == null) {
            view.reference(null, null);
        } else {
            try {
                java.awt.image.BufferedImage img = javax.imageio.ImageIO.read(png.toFile());
                if (img == null) {
                    throw new java.io.IOException("not an image ImageIO can read");
                }
                view.reference(img, png.getFileName().toString());
            } catch (java.io.IOException | RuntimeException e) {
                view.reference(null, null);
                showError("Cannot read the reference image " + png + ": " + ErrorTexts.reason(e));
            }
        }
        RenderJob job = session.current();
        referenceScene = job == null ? null : job.file();
        updateActions();
    }

    void show(ImageView.Mode m) {
        view.mode(m);
        updateActions();
    }

    void toggleAB() {
        view.toggle();
        updateActions();
    }

    /** Changes the exposure by {@code stops}; 0 sets it back to 0 (the PNG's values). */
    void exposure(double stops) {
        view.exposure(stops == 0 ? 0 : view.exposure() + stops);
    }

    /** The title names the scene the window is about, whether its last attempt failed, and whether it is watched. */
    private void updateTitle() {
        setTitle(shownFile == null ? TITLE : TITLE + " - " + shownFile.getFileName() + (failed ? " (failed)" : "")
                + (menus.watch.isSelected() ? " (watching)" : ""));
    }

    void saveImage() {
        RenderJob shown = session.saveable();
        if (shown == null) {
            return;                    // the action is disabled then; a shortcut may still arrive
        }
        RenderJob current = session.current();
        String saved = Dialogs.save(this, shown, current == null ? null : current.file());
        if (saved != null) {
            setStatus(saved);
        }
    }

    private void setStatus(String text) {
        status.setText(text);
        status.setToolTipText(text);      // the whole line when the window is narrower than the text
    }

    void showError(String text) {
        error.setText(text);
        error.setVisible(text != null);
        revalidate();
    }

    /** Five times a second: the status of a running render, and the watched file. */
    private void tick() {
        RenderJob job = session.current();
        if (job != null && job.state() == RenderJob.State.RENDERING) {
            setStatus(StatusText.of(job, System.nanoTime()));
        }
        if (menus.watch.isSelected() && watch.changed()) {
            load(watch.file());
        }
    }

    private void updateActions() {
        menus.save.setEnabled(session.canSave());
        RenderJob saveable = session.saveable();
        menus.save.putValue(javax.swing.Action.NAME, saveable != null && saveable.partial() ? "Save partial image as PNG..." : "Save image as PNG...");
        boolean ref = view.hasReference();
        menus.showReference.setEnabled(ref);
        menus.showDifference.setEnabled(ref);
        menus.toggleAB.setEnabled(ref);
        menus.renderItem.setSelected(view.mode() == ImageView.Mode.RENDER);
        menus.referenceItem.setSelected(view.mode() == ImageView.Mode.REFERENCE);
        menus.differenceItem.setSelected(view.mode() == ImageView.Mode.DIFFERENCE);
        menus.stop.setEnabled(session.busy());
        menus.rerender.setEnabled(session.current() != null);
        boolean image = view.hasImage();
        menus.fit.setEnabled(image);
        menus.actual.setEnabled(image);
        menus.zoomIn.setEnabled(image);
        menus.zoomOut.setEnabled(image);
    }

    /** The window's first size: the image at 1:1 plus the frame, at most 90% of the screen's usable area. */
    private void sizeFor(int w, int h) {
        GraphicsConfiguration gc = getGraphicsConfiguration();
        Rectangle screen = gc.getBounds();
        Insets in = Toolkit.getDefaultToolkit().getScreenInsets(gc);
        int maxW = (screen.width - in.left - in.right) * 9 / 10, maxH = (screen.height - in.top - in.bottom) * 9 / 10;
        Dimension viewport = scroll.getViewport().getExtentSize();
        int chromeW = getWidth() - viewport.width, chromeH = getHeight() - viewport.height;
        setSize(Math.max(720, Math.min(maxW, w + chromeW)), Math.max(400, Math.min(maxH, h + chromeH)));
    }

    /** The session's events, on the event thread. */
    private final class SessionEvents implements RenderSession.View {
        private boolean sized;

        @Override
        public void parsing(RenderJob job) {
            setStatus(StatusText.of(job, System.nanoTime()));
            updateActions();
        }

        /** A new scene's own reference image is found again; one chosen by hand stays for the same scene. */
        private void findReference(RenderJob job) {
            if (!job.file().equals(referenceScene)) {
                loadReference(Compare.referenceFor(job.file()));
            }
        }

        @Override
        public void rendering(RenderJob job) {
            showError(null);
            shownFile = job.file();
            failed = false;
            updateTitle();
            view.reset(job.partialImage());
            findReference(job);
            if (!sized) {
                sized = true;
                sizeFor(job.scene().width, job.scene().height);
            }
            setStatus(StatusText.of(job, System.nanoTime()));
            updateActions();
        }

        @Override
        public void tile(RenderJob job, Image image, int x0, int y0, int x1, int y1) {
            view.copyTile(image, x0, y0, x1, y1);
        }

        @Override
        public void ended(RenderJob job) {
            if (job.state() == RenderJob.State.FAILED) {
                System.err.println(ray.Failures.oneLine(job.error()));   // as on the command line (and as warnings are): one line on stderr too
                showError(job.error());
                RenderJob back = session.shown();
                // the last finished image comes back if it is this file's; another scene's does not stay
                // beside this file's error (title, Save and Re-render all name this file now)
                view.show(back == null ? null : back.image());
                shownFile = job.file();
                failed = true;
                updateTitle();
                if (back == null) {
                    loadReference(null);
                }
            } else if (job.state() == RenderJob.State.DONE) {
                view.show(job.image());            // exactly the finished image, whatever the tiles showed
                for (String w : job.warnings()) {
                    System.err.println(w);
                }
                showError(job.warnings().isEmpty() ? null : String.join("\n", job.warnings()));
            }
            setStatus(StatusText.of(job, System.nanoTime()));
            updateActions();
        }
    }

    /** Closing the window stops its work at once; the last window's closing ends the process. */
    private final class Closing extends WindowAdapter {
        @Override
        public void windowClosing(WindowEvent e) {
            session.stop();
        }

        @Override
        public void windowOpened(WindowEvent e) {
            openWindows++;
        }

        @Override
        public void windowClosed(WindowEvent e) {
            session.stop();
            ticker.stop();
            if (--openWindows <= 0) {
                System.exit(0);       // render threads are daemons, but a user class may have started others
            }
        }
    }
}
