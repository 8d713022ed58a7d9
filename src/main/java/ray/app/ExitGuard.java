package ray.app;

import java.io.PrintStream;
import java.util.Map;
import ray.io.OutputFile;

/**
 * The shutdown hook of the {@code raytracer} process. It knows which scene is being read or rendered;
 * when the JVM shuts down during that work, either a user's class called {@code System.exit} (then the
 * run must not look like a success: one line naming the scene and the calling method, and the process
 * halts with status 1 whatever status the class asked for) or the user pressed Ctrl+C (then the
 * progress line is erased). Temporary image files are removed in both cases.
 */
final class ExitGuard extends Thread {

    /** Exit status after a user's class ended the program. */
    static final int USER_EXIT_STATUS = 1;

    private static volatile String scene;
    /** The last scene worked on, for an exit between two scenes. */
    private static volatile String lastScene;
    private static volatile ProgressLine progress;
    private static volatile boolean installed;
    /** While the command runs (every mode but the open viewer): any System.exit then is not ours. */
    private static volatile boolean active;
    /** While the viewer is open: a System.exit from a user's class (a render, a thread it started) is not a quit. */
    private static volatile boolean viewer;
    private final PrintStream err;

    private ExitGuard(PrintStream err) {
        super("raytracer-exit-guard");
        this.err = err;
    }

    /** Installs the hook (once per JVM); only the real process does this, never a test calling Main.run. */
    static void install(PrintStream err) {
        if (!installed) {
            installed = true;
            Runtime.getRuntime().addShutdownHook(new ExitGuard(err));
        }
    }

    /** What is being done to the scene, for the line: "rendered", "planned", "studied". */
    private static volatile String doing = "rendered";

    /** The scene now being read or rendered, or null between scenes. */
    static void working(String sceneName, ProgressLine line) {
        working(sceneName, line, "rendered");
    }

    /** The scene now being read and {@code what} ("rendered", "planned", "studied"). */
    static void working(String sceneName, ProgressLine line, String what) {
        progress = line;
        doing = what;
        scene = sceneName;
        lastScene = sceneName;
    }

    /**
     * Whether the command is running: from the start of {@link Main#runProcess} until it returns its
     * status (render, --plan, --study alike). A System.exit in that time, from any thread (a user's
     * class, or a thread it started, even between two scenes), ends the run with status 1 and a line.
     */
    static void active(boolean on) {
        active = on;
    }

    /**
     * The viewer is open (after {@link Main#runProcess} has returned {@link Main#VIEWER_OPEN}): from now
     * on the program ends when its windows are closed (the viewer's own System.exit, or the JDK's), and a
     * System.exit from any other code (a user's class rendering, or a thread it started) ends it with
     * status 1 and one line, instead of closing the windows silently with the status the class chose.
     */
    static void viewerOpen() {
        viewer = true;
        active = true;
    }

    static void idle() {
        scene = null;
        progress = null;
    }

    @Override
    public void run() {
        ProgressLine p = progress;
        if (p != null) {
            p.clear();
        }
        String s = scene;
        if (s == null && !active) {
            return;
        }
        String caller = exitCaller();
        if (caller == null) {
            return;         // a signal (Ctrl+C): the JVM's own status (130) says so; OutputFile's hook cleans up
        }
        if (viewer && s == null && ownCode(caller.substring(0, caller.lastIndexOf('.')))) {
            return;         // the viewer's last window closed, or its Quit
        }
        OutputFile.deletePendingTemporaries();
        String last = lastScene;
        err.println(Main.oneLine(s != null ? s + ": " + caller + " called System.exit while the scene was being "
                + doing + "; the program stopped there" + (doing.equals("rendered") ? " and no image was written" : "")
                : viewer ? "raytracer: " + caller + " called System.exit while the viewer was open; the viewer closed there "
                        + "(a class of yours ended the program; nothing was saved)"
                : "raytracer: " + caller + " called System.exit" + (last != null ? " after " + last : "")
                        + "; the program stopped there and the scenes after it were not done"));
        err.flush();
        Runtime.getRuntime().halt(USER_EXIT_STATUS);
    }

    /**
     * Whether {@code className} is the renderer's own or the JDK's (loaded from this program's own jar
     * or folder, or by the JDK's loaders), not a user's class from the class path.
     */
    static boolean ownCode(String className) {
        try {
            Class<?> c = Class.forName(className, false, ExitGuard.class.getClassLoader());
            ClassLoader l = c.getClassLoader();
            if (l == null || l == ClassLoader.getPlatformClassLoader()) {
                return true;
            }
            java.security.CodeSource mine = ExitGuard.class.getProtectionDomain().getCodeSource();
            java.security.CodeSource its = c.getProtectionDomain().getCodeSource();
            return mine != null && its != null && mine.getLocation() != null && mine.getLocation().equals(its.getLocation());
        } catch (ClassNotFoundException | LinkageError | SecurityException e) {
            return false;
        }
    }

    /** The method that called System.exit or Runtime.exit, or null if no thread is exiting that way. */
    static String exitCaller() {
        for (Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
            StackTraceElement[] st = e.getValue();
            int last = -1;
            for (int i = 0; i < st.length; i++) {
                String c = st[i].getClassName();
                if ((c.equals("java.lang.Runtime") || c.equals("java.lang.System")) && st[i].getMethodName().equals("exit")) {
                    last = i;
                }
            }
            if (last >= 0 && last + 1 < st.length) {
                StackTraceElement f = st[last + 1];
                return f.getClassName() + "." + f.getMethodName();
            }
        }
        return null;
    }
}
