package ray;

/**
 * Turns any {@link Throwable} (most often from a user's own class: an exception, an {@code Error}, a
 * checked exception thrown sneakily, one whose {@code getMessage()} itself throws) into a short,
 * one-line description naming its class, its message and the method that threw it. Every mode reports
 * user code's failures through here: the render, {@code --plan}, {@code --study}, the viewer.
 */
public final class Failures {

    /** Longest message kept from a throwable; longer ones are cut with "...". */
    static final int MAX_MESSAGE = 200;

    private Failures() {
    }

    /**
     * {@code SimpleName (message) at Class.method(File.java:12)}; an IllegalArgumentException or
     * IllegalStateException with a message (a value a scene object refused) is just its message.
     */
    public static String describe(Throwable e) {
        String msg = message(e);
        Throwable cause = cause(e);
        if (msg == null && cause != null) {     // ExceptionInInitializerError, InvocationTargetException, ...
            String cm = message(cause);
            msg = "caused by " + simpleName(cause.getClass()) + (cm == null ? "" : ": " + cm);
        }
        String what = msg != null && (e instanceof IllegalArgumentException || e instanceof IllegalStateException)
                ? msg : simpleName(e.getClass()) + (msg == null ? "" : " (" + msg + ")");
        StackTraceElement at = where(e);
        return what + (at == null ? "" : " at " + safeString(at));
    }

    /** The message, on one line and cut to {@link #MAX_MESSAGE}, or null; never throws. */
    public static String message(Throwable e) {
        String m;
        try {
            m = e.getMessage();
        } catch (Throwable t) {      // a user's getMessage() that fails
            return "its getMessage() threw " + simpleName(t.getClass());
        }
        if (m == null) {
            return null;
        }
        m = oneLine(m).trim();
        return m.length() <= MAX_MESSAGE ? m : m.substring(0, MAX_MESSAGE) + "... (" + m.length() + " characters)";
    }

    /** The simple name, or for an anonymous class its binary name without the package. */
    public static String simpleName(Class<?> c) {
        String s = c.getSimpleName();
        if (!s.isEmpty()) {
            return s;
        }
        String n = c.getName();
        return n.substring(n.lastIndexOf('.') + 1);
    }

    private static Throwable cause(Throwable e) {
        try {
            return e.getCause();
        } catch (Throwable t) {
            return null;
        }
    }

    /**
     * The frame to blame: the first one outside the JDK (so a NullPointerException inside a JDK
     * method called by a user's shade() names shade()), else the top frame; null without a stack.
     */
    public static StackTraceElement where(Throwable e) {
        StackTraceElement[] st;
        try {
            st = e.getStackTrace();
        } catch (Throwable t) {
            return null;
        }
        if (st == null || st.length == 0) {
            return null;
        }
        for (StackTraceElement f : st) {
            String c = f.getClassName();
            if (!(c.startsWith("java.") || c.startsWith("javax.") || c.startsWith("jdk.") || c.startsWith("sun.")
                    || c.startsWith("com.sun."))) {
                return f;
            }
        }
        return st[0];
    }

    /** Keeps an error report on one line whatever a message or a file name holds (control characters become spaces). */
    public static String oneLine(String s) {
        // what s.replaceAll("[\\p{Cntrl}\u2028\u2029]+", " ") gives, without the regex: its character
        // class is a lambda inside java.util.regex, and the first lambda a process calls spins it a class
        // (the method-handle machinery, about 90 classes), on every render's summary line
        int n = s.length(), i = 0;
        while (i < n && !lineBreaking(s.charAt(i))) {
            i++;
        }
        if (i == n) {
            return s;
        }
        StringBuilder b = new StringBuilder(n).append(s, 0, i);
        while (i < n) {
            char c = s.charAt(i++);
            if (lineBreaking(c)) {
                b.append(' ');
                while (i < n && lineBreaking(s.charAt(i))) {
                    i++;
                }
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }

    /** A character {@link #oneLine} replaces: a POSIX control character ({@code \p{Cntrl}}) or U+2028, U+2029. */
    private static boolean lineBreaking(char c) {
        return c < 0x20 || c == 0x7f || c == '\u2028' || c == '\u2029';
    }

    private static String safeString(StackTraceElement f) {
        return oneLine(f.toString());
    }
}
