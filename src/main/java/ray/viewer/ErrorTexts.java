package ray.viewer;

import java.nio.file.AccessDeniedException;
import java.nio.file.FileSystemException;
import java.nio.file.NoSuchFileException;

/**
 * The viewer's error texts for its status line and dialogs: whole, on one line each, naming what failed
 * and never a temporary file. What a user's class threw is described by {@link ray.Failures}, as in every mode.
 */
final class ErrorTexts {

    private ErrorTexts() {
    }

    /**
     * A failure inside a render or a user's class, naming the method it happened in: the first stack
     * frame outside the JDK, e.g. {@code rendering failed in ThrowingMaterial.shade (ThrowingMaterial.java:12):
     * UnsupportedOperationException: student code not finished}.
     */
    static String describe(String what, Throwable e) {
        StringBuilder b = new StringBuilder(what);
        StackTraceElement at = firstOutsideJdk(e);
        if (at != null) {
            String cls = at.getClassName();
            b.append(" in ").append(cls.substring(cls.lastIndexOf('.') + 1)).append('.').append(at.getMethodName());
            if (at.getFileName() != null && at.getLineNumber() > 0) {
                b.append(" (").append(at.getFileName()).append(':').append(at.getLineNumber()).append(')');
            }
        }
        b.append(": ").append(ray.Failures.simpleName(e.getClass()));
        String m = ray.Failures.message(e);     // never throws, even when the user's getMessage() does; cut to a line
        if (m != null) {
            b.append(": ").append(m);
        }
        return ray.Failures.oneLine(b.toString());
    }

    private static StackTraceElement firstOutsideJdk(Throwable e) {
        return ray.Failures.where(e);     // never throws, even for a user's Throwable with an odd stack
    }

    /** Why a file operation failed, without the (temporary) path the exception may name. */
    static String reason(Exception e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "no such folder";
        }
        if (e instanceof FileSystemException fse && fse.getReason() != null) {
            return fse.getReason();
        }
        if (e instanceof FileSystemException) {
            return e.getClass().getSimpleName();
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }
}
