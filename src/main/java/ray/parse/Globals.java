package ray.parse;

import java.util.ArrayList;
import java.util.List;
import ray.Scene;
import ray.settings.RenderOption;

/**
 * The scene file's globals, one row each: the keyword, what its value looks like (for "needs a value"
 * messages) and how it is read into the {@link Scene}. The one list the parser knows them from; the
 * render settings' rows (AASamples, MaxDepth, Sampler, TargetError) take their ranges from
 * {@link RenderOption}.
 */
enum Globals {
    BG_COLOR("BGColor", "[r g b]") {
        @Override
        void read(String value, Scene scene) throws Problem {
            scene.backgroundColor = Values.parseVector(value, keyword);
        }
    },
    AMBIENT_LIGHT("AmbientLight", "[r g b]") {
        @Override
        void read(String value, Scene scene) throws Problem {
            scene.ambientLight = Values.parseVector(value, keyword);
        }
    },
    WIDTH("Width", "<pixels>") {
        @Override
        void read(String value, Scene scene) throws Problem {
            scene.width = whole(value, keyword, 1, Limits.MAX_SIDE);
        }
    },
    HEIGHT("Height", "<pixels>") {
        @Override
        void read(String value, Scene scene) throws Problem {
            scene.height = whole(value, keyword, 1, Limits.MAX_SIDE);
        }
    },
    AA_SAMPLES(RenderOption.SAMPLES) {
        @Override
        void read(String value, Scene scene) throws Problem {
            scene.samplesPerPixel = whole(value, RenderOption.SAMPLES);
        }
    },
    MAX_DEPTH(RenderOption.MAX_DEPTH) {
        @Override
        void read(String value, Scene scene) throws Problem {
            scene.maxDepth = whole(value, RenderOption.MAX_DEPTH);
        }
    },
    SAMPLER(RenderOption.SAMPLER) {
        @Override
        void read(String value, Scene scene) throws Problem {
            List<String> names = RenderOption.SAMPLER.choices;
            if (!RenderOption.SAMPLER.accepts(value)) {
                throw new Problem(Values.quote(keyword + " " + value) + " names no sampler (" + Values.caseHint(value, names)
                        + "expected one of " + String.join(", ", names) + ")");
            }
            scene.sampler = value;
        }
    },
    TARGET_ERROR(RenderOption.TARGET_ERROR) {
        @Override
        void read(String value, Scene scene) throws Problem {
            double e = Values.parseDouble(value, keyword);
            if (!RenderOption.TARGET_ERROR.accepts(e)) {
                throw new Problem(Values.quote(keyword + " " + value) + " is out of range (expected " + RenderOption.TARGET_ERROR.expected() + ")");
            }
            scene.targetError = e;
        }
    };

    /** The keywords, in the table's order. */
    static final List<String> NAMES = names();

    final String keyword;
    /** What the value looks like, e.g. {@code [r g b]}. */
    final String hint;

    Globals(String keyword, String hint) {
        this.keyword = keyword;
        this.hint = hint;
    }

    Globals(RenderOption option) {
        this(option.global, option.hint);
    }

    /** Reads {@code value} (not empty) into {@code scene}; a Problem when it is not a valid value. */
    abstract void read(String value, Scene scene) throws Problem;

    /** The row for {@code keyword}, or null. */
    static Globals of(String keyword) {
        for (Globals g : values()) {
            if (g.keyword.equals(keyword)) {
                return g;
            }
        }
        return null;
    }

    private static List<String> names() {
        List<String> n = new ArrayList<>();
        for (Globals g : values()) {
            n.add(g.keyword);
        }
        return List.copyOf(n);
    }

    /** A whole-number global checked against its row of the render-settings table. */
    static int whole(String value, RenderOption option) throws Problem {
        return whole(value, option.global, (int) option.min, (int) option.max);
    }

    static int whole(String value, String key, int min, int max) throws Problem {
        String expected = " (expected " + min + " to " + max + ")";
        if (!Values.isWhole(value)) {
            throw new Problem(Values.quote(value) + " is not a whole number for " + key + expected);
        }
        Long v = Values.wholeValue(value);
        if (v == null || v < min || v > max) {
            throw new Problem(Values.quote(key + " " + value) + " is out of range" + expected);
        }
        return (int) (long) v;
    }
}
