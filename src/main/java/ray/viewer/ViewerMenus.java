package ray.viewer;

import java.awt.Toolkit;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.nio.file.Path;
import java.util.List;
import javax.swing.AbstractAction;
import javax.swing.Action;
import javax.swing.ButtonGroup;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.KeyStroke;

/** The viewer's menus; every item has a keyboard shortcut (listed in the README). */
final class ViewerMenus {

    private static final int MENU = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();

    final Action open, openReference, save, rerender, stop, close, quit, fit, actual, zoomIn, zoomOut;
    final Action showRender, showReference, showDifference, toggleAB, brighter, darker, exposureZero;
    final JCheckBoxMenuItem watch = new JCheckBoxMenuItem("Watch file (re-render when it changes)");
    final JRadioButtonMenuItem renderItem, referenceItem, differenceItem;
    final JMenu recent = new JMenu("Open recent");
    private final ViewingFrame frame;

    ViewerMenus(ViewingFrame f) {
        frame = f;
        open = action("Open scene...", key(KeyEvent.VK_O, MENU), f::chooseScene);
        openReference = action("Open reference image...", key(KeyEvent.VK_O, MENU | InputEvent.SHIFT_DOWN_MASK), f::chooseReference);
        save = action("Save image as PNG...", key(KeyEvent.VK_S, MENU), f::saveImage);
        rerender = action("Re-render (read the file again)", key(KeyEvent.VK_R, MENU), f::rerender);
        stop = action("Stop", key(KeyEvent.VK_PERIOD, MENU), f::stop);
        close = action("Close window", key(KeyEvent.VK_W, MENU), f::close);
        quit = action("Quit", key(KeyEvent.VK_Q, MENU), ViewingFrame::quitAll);
        fit = action("Zoom to fit", key(KeyEvent.VK_0, MENU), () -> f.view.fitToView());
        actual = action("Actual size (1:1)", key(KeyEvent.VK_1, MENU), () -> f.view.actualSize());
        zoomIn = action("Zoom in", key(KeyEvent.VK_EQUALS, MENU), () -> f.view.zoomIn());
        zoomOut = action("Zoom out", key(KeyEvent.VK_MINUS, MENU), () -> f.view.zoomOut());
        showRender = action("Show render (A)", key(KeyEvent.VK_2, MENU), () -> f.show(ImageView.Mode.RENDER));
        showReference = action("Show reference (B)", key(KeyEvent.VK_3, MENU), () -> f.show(ImageView.Mode.REFERENCE));
        showDifference = action("Show difference (heat map)", key(KeyEvent.VK_4, MENU), () -> f.show(ImageView.Mode.DIFFERENCE));
        toggleAB = action("Toggle render / reference (A/B)", key(KeyEvent.VK_T, MENU), f::toggleAB);
        brighter = action("Brighter (+1/2 stop)", key(KeyEvent.VK_E, MENU), () -> f.exposure(0.5));
        darker = action("Darker (-1/2 stop)", key(KeyEvent.VK_E, MENU | InputEvent.SHIFT_DOWN_MASK), () -> f.exposure(-0.5));
        exposureZero = action("Exposure 0 (the PNG's values)", key(KeyEvent.VK_E, MENU | InputEvent.ALT_DOWN_MASK), () -> f.exposure(0));
        renderItem = new JRadioButtonMenuItem(showRender);
        referenceItem = new JRadioButtonMenuItem(showReference);
        differenceItem = new JRadioButtonMenuItem(showDifference);
        ButtonGroup shows = new ButtonGroup();
        shows.add(renderItem);
        shows.add(referenceItem);
        shows.add(differenceItem);
        renderItem.setSelected(true);
        watch.setAccelerator(key(KeyEvent.VK_W, MENU | InputEvent.SHIFT_DOWN_MASK));
        watch.addActionListener(e -> f.watchChanged());
    }

    JMenuBar bar() {
        JMenuBar bar = new JMenuBar();
        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(open);
        file.add(recent);
        file.add(openReference);
        file.addSeparator();
        file.add(save);
        file.addSeparator();
        file.add(close);
        file.add(quit);
        JMenu render = new JMenu("Render");
        render.setMnemonic(KeyEvent.VK_R);
        render.add(rerender);
        render.add(stop);
        render.addSeparator();
        render.add(watch);
        JMenu view = new JMenu("View");
        view.setMnemonic(KeyEvent.VK_V);
        view.add(fit);
        view.add(actual);
        view.add(zoomIn);
        view.add(zoomOut);
        view.addSeparator();
        view.add(renderItem);
        view.add(referenceItem);
        view.add(differenceItem);
        view.add(toggleAB);
        view.addSeparator();
        view.add(brighter);
        view.add(darker);
        view.add(exposureZero);
        bar.add(file);
        bar.add(render);
        bar.add(view);
        return bar;
    }

    /** Extra keys: F5 re-renders, Escape stops, Ctrl+Plus and the keypad's + and - zoom. */
    void bindExtraKeys(JComponent root) {
        bind(root, KeyStroke.getKeyStroke(KeyEvent.VK_F5, 0), rerender);
        bind(root, KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), stop);
        bind(root, key(KeyEvent.VK_PLUS, MENU), zoomIn);
        bind(root, key(KeyEvent.VK_ADD, MENU), zoomIn);
        bind(root, key(KeyEvent.VK_SUBTRACT, MENU), zoomOut);
    }

    private static void bind(JComponent root, KeyStroke k, Action a) {
        root.getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(k, a.getValue(Action.NAME));
        root.getActionMap().put(a.getValue(Action.NAME), a);
    }

    /** Rebuilds File > Open recent from {@code files} (newest first); Ctrl+Alt+1..8 open them. */
    void recentFiles(List<Path> files) {
        recent.removeAll();
        int i = 0;
        for (Path p : files) {
            i++;
            JMenuItem item = new JMenuItem(i + "  " + p.getFileName() + "  (" + p.getParent() + ")");
            item.setAccelerator(key(KeyEvent.VK_0 + i, MENU | InputEvent.ALT_DOWN_MASK));
            item.addActionListener(e -> frame.openRecent(p));
            recent.add(item);
        }
        recent.setEnabled(i > 0);
    }

    private static KeyStroke key(int code, int modifiers) {
        return KeyStroke.getKeyStroke(code, modifiers);
    }

    private static Action action(String name, KeyStroke key, Runnable r) {
        Action a = new AbstractAction(name) {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(java.awt.event.ActionEvent e) {
                r.run();
            }
        };
        a.putValue(Action.ACCELERATOR_KEY, key);
        return a;
    }
}
