package ray.material;

import javax.vecmath.Vector3d;

/**
 * A user's {@link Material#shade(ray.Ray, ray.IntersectionRecord, ray.Scene)} returned null or a colour with
 * NaN in it. The message is one line naming the class, the method and the pixel being rendered, e.g.
 * {@code Tinted.shade returned null for pixel (12, 40)}; it carries no stack trace (the message says where).
 * The render stops there: a silently black or speckled image would hide the mistake.
 */
public final class BadColorException extends IllegalStateException {
    private static final long serialVersionUID = 1L;

    BadColorException(Material m, Vector3d c, int x, int y) {
        super(name(m.getClass()) + ".shade returned " + (c == null ? "null" : "a NaN colour " + c) + " for pixel (" + x + ", " + y
                + ") (expected a Vector3d of numbers)");
    }

    /** The class's binary name without its package: {@code Tinted}, {@code Outer$Inner}, {@code Outer$1}. */
    static String name(Class<?> c) {
        String n = c.getName();
        return n.substring(n.lastIndexOf('.') + 1);
    }

    @Override
    public synchronized Throwable fillInStackTrace() {
        return this;
    }
}
