package ray.parse;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;

/** What every input must give, shared by the fuzz and mutation tests: a scene, or a well-formed SceneFormatException. */
final class ParserInvariant {

    private ParserInvariant() {
    }

    /** Set by the static initialiser of the default-package test class EvilNotASurface, which no scene may run. */
    static final String EVIL_RAN = "raytracer.test.EvilNotASurface.initialised";

    /**
     * Parses {@code data} as bytes and as text; anything but success or a one-line located
     * SceneFormatException escapes, and so does an AssertionError if the parse initialised a class that
     * is not a scene class.
     */
    static void check(byte[] data) {
        try {
            Parser.parse(data, "fuzz.txt", new ArrayList<>());
        } catch (SceneFormatException e) {
            checkMessage(e);
        }
        try {
            Parser.parse(new String(data, StandardCharsets.UTF_8), "fuzz.txt", new ArrayList<>());
        } catch (SceneFormatException e) {
            checkMessage(e);
        }
        if (System.getProperty(EVIL_RAN) != null) {
            throw new AssertionError("the scene ran the static initialiser of EvilNotASurface, which is not a scene class");
        }
    }

    static void checkMessage(SceneFormatException e) {
        String m = e.getMessage();
        if (e.line() < 1 || !m.startsWith("fuzz.txt:" + e.line() + ": ") || m.chars().anyMatch(c -> c < 0x20 || c == 0x7f)) {
            throw new AssertionError("malformed message: " + m);
        }
        if (m.length() > 2000) {
            throw new AssertionError("message of " + m.length() + " characters: " + m.substring(0, 200));
        }
    }
}
