import java.util.Locale;
import java.util.function.Supplier;
import javax.vecmath.Vector3d;

/**
 * The grader's helpers for its per-method checks: calling a student's method with a message that names
 * it, and comparing numbers and vectors. Each check fails with an AssertionError whose message starts
 * with the method at fault ("Sphere.intersects: ...").
 */
public final class GraderSupport {

    private GraderSupport() {
    }

    public static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    /** Calls a student's method; an exception it throws becomes a failure naming the method and the situation. */
    public static <T> T call(String method, String situation, Supplier<T> body) {
        try {
            return body.get();
        } catch (StackOverflowError e) {
            throw new AssertionError(method + ": " + situation + ": endless recursion (StackOverflowError)" + where(e), e);
        } catch (RuntimeException e) {
            throw new AssertionError(method + ": " + situation + ": threw " + e.getClass().getSimpleName()
                    + (e.getMessage() == null ? "" : " (" + e.getMessage() + ")") + where(e), e);
        }
    }

    public static void run(String method, String situation, Runnable body) {
        call(method, situation, () -> {
            body.run();
            return null;
        });
    }

    /** " at File.java:line" of the first frame outside the grader's checks and the JDK. */
    static String where(Throwable e) {
        for (StackTraceElement f : e.getStackTrace()) {
            String c = f.getClassName();
            if (!c.contains(".") && !c.startsWith("Check") && !c.startsWith("GraderSupport") && f.getFileName() != null) {
                return " at " + f.getFileName() + ":" + f.getLineNumber();
            }
        }
        return "";
    }

    public static AssertionError fail(String message) {
        return new AssertionError(message);
    }

    public static void expect(boolean ok, String message) {
        if (!ok) {
            throw new AssertionError(message);
        }
    }

    public static boolean near(double a, double b, double tol) {
        return Math.abs(a - b) <= tol * Math.max(1, Math.abs(b));
    }

    public static boolean near(Vector3d a, Vector3d b, double tol) {
        return a != null && near(a.x, b.x, tol) && near(a.y, b.y, tol) && near(a.z, b.z, tol);
    }

    public static String str(double d) {
        if (Double.isNaN(d) || Double.isInfinite(d)) {
            return Double.toString(d);
        }
        String s = String.format(Locale.ROOT, "%.4f", d);
        s = s.replaceAll("0+$", "").replaceAll("\\.$", "");
        return s.equals("-0") ? "0" : s;
    }

    public static String str(Vector3d v) {
        return v == null ? "null" : "(" + str(v.x) + ", " + str(v.y) + ", " + str(v.z) + ")";
    }

    /** Fails unless {@code got} is non-null and near {@code want}: "METHOD: SITUATION must be WANT; yours is GOT". */
    public static void expectVector(String method, String situation, String what, Vector3d got, Vector3d want, double tol) {
        if (got == null) {
            throw fail(method + ": " + situation + ": " + what + " must be " + str(want) + "; yours returned null");
        }
        if (!near(got, want, tol)) {
            throw fail(method + ": " + situation + ": " + what + " must be " + str(want) + "; yours is " + str(got));
        }
    }

    public static void expectNumber(String method, String situation, String what, double got, double want, double tol) {
        if (!near(got, want, tol)) {
            throw fail(method + ": " + situation + ": " + what + " must be " + str(want) + "; yours is " + str(got));
        }
    }
}
