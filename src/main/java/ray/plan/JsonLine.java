package ray.plan;

/**
 * One JSON object on one line (JSON Lines), written by hand: string, number, boolean and null values,
 * nested objects. Numbers that are whole and below 2^53 print as integers, infinite ones as null.
 */
public final class JsonLine {

    private final StringBuilder b = new StringBuilder("{");
    private boolean first = true;

    private JsonLine key(String k) {
        if (!first) {
            b.append(',');
        }
        first = false;
        string(k);
        b.append(':');
        return this;
    }

    public JsonLine put(String k, String v) {
        key(k);
        if (v == null) {
            b.append("null");
        } else {
            string(v);
        }
        return this;
    }

    public JsonLine put(String k, double v) {
        key(k);
        b.append(number(v));
        return this;
    }

    public JsonLine put(String k, boolean v) {
        key(k);
        b.append(v);
        return this;
    }

    /** Starts a nested object under {@code k}; {@link #close()} ends it. */
    public JsonLine open(String k) {
        key(k);
        b.append('{');
        first = true;
        return this;
    }

    public JsonLine close() {
        b.append('}');
        first = false;
        return this;
    }

    /** A JSON array of strings under {@code k}. */
    public JsonLine put(String k, java.util.List<String> values) {
        key(k);
        b.append('[');
        for (int i = 0; i < values.size(); i++) {
            if (i > 0) {
                b.append(',');
            }
            string(values.get(i));
        }
        b.append(']');
        return this;
    }

    @Override
    public String toString() {
        return b + "}";
    }

    /** {@code v} as a JSON number: an integer where it is one (below 2^53), null where not finite. */
    public static String number(double v) {
        if (!Double.isFinite(v)) {
            return "null";
        }
        if (v == Math.rint(v) && Math.abs(v) < 0x1p53) {
            return Long.toString((long) v);
        }
        return Double.toString(v);
    }

    private void string(String s) {
        quote(b, s);
    }

    /** {@code s} as a JSON string (quoted, escaped) appended to {@code b}; also ray.grade's reports. */
    public static void quote(StringBuilder b, String s) {
        b.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> b.append("\\\"");
                case '\\' -> b.append("\\\\");
                case '\n' -> b.append("\\n");
                case '\r' -> b.append("\\r");
                case '\t' -> b.append("\\t");
                default -> {
                    if (c < 0x20 || c == 0x2028 || c == 0x2029) {
                        b.append(String.format("\\u%04x", (int) c));
                    } else {
                        b.append(c);
                    }
                }
            }
        }
        b.append('"');
    }
}
