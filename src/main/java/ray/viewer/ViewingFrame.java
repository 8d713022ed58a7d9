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
        JPanel south = new JPanel(new BorderLayout());
        south.add(error, BorderLayout.NORTH);
        south.add(status, BorderLayout.SOUTH);
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
        open(scene, new RenderSettings());
    }

    /** {@link #open(Path)}, rendering with {@code settings} over each scene's globals ({@code raytracer --view --samples 4 ...}). */
    public static void open(Path scene, RenderSettings settings) throws HeadlessException {
        if (GraphicsEnvironment.isHeadless()) {
            throw new HeadlessException("no display");
        }
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment().getScreenDevices();   // connects to the display
            SwingUtilities.invokeAndWait(() -> {
                LookAndFeels.install();
                ViewingFrame f = new ViewingFrame(settings);
                f.setVisible(true);
                if (scene != null) {
                    f.load(scene);
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
        return new HeadlessException(Failures.oneLine("cannot open the display (" + why + ")"));
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

    void watchChanged() {
        RenderJob job = session.current();
        watch.watch(menus.watch.isSelected() && job != null ? job.file() : null);
    }

    void saveImage() {
        RenderJob shown = session.shown();
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

        @Override
        public void rendering(RenderJob job) {
            showError(null);
            setTitle(TITLE + " - " + job.file().getFileName());
            view.reset(job.scene().width, job.scene().height);
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
                showError(job.error());
                RenderJob back = session.shown();
                if (back != null) {
                    view.show(back.image());        // the last finished image comes back
                    setTitle(TITLE + " - " + back.file().getFileName());
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
