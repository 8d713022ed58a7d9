package ray.settings;

import java.util.List;

/**
 * The render settings, one row each: the scene global that sets it, the command-line option that
 * overrides it, its type, its range and the hint an error message gives. The one place they are
 * defined: the parser checks the scene's globals against these rows, {@link RenderSettings} its
 * arguments, the command line its options, and the render plan and the renderer read the values a
 * {@link RenderSettings} resolved from them.
 */
public enum RenderOption {

    /** The sampler: where a pixel's samples go. */
    SAMPLER("Sampler", "--sampler", "<name>", List.of("grid", "jittered", "sobol", "adaptive")),
    /** n_s: n_s x n_s samples per pixel (the adaptive sampler's budget). */
    SAMPLES("AASamples", "--samples", "<n>", 1, 64, ""),
    /** The adaptive sampler's target: the standard error of a pixel's mean, in 8-bit steps. */
    TARGET_ERROR("TargetError", "--target-error", "<8-bit steps>", 0, 255, " 8-bit steps"),
    /** Mirror and refraction bounces followed. */
    MAX_DEPTH("MaxDepth", "--max-depth", "<bounces>", 0, 1000, "");

    /** The value's type. */
    public enum Type { CHOICE, INT, NUMBER }

    /** The scene file's global and the command line's option. */
    public final String global, option;
    /** What the value looks like, for "needs a value" messages ({@code <n>}). */
    public final String hint;
    public final Type type;
    /** The inclusive range of INT and NUMBER values. */
    public final double min, max;
    /** The values of a CHOICE. */
    public final List<String> choices;
    /** The unit after the range in messages (" 8-bit steps"), or "". */
    private final String unit;

    RenderOption(String global, String option, String hint, List<String> choices) {
        this(global, option, hint, Type.CHOICE, 0, 0, "", choices);
    }

    RenderOption(String global, String option, String hint, int min, int max, String unit) {
        this(global, option, hint, unit.isEmpty() ? Type.INT : Type.NUMBER, min, max, unit, List.of());
    }

    RenderOption(String global, String option, String hint, Type type, double min, double max, String unit, List<String> choices) {
        this.global = global;
        this.option = option;
        this.hint = hint;
        this.type = type;
        this.min = min;
        this.max = max;
        this.unit = unit;
        this.choices = choices;
    }

    /** The row whose scene global is {@code name}, or null. */
    public static RenderOption ofGlobal(String name) {
        for (RenderOption o : values()) {
            if (o.global.equals(name)) {
                return o;
            }
        }
        return null;
    }

    /** The expected values in words: "1 to 64", "0 to 255 8-bit steps", "one of grid, jittered, sobol, adaptive". */
    public String expected() {
        if (type == Type.CHOICE) {
            return "one of " + String.join(", ", choices);
        }
        return number(min) + " to " + number(max) + unit;
    }

    /** True when {@code v} is in range (a whole number for INT). */
    public boolean accepts(double v) {
        return type != Type.CHOICE && v >= min && v <= max && (type != Type.INT || v == Math.rint(v));
    }

    /** True when {@code name} is one of a CHOICE's values. */
    public boolean accepts(String name) {
        return choices.contains(name);
    }

    /** What is wrong with {@code v} given under {@code label} (an option's or the global's name), or null. */
    public String problem(String label, double v) {
        return accepts(v) ? null : label + " must be " + expectedInParens() + ", got " + (type == Type.INT ? number(v) : Double.toString(v));
    }

    /** What is wrong with the CHOICE value {@code name} given under {@code label}, or null. */
    public String problem(String label, String name) {
        return accepts(name) ? null : label + " must be " + expected() + ", got '" + name + "'";
    }

    private String expectedInParens() {
        return unit.isEmpty() ? expected() : number(min) + " to " + number(max) + " (" + unit.strip() + ")";
    }

    /** {@code v}, checked: throws IllegalArgumentException naming the global when out of range. */
    int checked(int v) {
        String p = problem(global, v);
        if (p != null) {
            throw new IllegalArgumentException(p);
        }
        return v;
    }

    double checked(double v) {
        String p = problem(global, v);
        if (p != null) {
            throw new IllegalArgumentException(p);
        }
        return v;
    }

    String checked(String v) {
        String p = problem(global, v);
        if (p != null) {
            throw new IllegalArgumentException(p);
        }
        return v;
    }

    private static String number(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }
}
