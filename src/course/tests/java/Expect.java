import javax.vecmath.Vector3d;
import org.opentest4j.AssertionFailedError;

/** Assertions whose failures say, in words, what the method had to do and what yours did. */
final class Expect {

    /** Numbers closer than this count as equal. */
    static final double TOLERANCE = 1e-6;

    private Expect() {
    }

    /**
     * Fails the test with {@code message} alone: no stack trace, since the message says everything (a
     * stack trace is kept for exceptions your code throws).
     */
    static AssertionFailedError fail(String message) {
        AssertionFailedError e = new AssertionFailedError(message);
        e.setStackTrace(new StackTraceElement[0]);
        throw e;
    }

    /** "(0, 0, 1)" with short numbers. */
    static String show(Vector3d v) {
        return v == null ? "null" : "(" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ")";
    }

    static String show(double x, double y, double z) {
        return show(new Vector3d(x, y, z));
    }

    static String num(double d) {
        if (d == Math.rint(d) && Math.abs(d) < 1e9) {
            return String.valueOf((long) d);
        }
        String s = String.format("%.6g", d);
        if (s.contains(".") && !s.contains("e")) {
            s = s.replaceAll("0+$", "").replaceAll("\\.$", "");
        }
        return s;
    }

    static Vector3d v(double x, double y, double z) {
        return new Vector3d(x, y, z);
    }

    static Vector3d unit(double x, double y, double z) {
        double length = Math.sqrt(x * x + y * y + z * z);
        return new Vector3d(x / length, y / length, z / length);
    }

    static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray(new Vector3d(ox, oy, oz), new Vector3d(dx, dy, dz));
    }

    /** Fails with "{method}: {must}; yours returned {what}" unless {@code ok}. */
    static void that(boolean ok, String method, String must, String yours) {
        if (!ok) {
            fail(method + ": " + must + "; yours " + yours);
        }
    }

    static void near(double expected, double actual, String method, String what) {
        if (!(Math.abs(expected - actual) <= TOLERANCE * Math.max(1, Math.abs(expected)))) {
            fail(method + ": " + what + " must be " + num(expected) + "; yours is " + num(actual));
        }
    }

    static void near(Vector3d expected, Vector3d actual, String method, String what) {
        if (actual == null) {
            fail(method + ": " + what + " must be " + show(expected) + "; yours is null");
        }
        if (!(close(expected.x, actual.x) && close(expected.y, actual.y) && close(expected.z, actual.z))) {
            fail(method + ": " + what + " must be " + show(expected) + "; yours is " + show(actual));
        }
    }

    /** A colour returned by {@code method}: not null, no NaN, and {@code expected}. */
    static void color(Vector3d expected, Vector3d actual, String method, String situation) {
        if (actual == null) {
            fail(method + " returned null for " + situation + " (expected the colour " + show(expected) + " in a new Vector3d)");
        }
        if (Double.isNaN(actual.x) || Double.isNaN(actual.y) || Double.isNaN(actual.z)) {
            fail(method + " returned a NaN colour " + show(actual) + " for " + situation + " (expected " + show(expected)
                    + "; NaN comes from 0/0, sqrt of a negative number or normalizing a zero vector)");
        }
        near(expected, actual, method, "the colour for " + situation);
    }

    static boolean close(double a, double b) {
        return Math.abs(a - b) <= TOLERANCE * Math.max(1, Math.abs(a));
    }
}
